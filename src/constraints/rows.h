// How one velocity solve treats a constraint's position rows: the strategy's choice, made at
// compile time so each strategy's loop holds only its own arithmetic.
//
//   Rigid   lambda = -K^-1 Cdot                        (the rows hold the velocity only;
//                                                       SoftStep's relax, rigid XPBD)
//   Biased  lambda = -K^-1 (Cdot + bias)               (Baumgarte: bias = beta / h C)
//   Soft    lambda = massScale (-K^-1 (Cdot + bias)) - impulseScale lambda_acc
//                                                      (soft step: bias = biasRate C)
//   None    the rows are not solved at all             (compliant XPBD: the poses instead)
// with the soft factors of soft_factors.h: the row is a spring of the joint's hertz and damping
// ratio on its own effective mass, solved implicitly; at the default damping ratio (2, well
// above critical) it closes an error without the overshoot a Baumgarte bias of the same
// strength has. Motors and the joints' own springs are the same in every mode.
//
// A unilateral bound (a limit, a rope's length) has a velocity target instead of a bias: C / h
// while it is not reached (speculative: the bodies may close the gap this step and no more)
// and, once reached, the bias a strategy set. A reached bound is softened under Soft, and has no
// target at all under Rigid (it then only stops the approach).
#pragma once

#include <algorithm>
#include <cstdint>

#include "constraints/soft_factors.h"
#include "pivot/math.h"

namespace pivot {

/// See the header comment. Under None the motors and the joints' own springs are still solved.
enum class Rows : std::uint8_t { Rigid, Biased, Soft, None };

/// The impulse a row applies in this mode, from its rigid solve and its accumulated impulse.
template <Rows rows, typename T>
inline T soften(T rigid, T accumulated, const SoftFactors& s) {
    if constexpr (rows == Rows::Soft) {
        return s.massScale * rigid - s.impulseScale * accumulated;
    } else {
        return rigid;
    }
}

/// A bound's velocity target (see the header comment).
struct BoundTerm {
    float value = 0.0f;   // m/s or rad/s, added to the bound's Cdot
    bool biased = false;  // value is a strategy's bias (the bound was reached), not C / h

    /// The speculative target of a bound `gap` (C >= 0 away from it) over a step of 1 / invH.
    static BoundTerm speculative(float gap, float invH) {
        return {std::max(gap, 0.0f) * invH, false};
    }
    template <Rows rows>
    float target() const {
        return rows == Rows::Rigid && biased ? 0.0f : value;
    }
    template <Rows rows>
    float soften(float rigid, float accumulated, const SoftFactors& s) const {
        return biased ? pivot::soften<rows>(rigid, accumulated, s) : rigid;
    }
};

}  // namespace pivot
