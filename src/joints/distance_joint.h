// Distance joint storage: the settings and accumulated impulses of a rod, rope or spring between
// two anchors (the alternative of Joint::data for a distance joint; joint.h holds the anchors).
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

struct DistanceJoint {
    float length = 1.0f;  // m, the rod's or spring's rest length
    bool enableLimit = false;
    float minLength = 0.0f;
    float maxLength = 0.0f;
    bool enableSpring = false;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;

    // Accumulated impulses of the last step solved (warm starting, reactions), N s, and the
    // direction they acted along.
    float impulse = 0.0f;  // rod or spring
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    Vec2 axis;

    /// A rope: free while its length is within the limit.
    bool isRope() const { return enableLimit && minLength < maxLength; }
    /// A rigid length: without a spring or a rope, or with a limit whose min is its max.
    bool isRod() const { return enableLimit ? minLength == maxLength : !enableSpring; }
    bool hasSpring() const { return enableSpring && !isRod(); }
    /// The rod's length: a limit with min == max holds that length.
    float rodLength() const { return enableLimit ? minLength : length; }
    float axialImpulse() const { return impulse + lowerImpulse - upperImpulse; }

    bool hasFiniteReactions(float invDt) const {
        return std::isfinite(invDt * impulse) && std::isfinite(invDt * lowerImpulse) &&
               std::isfinite(invDt * upperImpulse) && std::isfinite(invDt * axialImpulse()) &&
               isFinite(axis);
    }
    void clearImpulses() {
        impulse = lowerImpulse = upperImpulse = 0.0f;
        axis = Vec2{};  // measured in a diverged substep, it may not be finite
    }
    /// m, how far the joint, its anchors (in world coordinates) where they are, is from what it
    /// allows.
    float separation(Rot, Vec2 anchorA, Vec2 anchorB) const {
        return separationAt(distance(anchorA, anchorB));
    }
    float separationAt(float currentLength) const {
        if (isRod()) return std::fabs(currentLength - rodLength());
        if (!enableLimit) return 0.0f;
        if (currentLength < minLength) return minLength - currentLength;
        if (currentLength > maxLength) return currentLength - maxLength;
        return 0.0f;
    }
};

}  // namespace pivot
