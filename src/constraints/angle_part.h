// The angle part of the revolute joint: a motor and a lower/upper angle limit, both scalar
// constraints on the relative rotation about the pin.
//
//   angle = aB - aA - referenceAngle
//   Cdot  = wB - wA,   J = [0 0 -1 0 0 1],   K = iA + iB   (axialMass = 1 / K)
//
// Motor:  Cdot = motorSpeed, impulse clamped to +-h * maxMotorTorque. Velocity only.
// Limits: lower  C = angle - lower >= 0, impulse >= 0;
//         upper  C = upper - angle >= 0, impulse >= 0 (signs flipped so both push when > 0).
// In the velocity phase a limit not yet reached lets the bodies approach it by C / h this step
// (so they stop at it, not before); how a reached or overshot limit is corrected is the
// joint's PositionSolver's business, as for the pin. The position error of a limit allows
// kAngularSlop and never asks for more than kMaxAngularCorrection at once:
//   lower: clamp(angle - lower + slop, -maxCorrection, 0)
//   upper: clamp(angle - upper - slop, 0, maxCorrection)
//   limits closer than 2 slop act as one equality: clamp(angle - lower, +-maxCorrection).
// Because K is a scalar that does not depend on the pose, ModifiedNGS and FullNGS treat the
// limit identically (the seed note's guess that Modified NGS suits scalar constraints).
#pragma once

#include <algorithm>
#include <cmath>

#include "constraints/constraint_bodies.h"
#include "constraints/rows.h"
#include "constraints/solver_body.h"
#include "constraints/xpbd_rows.h"
#include "pivot/constants.h"

namespace pivot {

struct AnglePart {
    bool limitEnabled = false;  // read by every velocity solve: first
    bool motorEnabled = false;
    float referenceAngle = 0.0f;
    float axialMass = 0.0f;  // 1 / (iA + iB), 0 with fixed rotation
    float angle = 0.0f;      // joint angle at the start of the step
    float lower = 0.0f;
    float upper = 0.0f;
    float motorSpeed = 0.0f;       // rad/s
    float maxMotorImpulse = 0.0f;  // h * max motor torque, N m s
    float motorImpulse = 0.0f;     // accumulated, N m s
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    // Velocity targets added to the limits' Cdot (rows.h): the speculative C / h while a limit is
    // not reached, and a strategy's bias for an overshot one.
    BoundTerm lowerTerm;
    BoundTerm upperTerm;

    /// The axial impulse the warm start applies to B (and minus it to A).
    float axialImpulse() const { return motorImpulse + lowerImpulse - upperImpulse; }
    bool limitsAreEqual() const { return std::fabs(upper - lower) < 2.0f * kAngularSlop; }
};

inline float jointAngle(const AnglePart& a, const SolverPose* positions,
                        const ConstraintBodies& b) {
    return positions[b.indexB].a - positions[b.indexA].a - a.referenceAngle;
}

/// The speculative limit terms for a step of 1 / invH from the stored angle.
inline void setLimitTerms(AnglePart& a, float invH) {
    a.lowerTerm = BoundTerm::speculative(a.angle - a.lower, invH);
    a.upperTerm = BoundTerm::speculative(a.upper - a.angle, invH);
}

/// Start of the step: the angle, the axial mass and the speculative limit terms.
inline void prepareAngle(const ConstraintBodies& b, AnglePart& a, const SolverPose* positions,
                         float invDt) {
    a.axialMass = b.fixedRotation() ? 0.0f : 1.0f / (b.iA + b.iB);
    a.angle = jointAngle(a, positions, b);
    if (!a.limitEnabled || b.fixedRotation()) {
        a.lowerImpulse = 0.0f;
        a.upperImpulse = 0.0f;
    }
    if (!a.motorEnabled || b.fixedRotation()) a.motorImpulse = 0.0f;
    setLimitTerms(a, invDt);
}

/// The limits' position error as the NGS solves see it (see the header comment): negative
/// below the lower limit, positive above the upper one, 0 within the limits and slop.
inline float limitPositionError(const AnglePart& a, float angle) {
    if (a.limitsAreEqual()) {
        return std::clamp(angle - a.lower, -kMaxAngularCorrection, kMaxAngularCorrection);
    }
    if (angle <= a.lower) {
        return std::clamp(angle - a.lower + kAngularSlop, -kMaxAngularCorrection, 0.0f);
    }
    if (angle >= a.upper) {
        return std::clamp(angle - a.upper - kAngularSlop, 0.0f, kMaxAngularCorrection);
    }
    return 0.0f;
}

/// Motor (unless withMotor is false: pseudo velocities have no motor), then lower and upper
/// limit, on the given velocities, the limits as `rows` say (rows.h; `soft` for Rows::Soft).
template <bool withMotor = true, Rows rows = Rows::Biased>
inline void solveAngleVelocity(const ConstraintBodies& b, AnglePart& a, SolverVelocity* velocities,
                               const SoftFactors& soft = SoftFactors{}) {
    if (b.fixedRotation()) return;
    float& wA = velocities[b.indexA].w;
    float& wB = velocities[b.indexB].w;
    if (withMotor && a.motorEnabled) {
        float cdot = wB - wA - a.motorSpeed;
        float impulse = -a.axialMass * cdot;
        float old = a.motorImpulse;
        float maxImpulse = a.maxMotorImpulse;
        a.motorImpulse = std::clamp(old + impulse, -maxImpulse, maxImpulse);
        impulse = a.motorImpulse - old;
        wA -= b.iA * impulse;
        wB += b.iB * impulse;
    }
    if (a.limitEnabled && rows != Rows::None) {
        {
            float cdot = wB - wA;
            float impulse = a.lowerTerm.soften<rows>(
                -a.axialMass * (cdot + a.lowerTerm.target<rows>()), a.lowerImpulse, soft);
            float old = a.lowerImpulse;
            a.lowerImpulse = std::max(old + impulse, 0.0f);
            impulse = a.lowerImpulse - old;
            wA -= b.iA * impulse;
            wB += b.iB * impulse;
        }
        {
            float cdot = wA - wB;
            float impulse = a.upperTerm.soften<rows>(
                -a.axialMass * (cdot + a.upperTerm.target<rows>()), a.upperImpulse, soft);
            float old = a.upperImpulse;
            a.upperImpulse = std::max(old + impulse, 0.0f);
            impulse = a.upperImpulse - old;
            wA += b.iA * impulse;
            wB -= b.iB * impulse;
        }
    }
}

/// A velocity bias of k times the limit's position error (slop allowed, clamped) for an
/// overshot limit; a limit not yet reached keeps its speculative term.
inline void setLimitBias(AnglePart& a, float k) {
    if (!a.limitEnabled) return;
    float error = limitPositionError(a, a.angle);
    if (a.angle - a.lower <= 0.0f) a.lowerTerm = {k * std::min(error, 0.0f), true};
    if (a.upper - a.angle <= 0.0f) a.upperTerm = {-k * std::max(error, 0.0f), true};
}

/// XPBD on the limits (xpbd_rows.h): the lower bound, then the upper one, each re-measured;
/// limits closer than 2 slop as one equality. lambda[0], lambda[1] are their accumulators.
inline void xpbdLimits(const ConstraintBodies& b, const AnglePart& a, SolverPose* poses,
                       float alphaTilde, float* lambda) {
    if (!a.limitEnabled || b.fixedRotation()) return;
    const float w = b.iA + b.iB;
    if (a.limitsAreEqual()) {
        xpbdAngle(b, poses, jointAngle(a, poses, b) - a.lower, alphaTilde, lambda[0]);
        return;
    }
    const float lower = xpbdLowerBound(jointAngle(a, poses, b) - a.lower, w, alphaTilde, lambda[0]);
    poses[b.indexA].a -= b.iA * lower;
    poses[b.indexB].a += b.iB * lower;
    // C = upper - angle >= 0: the row turns the bodies the other way.
    const float upper = xpbdLowerBound(a.upper - jointAngle(a, poses, b), w, alphaTilde, lambda[1]);
    poses[b.indexA].a += b.iA * upper;
    poses[b.indexB].a -= b.iB * upper;
}

/// One NGS solve of the limit on positions: re-measure the angle, rotate the bodies by
/// -beta C / K. Returns |C| before the correction (0 with the limit off).
inline float solveLimitPosition(const ConstraintBodies& b, const AnglePart& a,
                                SolverPose* positions, float beta) {
    if (!a.limitEnabled || b.fixedRotation()) return 0.0f;
    float C = limitPositionError(a, jointAngle(a, positions, b));
    float impulse = -beta * a.axialMass * C;
    positions[b.indexA].a -= b.iA * impulse;
    positions[b.indexB].a += b.iB * impulse;
    return std::fabs(C);
}

}  // namespace pivot
