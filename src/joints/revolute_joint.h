// Revolute joint storage: the settings and accumulated impulses of a pin with an optional
// angle limit and motor (the alternative of Joint::data for a revolute joint; joint.h holds
// the anchors and everything else every joint has).
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

struct RevoluteJoint {
    bool enableLimit = false;
    float lowerAngle = 0.0f;  // rad
    float upperAngle = 0.0f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;      // rad/s
    float maxMotorTorque = 0.0f;  // N m

    // Accumulated impulses of the last step solved (warm starting, reactions).
    Vec2 impulse;               // pin, N s
    float motorImpulse = 0.0f;  // N m s
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;

    /// Whether the impulses and the force and torques they stand for (impulse * invDt) are
    /// finite.
    bool hasFiniteReactions(float invDt) const {
        const float angular = motorImpulse + lowerImpulse - upperImpulse;
        return isFinite(invDt * impulse) && std::isfinite(invDt * angular) &&
               std::isfinite(invDt * motorImpulse) && std::isfinite(invDt * lowerImpulse) &&
               std::isfinite(invDt * upperImpulse);
    }
    /// m: a pin's separation is how far apart its anchors (in world coordinates) are.
    float separation(Rot, Vec2 anchorA, Vec2 anchorB) const { return distance(anchorA, anchorB); }
    void clearImpulses() {
        impulse = Vec2{};
        motorImpulse = lowerImpulse = upperImpulse = 0.0f;
    }
};

}  // namespace pivot
