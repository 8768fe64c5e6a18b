// Wheel joint storage: the axis, suspension spring, limit and motor of a wheel, and its
// accumulated impulses (the alternative of Joint::data for a wheel joint; joint.h holds the
// anchors).
#pragma once

#include <algorithm>
#include <cmath>

#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

struct WheelJoint {
    Vec2 localAxisA{1.0f, 0.0f};  // unit, in body A's frame
    JointSpring spring;
    bool enableLimit = false;
    float lowerTranslation = 0.0f;  // m
    float upperTranslation = 0.0f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;      // rad/s
    float maxMotorTorque = 0.0f;  // N m

    // Accumulated impulses of the last step solved (warm starting, reactions), and the world
    // axis they acted along.
    float impulse = 0.0f;  // across the axis, N s
    float springImpulse = 0.0f;
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    float motorImpulse = 0.0f;  // N m s
    Vec2 axis;

    Vec2 localPerpA() const { return {-localAxisA.y, localAxisA.x}; }
    /// N s along the axis, to B.
    float axialImpulse() const { return springImpulse + lowerImpulse - upperImpulse; }

    bool hasFiniteReactions(float invDt) const {
        return std::isfinite(invDt * impulse) && std::isfinite(invDt * springImpulse) &&
               std::isfinite(invDt * lowerImpulse) && std::isfinite(invDt * upperImpulse) &&
               std::isfinite(invDt * motorImpulse) && std::isfinite(invDt * axialImpulse()) &&
               isFinite(axis);
    }
    void clearImpulses() {
        impulse = springImpulse = lowerImpulse = upperImpulse = motorImpulse = 0.0f;
        axis = Vec2{};  // measured in a diverged substep, it may not be finite
    }
    /// m: how far anchor B is off the axis line, combined with how far the translation is
    /// beyond the limit (when enabled).
    float separation(Rot qA, Vec2 anchorA, Vec2 anchorB) const {
        const Vec2 d = anchorB - anchorA;
        const float across = dot(rotate(qA, localPerpA()), d);
        float beyond = 0.0f;
        if (enableLimit) {
            const float x = dot(rotate(qA, localAxisA), d);
            beyond = std::max({lowerTranslation - x, x - upperTranslation, 0.0f});
        }
        return std::hypot(across, beyond);
    }
};

}  // namespace pivot
