// Pulley joint storage: the ground anchors, lengths and ratio of a rope over two wheels, and its
// accumulated impulse (the alternative of Joint::data for a pulley joint).
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

struct PulleyJoint {
    Vec2 groundAnchorA;
    Vec2 groundAnchorB;
    float lengthA = 0.0f;  // m, the lengths the rope was cut to
    float lengthB = 0.0f;
    float ratio = 1.0f;

    float impulse = 0.0f;  // accumulated, N s
    Vec2 axisB;            // the direction of B's side when last solved (reactions)

    float constant() const { return lengthA + ratio * lengthB; }
    bool hasFiniteReactions(float invDt) const {
        return std::isfinite(invDt * impulse) && std::isfinite(invDt * ratio * impulse) &&
               isFinite(axisB);
    }
    void clearImpulses() {
        impulse = 0.0f;
        axisB = Vec2{};  // measured in a diverged substep, it may not be finite
    }
    /// m, |C|: how far the rope's two lengths are from what it was cut to.
    float separation(Rot, Vec2 anchorA, Vec2 anchorB) const {
        return std::fabs(constant() - distance(anchorA, groundAnchorA) -
                         ratio * distance(anchorB, groundAnchorB));
    }
};

}  // namespace pivot
