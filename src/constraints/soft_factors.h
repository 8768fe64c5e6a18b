// The factors of a soft row: a spring of `hertz` and damping ratio `z` on the row's own
// effective mass (K^-1), solved as
//   lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambda_acc,
//   w = 2 pi hertz,  c = 1 / (h w (2 z + h w)),
//   massScale = 1 / (1 + c),  impulseScale = c / (1 + c),  biasRate = w / (2 z + h w),
// which is the distance joint's spring (length_part.h), written so that K may be a matrix (the
// weld's point) as well as a scalar (the weld's angle, the wheel's suspension). A soft row has no
// position correction: the spring is its own.
#pragma once

#include <cmath>

#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

/// A soft row's per-step factors.
struct SoftFactors {
    float massScale = 1.0f;
    float impulseScale = 0.0f;
    float biasRate = 0.0f;  // 1/s: the bias is biasRate C

    static SoftFactors of(const JointSpring& spring, float h) {
        return of(spring.hertz, spring.dampingRatio, h);
    }
    static SoftFactors of(float hertz, float dampingRatio, float h) {
        const float omega = 2.0f * kPi * hertz;
        const float a1 = 2.0f * dampingRatio + h * omega;
        const float c = 1.0f / (h * omega * a1);
        SoftFactors f{1.0f / (1.0f + c), c / (1.0f + c), omega / a1};
        if (!std::isfinite(f.massScale) || !std::isfinite(f.impulseScale) ||
            !std::isfinite(f.biasRate)) {
            f = SoftFactors{0.0f, 0.0f, 0.0f};  // no spring force at all rather than a NaN
        }
        return f;
    }
};

}  // namespace pivot
