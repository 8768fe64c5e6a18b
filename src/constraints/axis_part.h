// The axis part: a scalar constraint on how far anchor B is from anchor A along a direction
// fixed in body A (the prismatic joint's axis and the line across it; the wheel joint's).
//
//   d    = (cB + rB) - (cA + rA),  u = R(aA) localAxis         the gap and the axis, world
//   x    = u . d                                              the coordinate along u, m
//   Cdot = u . (vB - vA) + a2 wB - a1 wA,   a1 = (d + rA) x u,  a2 = rB x u
//   J    = [ -u  -a1  u  a2 ]
//   K    = mA + mB + iA a1^2 + iB a2^2                         axialMass = 1 / K
// The axis turns with body A, so A's lever arm runs to anchor B (d + rA), not to anchor A. An
// impulse lambda acts along u: vB += mB lambda u, wB += iB lambda a2, the opposite on A.
//
// The frame (rA, rB, d) is measured once per joint and shared by its axes.
#pragma once

#include <algorithm>

#include "constraints/constraint_bodies.h"
#include "constraints/rows.h"
#include "constraints/solver_body.h"
#include "constraints/xpbd_rows.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

/// Radius vectors and anchor gap at some poses.
struct AxisFrame {
    Vec2 rA;
    Vec2 rB;
    Vec2 d;
};

/// One direction of an axis part at some poses.
struct AxisRow {
    Vec2 u;
    float a1 = 0.0f;
    float a2 = 0.0f;
};

/// The frame at the start of a step: the gap formed as (cB - cA) + rB - rA, the order Box2D
/// 2.4.1's prismatic and wheel joints use when they set up their velocity constraints.
inline AxisFrame axisFrameForVelocities(const SolverPose& A, const SolverPose& B, Vec2 localRA,
                                        Vec2 localRB) {
    AxisFrame f;
    f.rA = rotate(Rot(A.a), localRA);
    f.rB = rotate(Rot(B.a), localRB);
    f.d = (B.c - A.c) + f.rB - f.rA;
    return f;
}

/// The frame during position solves, the gap formed as cB + rB - cA - rA (Box2D's order there):
/// the same vector, rounded differently.
inline AxisFrame axisFrameForPositions(const SolverPose& A, const SolverPose& B, Vec2 localRA,
                                       Vec2 localRB) {
    AxisFrame f;
    f.rA = rotate(Rot(A.a), localRA);
    f.rB = rotate(Rot(B.a), localRB);
    f.d = B.c + f.rB - A.c - f.rA;
    return f;
}

inline AxisRow axisRow(const AxisFrame& f, Vec2 u) {
    return {u, cross(f.d + f.rA, u), cross(f.rB, u)};
}

/// K of one row, m + i a^2 summed over the bodies.
inline float axisK(const ConstraintBodies& b, const AxisRow& r) {
    return b.mA + b.mB + b.iA * r.a1 * r.a1 + b.iB * r.a2 * r.a2;
}

inline float axisMass(const ConstraintBodies& b, const AxisRow& r) {
    const float k = axisK(b, r);
    return k > 0.0f ? 1.0f / k : 0.0f;
}

/// Cdot along the row at the current velocities.
inline float axisSpeed(const AxisRow& r, const SolverVelocity& A, const SolverVelocity& B) {
    return dot(r.u, B.v - A.v) + r.a2 * B.w - r.a1 * A.w;
}

/// Applies lambda along the row (B gets +lambda u, A the opposite).
inline void applyAxisImpulse(const ConstraintBodies& b, const AxisRow& r,
                             SolverVelocity* velocities, float lambda) {
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    const Vec2 P = lambda * r.u;
    A.v -= b.mA * P;
    A.w -= b.iA * (lambda * r.a1);
    B.v += b.mB * P;
    B.w += b.iB * (lambda * r.a2);
}

/// A row whose impulse pushes B towards -u (an upper limit): Cdot and the impulse are both
/// formed from A's side, Box2D's signs, so that the limit agrees with its joints bit for bit.
inline float axisSpeedFlipped(const AxisRow& r, const SolverVelocity& A, const SolverVelocity& B) {
    return dot(r.u, A.v - B.v) + r.a1 * A.w - r.a2 * B.w;
}
inline void applyAxisImpulseFlipped(const ConstraintBodies& b, const AxisRow& r,
                                    SolverVelocity* velocities, float lambda) {
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    const Vec2 P = lambda * r.u;
    A.v += b.mA * P;
    A.w += b.iA * (lambda * r.a1);
    B.v -= b.mB * P;
    B.w -= b.iB * (lambda * r.a2);
}

/// Moves the poses by lambda along the row (B by +lambda u, A the opposite), at once.
inline void moveAlongAxis(const ConstraintBodies& b, const AxisRow& r, SolverPose* poses,
                          float lambda) {
    SolverPose& A = poses[b.indexA];
    SolverPose& B = poses[b.indexB];
    const Vec2 P = lambda * r.u;
    A.c -= b.mA * P;
    A.a -= b.iA * (lambda * r.a1);
    B.c += b.mB * P;
    B.a += b.iB * (lambda * r.a2);
}

/// Lower and upper bounds on the coordinate along an axis row: lower  C = x - lower >= 0 and
/// upper  C = upper - x >= 0, each impulse >= 0 (the upper's signs flipped so that both push
/// when positive). As for the angle limits, a bound not yet reached lets the anchors approach it
/// by C / h this step; an overshot one is corrected as the joint's strategy says, in full (no
/// slop, no cap, as Box2D 2.4.1's prismatic joint).
struct AxisLimits {
    bool enabled = false;
    float lower = 0.0f;
    float upper = 0.0f;
    float lowerImpulse = 0.0f;  // accumulated, N s
    float upperImpulse = 0.0f;
    BoundTerm lowerTerm;  // velocity targets added to Cdot (rows.h)
    BoundTerm upperTerm;

    /// Loads a joint's limit settings and stored impulses (zero while disabled) for a step
    /// whose rows start at coordinate x, the step 1 / invH long.
    void load(bool on, float lo, float hi, float storedLower, float storedUpper, float x,
              float invH) {
        enabled = on;
        lower = lo;
        upper = hi;
        lowerImpulse = on ? storedLower : 0.0f;
        upperImpulse = on ? storedUpper : 0.0f;
        setTerms(x, invH);
    }

    /// The impulse the limits apply along the axis, to B.
    float impulse() const { return lowerImpulse - upperImpulse; }
    bool equal() const { return upper - lower < 2.0f * kLinearSlop; }

    /// The speculative terms for a step of length 1 / invH from coordinate x.
    void setTerms(float x, float invH) {
        lowerTerm = BoundTerm::speculative(x - lower, invH);
        upperTerm = BoundTerm::speculative(upper - x, invH);
    }

    /// Whether the NGS solve treats the limit as active at coordinate x, and its error then:
    /// negative below lower, positive above upper (Box2D counts touching as active).
    bool active(float x) const { return enabled && (equal() || x <= lower || x >= upper); }
    float positionError(float x) const {
        if (equal()) return x - lower;
        if (x <= lower) return std::min(x - lower, 0.0f);
        if (x >= upper) return std::max(x - upper, 0.0f);
        return 0.0f;
    }
    /// m, how far x is outside [lower, upper].
    float violation(float x) const { return std::max({lower - x, x - upper, 0.0f}); }

    /// Baumgarte's bias for an overshot bound: k times its error; a bound not yet reached keeps
    /// its speculative term.
    void setBias(float x, float k) {
        const float error = positionError(x);
        if (x - lower <= 0.0f) lowerTerm = {k * std::min(error, 0.0f), true};
        if (upper - x <= 0.0f) upperTerm = {-k * std::max(error, 0.0f), true};
    }

    /// One velocity solve of both bounds along the row, as `rows` says (rows.h).
    template <Rows rows = Rows::Biased>
    void solve(const ConstraintBodies& b, const AxisRow& r, float mass, SolverVelocity* velocities,
               const SoftFactors& soft = SoftFactors{}) {
        if constexpr (rows == Rows::None) return;
        {
            const float cdot = axisSpeed(r, velocities[b.indexA], velocities[b.indexB]);
            const float lambda = lowerTerm.soften<rows>(-mass * (cdot + lowerTerm.target<rows>()),
                                                        lowerImpulse, soft);
            const float old = lowerImpulse;
            lowerImpulse = std::max(old + lambda, 0.0f);
            applyAxisImpulse(b, r, velocities, lowerImpulse - old);
        }
        {
            const float cdot = axisSpeedFlipped(r, velocities[b.indexA], velocities[b.indexB]);
            const float lambda = upperTerm.soften<rows>(-mass * (cdot + upperTerm.target<rows>()),
                                                        upperImpulse, soft);
            const float old = upperImpulse;
            upperImpulse = std::max(old + lambda, 0.0f);
            applyAxisImpulseFlipped(b, r, velocities, upperImpulse - old);
        }
    }
};

/// XPBD on both bounds along the axis `direction` (in body A's frame), re-measured before each;
/// lambda[0] and lambda[1] are their accumulators.
inline void xpbdAxisLimits(const ConstraintBodies& b, const AxisLimits& limits, Vec2 localRA,
                           Vec2 localRB, Vec2 direction, SolverPose* poses, float alphaTilde,
                           float* lambda) {
    const auto row = [&](float& x) {
        const AxisFrame f =
            axisFrameForPositions(poses[b.indexA], poses[b.indexB], localRA, localRB);
        const AxisRow u = axisRow(f, rotate(Rot(poses[b.indexA].a), direction));
        x = dot(u.u, f.d);
        return u;
    };
    float x = 0.0f;
    AxisRow u = row(x);
    if (limits.equal()) {
        moveAlongAxis(b, u, poses, xpbdDelta(x - limits.lower, axisK(b, u), alphaTilde, lambda[0]));
        return;
    }
    moveAlongAxis(b, u, poses,
                  xpbdLowerBound(x - limits.lower, axisK(b, u), alphaTilde, lambda[0]));
    u = row(x);
    // The upper bound's row points the other way: C = upper - x >= 0.
    moveAlongAxis(b, u, poses,
                  -xpbdLowerBound(limits.upper - x, axisK(b, u), alphaTilde, lambda[1]));
}

}  // namespace pivot
