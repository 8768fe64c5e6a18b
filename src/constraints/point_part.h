// The point part of the revolute joint: anchor A pinned to anchor B.
//
//   C    = (cB + rB) - (cA + rA)                      position error, m (2 rows)
//   Cdot = vB + wB x rB - vA - wA x rA                velocity error, m/s
//   J    = [ -I  -skew(rA)  I  skew(rB) ]             with skew(r) w = w x r = (-w r.y, w r.x)
//   K    = J M^-1 J^T                                 effective mass (inverse), 2x2
//        = (mA + mB) I + iA [ rA.y^2  -rA.x rA.y ]  + iB [ rB.y^2  -rB.x rB.y ]
//                           [ -rA.x rA.y  rA.x^2 ]       [ -rB.x rB.y  rB.x^2 ]
// where m and i are inverse mass and inverse rotational inertia. An impulse P acts on B and -P
// on A at the anchor: vB += mB P, wB += iB rB x P, and the opposite on A.
//
// The functions here do not know which strategy calls them: the strategies
// (src/strategies/position_strategies.h) differ only in when they recompute C, r and K, and in
// where the bias goes.
#pragma once

#include <cmath>

#include "constraints/constraint_bodies.h"
#include "constraints/rows.h"
#include "constraints/solver_body.h"
#include "pivot/math.h"

namespace pivot {

// The fields every velocity iteration reads come first, so one joint's working set shares as
// few cache lines as possible.
struct PointPart {
    Vec2 rA;  // world radius vectors when last prepared
    Vec2 rB;
    Mat22 K;              // effective mass matrix when last prepared (see cacheInverse)
    float invDet = 0.0f;  // 1 / det K (0 when singular), as Mat22::solve computes it
    Vec2 impulse;         // accumulated impulse (velocity phase), N s
    Vec2 bias;            // velocity bias, m/s (Baumgarte, and the PseudoVelocity pass)
    Vec2 localRA;         // anchor relative to the centre of mass, in body A's frame
    Vec2 localRB;
};

/// K^-1 b with K's inverse determinant cached: the same operations as Mat22::solve, so the same
/// bits, without a division per solve.
inline Vec2 solveWithCachedDet(const PointPart& p, Vec2 b) {
    const float a11 = p.K.cx.x, a12 = p.K.cy.x, a21 = p.K.cx.y, a22 = p.K.cy.y;
    return {p.invDet * (a22 * b.x - a12 * b.y), p.invDet * (a11 * b.y - a21 * b.x)};
}

/// Stores K for solveWithCachedDet the way Mat22::solve forms it (Mat22::cramer): K and
/// 1 / det K, or, when det K overflows (a light body on a lever arm of kilometres), K / s with
/// 1 / (s det(K / s)). Ordinary joints keep Box2D's operations.
inline void cacheInverse(PointPart& p, const Mat22& K) {
    const Mat22::Cramer k = K.cramer();
    p.K = {{k.a11, k.a21}, {k.a12, k.a22}};
    p.invDet = k.invDet;
}

// K is evaluated in two float orders: the same matrix, rounded differently. The velocity phase
// and the position phase each use the order Box2D 2.4.1's revolute joint uses in that phase, so
// FullNGS reproduces that reference joint bit for bit wherever the inputs agree (see
// docs/reference-agreement.md). Any other choice costs nothing but that exactness.
inline Mat22 pointEffectiveMass(const ConstraintBodies& b, Vec2 rA, Vec2 rB) {
    Mat22 K;
    K.cx.x = b.mA + b.mB + rA.y * rA.y * b.iA + rB.y * rB.y * b.iB;
    K.cy.x = -rA.y * rA.x * b.iA - rB.y * rB.x * b.iB;
    K.cx.y = K.cy.x;
    K.cy.y = b.mA + b.mB + rA.x * rA.x * b.iA + rB.x * rB.x * b.iB;
    return K;
}

inline Mat22 pointEffectiveMassForPositions(const ConstraintBodies& b, Vec2 rA, Vec2 rB) {
    Mat22 K;
    K.cx.x = b.mA + b.mB + b.iA * rA.y * rA.y + b.iB * rB.y * rB.y;
    K.cx.y = -b.iA * rA.x * rA.y - b.iB * rB.x * rB.y;
    K.cy.x = K.cx.y;
    K.cy.y = b.mA + b.mB + b.iA * rA.x * rA.x + b.iB * rB.x * rB.x;
    return K;
}

/// Radius vectors and effective mass from the current angles; returns the current error C.
inline Vec2 preparePoint(const ConstraintBodies& b, PointPart& p, const SolverPose* positions,
                         const Rot& qA, const Rot& qB) {
    const SolverPose& A = positions[b.indexA];
    const SolverPose& B = positions[b.indexB];
    p.rA = rotate(qA, p.localRA);
    p.rB = rotate(qB, p.localRB);
    cacheInverse(p, pointEffectiveMass(b, p.rA, p.rB));
    return B.c + p.rB - A.c - p.rA;
}
inline Vec2 preparePoint(const ConstraintBodies& b, PointPart& p, const SolverPose* positions) {
    return preparePoint(b, p, positions, Rot(positions[b.indexA].a), Rot(positions[b.indexB].a));
}

/// One Gauss-Seidel solve of K P = -(Cdot + bias) on the given velocities, softened under
/// Rows::Soft (rows.h). Returns the impulse applied.
template <Rows rows = Rows::Biased>
inline Vec2 solvePointVelocity(const ConstraintBodies& b, const PointPart& p,
                               SolverVelocity* velocities, Vec2 bias,
                               const SoftFactors& soft = SoftFactors{}) {
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    Vec2 cdot = B.v + cross(B.w, p.rB) - A.v - cross(A.w, p.rA);
    Vec2 P = soften<rows>(solveWithCachedDet(p, -(cdot + bias)), p.impulse, soft);
    A.v -= b.mA * P;
    A.w -= b.iA * cross(p.rA, P);
    B.v += b.mB * P;
    B.w += b.iB * cross(p.rB, P);
    return P;
}

/// One nonlinear Gauss-Seidel solve on positions: re-measure C and the radius vectors at the
/// current pose, then move both bodies by the impulse -beta K^-1 C. With rebuildMass K is
/// recomputed from the new radius vectors (FullNGS), otherwise p.K is used as frozen
/// (ModifiedNGS). Returns |C| before the correction.
template <bool rebuildMass>
inline float solvePointPosition(const ConstraintBodies& b, const PointPart& p,
                                SolverPose* positions, float beta) {
    SolverPose& A = positions[b.indexA];
    SolverPose& B = positions[b.indexB];
    Vec2 rA = rotate(Rot(A.a), p.localRA);
    Vec2 rB = rotate(Rot(B.a), p.localRB);
    Vec2 C = B.c + rB - A.c - rA;
    float error = length(C);
    // The frozen K through its cached inverse determinant: the same operations as K.solve.
    Vec2 P = -beta * (rebuildMass ? pointEffectiveMassForPositions(b, rA, rB).solve(C)
                                  : solveWithCachedDet(p, C));
    A.c -= b.mA * P;
    A.a -= b.iA * cross(rA, P);
    B.c += b.mB * P;
    B.a += b.iB * cross(rB, P);
    return error;
}

}  // namespace pivot
