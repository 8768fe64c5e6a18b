// The length part: a scalar constraint on the distance between two anchors (the distance joint's
// rod, rope limits and spring).
//
//   d    = (cB + rB) - (cA + rA),  L = |d|,  u = d / L           direction, A to B
//   Cdot = u . (vB + wB x rB - vA - wA x rA)
//   J    = [ -u  -(rA x u)  u  rB x u ]
//   K    = mA + mB + iA (rA x u)^2 + iB (rB x u)^2                 axialMass = 1 / K
// An impulse lambda acts along u: P = lambda u on B, -P on A.
//
// Rows, each a scalar solve on Cdot:
//   rod    C = L - length, impulse unbounded;
//   lower  C = L - min >= 0, impulse >= 0 (pushes apart); upper C = max - L >= 0, impulse >= 0
//          (pulls together). As for the angle limits, a limit not yet reached lets the anchors
//          approach it by C / h this step; an overshot one is corrected in full (no slop, no
//          cap: lengthLimitError says why);
//   spring soft towards `length`, as the mouse joint's spring: with w = 2 pi hertz, z the
//          damping ratio and h the step, compliance gamma = (1/axialMass) / (h w (2 z + h w)) and
//          bias = w / (2 z + h w) * C; solved as (K + gamma) lambda = -(Cdot + bias + gamma
//          lambda_acc). It has no position phase: the spring is the correction.
// Below kLinearSlop the direction is undefined and the part does nothing (u = 0, K unused).
#pragma once

#include <algorithm>
#include <cmath>

#include "constraints/constraint_bodies.h"
#include "constraints/solver_body.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

struct LengthPart {
    Vec2 rA;  // world radius vectors when last measured
    Vec2 rB;
    Vec2 u;                  // unit direction A to B when last measured (0 below kLinearSlop)
    float length = 0.0f;     // L when last measured
    float axialMass = 0.0f;  // 1 / K when last measured (0 when K is)
    Vec2 localRA;            // anchor relative to the centre of mass, in body A's frame
    Vec2 localRB;
};

struct LengthMeasure {
    Vec2 rA;
    Vec2 rB;
    Vec2 u;
    float length = 0.0f;
};

/// Radius vectors, direction and length at the given poses.
inline LengthMeasure measureLength(const ConstraintBodies& b, const LengthPart& p,
                                   const SolverPose* poses) {
    const SolverPose& A = poses[b.indexA];
    const SolverPose& B = poses[b.indexB];
    LengthMeasure m;
    m.rA = rotate(Rot(A.a), p.localRA);
    m.rB = rotate(Rot(B.a), p.localRB);
    const Vec2 d = B.c + m.rB - A.c - m.rA;
    m.length = length(d);
    m.u = m.length > kLinearSlop ? (1.0f / m.length) * d : Vec2{};
    return m;
}

inline float lengthAxialMass(const ConstraintBodies& b, Vec2 rA, Vec2 rB, Vec2 u) {
    const float crA = cross(rA, u);
    const float crB = cross(rB, u);
    const float k = b.mA + b.iA * crA * crA + b.mB + b.iB * crB * crB;
    return k != 0.0f ? 1.0f / k : 0.0f;
}

/// Measures the part at the given poses and stores what the solves reuse.
inline void prepareLength(const ConstraintBodies& b, LengthPart& p, const SolverPose* poses) {
    const LengthMeasure m = measureLength(b, p, poses);
    p.rA = m.rA;
    p.rB = m.rB;
    p.u = m.u;
    p.length = m.length;
    p.axialMass = lengthAxialMass(b, m.rA, m.rB, m.u);
}

/// Cdot along u at the current velocities.
/// (Each anchor's velocity is formed first, as Box2D 2.4.1's distance joint does, so that its
/// rod agrees with that joint bit for bit where the inputs do.)
inline float lengthSpeed(const LengthPart& p, const SolverVelocity& A, const SolverVelocity& B) {
    const Vec2 vA = A.v + cross(A.w, p.rA);
    const Vec2 vB = B.v + cross(B.w, p.rB);
    return dot(p.u, vB - vA);
}

/// Applies lambda along u (B gets +lambda u, A the opposite).
inline void applyLengthImpulse(const ConstraintBodies& b, const LengthPart& p,
                               SolverVelocity* velocities, float lambda) {
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    const Vec2 P = lambda * p.u;
    A.v -= b.mA * P;
    A.w -= b.iA * cross(p.rA, P);
    B.v += b.mB * P;
    B.w += b.iB * cross(p.rB, P);
}

/// The position error of a limited length: negative below min, positive above max, 0 between.
/// Unlike the angle limits it neither allows slop nor caps the correction: a rope's error grows
/// with the lever arms and spins of what it ties, and a capped correction (kMaxLinearCorrection,
/// times a bias factor of 0.2 for Baumgarte and pseudo velocities) fell behind that growth on
/// the rope scene, which then stretched without end. Box2D 2.4.1 corrects its distance limits
/// the same way.
inline float lengthLimitError(float length, float min, float max) {
    if (length < min) return length - min;
    if (length > max) return length - max;
    return 0.0f;
}

/// Moves the poses by the impulse P at the anchors measured as `m` (B by +P, A by -P).
inline void moveAlongLength(const ConstraintBodies& b, const LengthMeasure& m, SolverPose* poses,
                            Vec2 P) {
    SolverPose& A = poses[b.indexA];
    SolverPose& B = poses[b.indexB];
    A.c -= b.mA * P;
    A.a -= b.iA * cross(m.rA, P);
    B.c += b.mB * P;
    B.a += b.iB * cross(m.rB, P);
}

/// One nonlinear Gauss-Seidel solve on positions for the error `error(L)` of the part: re-measure
/// at the current poses, move both bodies by -beta C / K along u. With rebuildMass K is that of
/// the current poses (FullNGS), otherwise p.axialMass as frozen (ModifiedNGS). Returns |C|
/// before the correction.
template <bool rebuildMass, typename Error>
inline float solveLengthPosition(const ConstraintBodies& b, const LengthPart& p, SolverPose* poses,
                                 float beta, Error error) {
    const LengthMeasure m = measureLength(b, p, poses);
    const float C = error(m.length);
    const float mass = rebuildMass ? lengthAxialMass(b, m.rA, m.rB, m.u) : p.axialMass;
    moveAlongLength(b, m, poses, (-beta * mass * C) * m.u);
    return std::fabs(C);
}

}  // namespace pivot
