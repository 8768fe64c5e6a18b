// Weld joint storage: the optional springs of a weld and its accumulated impulse (the
// alternative of Joint::data for a weld joint; joint.h holds the anchors and reference angle).
#pragma once

#include <cmath>

#include "core/mat33.h"
#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

struct WeldJoint {
    JointSpring linearSpring;  // enabled: the point is soft
    JointSpring angularSpring;

    Vec3 impulse;  // accumulated: the point's (N s) and the angle's (N m s)

    bool hasFiniteReactions(float invDt) const {
        return std::isfinite(invDt * impulse.x) && std::isfinite(invDt * impulse.y) &&
               std::isfinite(invDt * impulse.z);
    }
    void clearImpulses() { impulse = Vec3{}; }
    /// m: the anchors' gap while the point is rigid; a soft point is a spring, which allows any.
    float separation(Rot, Vec2 anchorA, Vec2 anchorB) const {
        return linearSpring.enabled ? 0.0f : distance(anchorA, anchorB);
    }
};

}  // namespace pivot
