// The point-to-point constraint part of the revolute joint, as the solver sees it.
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
// The functions here do not know which PositionSolver calls them: the strategies in
// solver/position_solver.cpp differ only in when they recompute C, r and K.
#pragma once

#include <cstdint>

#include "pivot/math.h"
#include "solver/solver_types.h"

namespace pivot {

struct PointConstraint {
    std::int32_t indexA = 0;  // solver indices of the bodies
    std::int32_t indexB = 0;
    std::int32_t jointIndex = 0;  // where the impulse is stored back
    float mA = 0.0f, mB = 0.0f;   // inverse masses
    float iA = 0.0f, iB = 0.0f;   // inverse rotational inertias
    Vec2 localRA;                 // anchor relative to the centre of mass, in body A's frame
    Vec2 localRB;
    Vec2 rA;  // world radius vectors when last prepared
    Vec2 rB;
    Mat22 K;       // effective mass matrix when last prepared
    Vec2 impulse;  // accumulated impulse (velocity phase), N s
    Vec2 bias;     // velocity bias, m/s (Baumgarte in the velocity phase, PseudoVelocity pass)
    float biasFactor = 0.0f;
};

// K is evaluated in two float orders: the same matrix, rounded differently. The velocity phase
// and the position phase each use the order Box2D 2.4.1's revolute joint uses in that phase, so
// FullNGS reproduces that reference joint bit for bit wherever the inputs agree (see
// docs/reference-agreement.md). Any other choice costs nothing but that exactness.
inline Mat22 pointEffectiveMass(float mA, float mB, float iA, float iB, Vec2 rA, Vec2 rB) {
    Mat22 K;
    K.cx.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    K.cy.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    K.cx.y = K.cy.x;
    K.cy.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    return K;
}

inline Mat22 pointEffectiveMassForPositions(float mA, float mB, float iA, float iB, Vec2 rA,
                                            Vec2 rB) {
    Mat22 K;
    K.cx.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    K.cx.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    K.cy.x = K.cx.y;
    K.cy.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
    return K;
}

/// Radius vectors and effective mass from the current angles; returns the current error C.
inline Vec2 preparePoint(PointConstraint& pc, const SolverPosition* positions) {
    const SolverPosition& A = positions[pc.indexA];
    const SolverPosition& B = positions[pc.indexB];
    pc.rA = rotate(Rot(A.a), pc.localRA);
    pc.rB = rotate(Rot(B.a), pc.localRB);
    pc.K = pointEffectiveMass(pc.mA, pc.mB, pc.iA, pc.iB, pc.rA, pc.rB);
    return B.c + pc.rB - A.c - pc.rA;
}

inline void applyPointImpulse(const PointConstraint& pc, SolverVelocity* velocities, Vec2 P) {
    SolverVelocity& A = velocities[pc.indexA];
    SolverVelocity& B = velocities[pc.indexB];
    A.v -= pc.mA * P;
    A.w -= pc.iA * cross(pc.rA, P);
    B.v += pc.mB * P;
    B.w += pc.iB * cross(pc.rB, P);
}

/// One Gauss-Seidel solve of K P = -(Cdot + bias) on the given velocities. Returns the
/// impulse applied.
inline Vec2 solvePointVelocity(const PointConstraint& pc, SolverVelocity* velocities, Vec2 bias) {
    const SolverVelocity& A = velocities[pc.indexA];
    const SolverVelocity& B = velocities[pc.indexB];
    Vec2 cdot = B.v + cross(B.w, pc.rB) - A.v - cross(A.w, pc.rA);
    Vec2 P = pc.K.solve(-(cdot + bias));
    applyPointImpulse(pc, velocities, P);
    return P;
}

/// One nonlinear Gauss-Seidel solve on positions: re-measure C and the radius vectors at the
/// current pose, then move both bodies by the impulse -biasFactor K^-1 C. With rebuildMass K
/// is recomputed from the new radius vectors (FullNGS), otherwise pc.K is used as frozen
/// (ModifiedNGS). Returns |C| before the correction.
template <bool rebuildMass>
inline float solvePointPosition(const PointConstraint& pc, SolverPosition* positions) {
    SolverPosition& A = positions[pc.indexA];
    SolverPosition& B = positions[pc.indexB];
    Vec2 rA = rotate(Rot(A.a), pc.localRA);
    Vec2 rB = rotate(Rot(B.a), pc.localRB);
    Vec2 C = B.c + rB - A.c - rA;
    float error = length(C);
    Mat22 K =
        rebuildMass ? pointEffectiveMassForPositions(pc.mA, pc.mB, pc.iA, pc.iB, rA, rB) : pc.K;
    Vec2 P = -pc.biasFactor * K.solve(C);
    A.c -= pc.mA * P;
    A.a -= pc.iA * cross(rA, P);
    B.c += pc.mB * P;
    B.a += pc.iB * cross(rB, P);
    return error;
}

}  // namespace pivot
