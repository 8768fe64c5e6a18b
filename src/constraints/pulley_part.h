// The pulley part: one scalar constraint on two lengths, each from a fixed point in the world
// (the ground anchor g) to a body's anchor.
//
//   LA = |cA + rA - gA|, uA = (cA + rA - gA) / LA, and the same for B
//   C    = constant - LA - ratio LB                    constant = lengthA + ratio lengthB
//   Cdot = -uA . (vA + wA x rA) - ratio uB . (vB + wB x rB)
//   J    = [ -uA  -(rA x uA)  -ratio uB  -ratio (rB x uB) ]
//   K    = mA + iA (rA x uA)^2 + ratio^2 (mB + iB (rB x uB)^2)      mass = 1 / K
// An impulse lambda acts as -lambda uA on A and -ratio lambda uB on B (the rope pulls each load
// towards its wheel when lambda > 0). A side shorter than kMinPulleyLength has no direction: its
// u is 0 and it is not held (as in Box2D 2.4.1, whose operations, in their order, these are).
#pragma once

#include <cmath>

#include "constraints/constraint_bodies.h"
#include "constraints/solver_body.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

struct PulleyPart {
    Vec2 rA;  // world radius vectors when last measured
    Vec2 rB;
    Vec2 uA;  // unit directions from the ground anchors, when last measured (0 if too short)
    Vec2 uB;
    float mass = 0.0f;  // 1 / K when last measured (0 when K is)
    Vec2 localRA;       // anchors relative to the centres of mass, in the bodies' frames
    Vec2 localRB;
    Vec2 groundA;
    Vec2 groundB;
    float ratio = 1.0f;
    float constant = 0.0f;
};

struct PulleyMeasure {
    Vec2 rA, rB, uA, uB;
    float lengthA = 0.0f;
    float lengthB = 0.0f;
};

inline Vec2 pulleyDirection(Vec2 d, float length) {
    return length > kMinPulleyLength ? (1.0f / length) * d : Vec2{};
}

inline PulleyMeasure measurePulley(const ConstraintBodies& b, const PulleyPart& p,
                                   const SolverPose* poses) {
    const SolverPose& A = poses[b.indexA];
    const SolverPose& B = poses[b.indexB];
    PulleyMeasure m;
    m.rA = rotate(Rot(A.a), p.localRA);
    m.rB = rotate(Rot(B.a), p.localRB);
    const Vec2 dA = A.c + m.rA - p.groundA;
    const Vec2 dB = B.c + m.rB - p.groundB;
    m.lengthA = length(dA);
    m.lengthB = length(dB);
    m.uA = pulleyDirection(dA, m.lengthA);
    m.uB = pulleyDirection(dB, m.lengthB);
    return m;
}

inline float pulleyMass(const ConstraintBodies& b, const PulleyPart& p, const PulleyMeasure& m) {
    const float ruA = cross(m.rA, m.uA);
    const float ruB = cross(m.rB, m.uB);
    const float kA = b.mA + b.iA * ruA * ruA;
    const float kB = b.mB + b.iB * ruB * ruB;
    const float k = kA + p.ratio * p.ratio * kB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

/// Measures the part at the given poses and stores what the solves reuse; returns C.
inline float preparePulley(const ConstraintBodies& b, PulleyPart& p, const SolverPose* poses) {
    const PulleyMeasure m = measurePulley(b, p, poses);
    p.rA = m.rA;
    p.rB = m.rB;
    p.uA = m.uA;
    p.uB = m.uB;
    p.mass = pulleyMass(b, p, m);
    return p.constant - m.lengthA - p.ratio * m.lengthB;
}

inline float pulleySpeed(const PulleyPart& p, const SolverVelocity& A, const SolverVelocity& B) {
    const Vec2 vA = A.v + cross(A.w, p.rA);
    const Vec2 vB = B.v + cross(B.w, p.rB);
    return -dot(p.uA, vA) - p.ratio * dot(p.uB, vB);
}

inline void applyPulleyImpulse(const ConstraintBodies& b, const PulleyPart& p,
                               SolverVelocity* velocities, float lambda) {
    const Vec2 PA = -lambda * p.uA;
    const Vec2 PB = (-p.ratio * lambda) * p.uB;
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    A.v += b.mA * PA;
    A.w += b.iA * cross(p.rA, PA);
    B.v += b.mB * PB;
    B.w += b.iB * cross(p.rB, PB);
}

/// Moves the poses by lambda along the rope, measured as `m` (as applyPulleyImpulse moves the
/// velocities).
inline void movePulley(const ConstraintBodies& b, const PulleyPart& p, const PulleyMeasure& m,
                       SolverPose* poses, float lambda) {
    const Vec2 PA = -lambda * m.uA;
    const Vec2 PB = (-p.ratio * lambda) * m.uB;
    SolverPose& A = poses[b.indexA];
    SolverPose& B = poses[b.indexB];
    A.c += b.mA * PA;
    A.a += b.iA * cross(m.rA, PA);
    B.c += b.mB * PB;
    B.a += b.iB * cross(m.rB, PB);
}

/// One nonlinear Gauss-Seidel solve on positions: re-measure, move the bodies by -beta C / K.
/// With rebuildMass K is that of the current poses (FullNGS), otherwise p.mass as frozen
/// (ModifiedNGS). Returns |C| before the correction.
template <bool rebuildMass>
inline float solvePulleyPosition(const ConstraintBodies& b, const PulleyPart& p, SolverPose* poses,
                                 float beta) {
    const PulleyMeasure m = measurePulley(b, p, poses);
    const float mass = rebuildMass ? pulleyMass(b, p, m) : p.mass;
    const float C = p.constant - m.lengthA - p.ratio * m.lengthB;
    movePulley(b, p, m, poses, -beta * mass * C);
    return std::fabs(C);
}

}  // namespace pivot
