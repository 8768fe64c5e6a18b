// Storage of the velocity-only joints: the friction joint (top-down friction: the relative
// motion of two anchors and the relative rotation resisted up to a maximum force and torque) and
// the motor joint (drives body B's pose relative to body A towards an offset, within a maximum
// force and torque). Neither has a position error for a strategy to correct: as in Box2D, they
// act in the velocity phase only, the same under every PositionSolver.
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

struct FrictionJoint {
    float maxForce = 0.0f;   // N
    float maxTorque = 0.0f;  // N m

    Vec2 linearImpulse;  // accumulated, N s
    float angularImpulse = 0.0f;

    bool hasFiniteReactions(float invDt) const {
        return isFinite(invDt * linearImpulse) && std::isfinite(invDt * angularImpulse);
    }
    void clearImpulses() {
        linearImpulse = Vec2{};
        angularImpulse = 0.0f;
    }
    /// Friction holds nothing together: it never separates.
    float separation(Rot, Vec2, Vec2) const { return 0.0f; }
};

struct MotorJoint {
    Vec2 linearOffset;           // m, body B's origin relative to body A's, in A's frame
    float angularOffset = 0.0f;  // rad, angleB - angleA
    float maxForce = 0.0f;
    float maxTorque = 0.0f;
    float correctionFactor = 0.0f;  // in [0, 1]

    Vec2 linearImpulse;
    float angularImpulse = 0.0f;

    bool hasFiniteReactions(float invDt) const {
        return isFinite(invDt * linearImpulse) && std::isfinite(invDt * angularImpulse);
    }
    void clearImpulses() {
        linearImpulse = Vec2{};
        angularImpulse = 0.0f;
    }
    /// A motor drives towards its offset within limits; falling short is not coming apart.
    float separation(Rot, Vec2, Vec2) const { return 0.0f; }
};

}  // namespace pivot
