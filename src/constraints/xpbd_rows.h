// XPBD (Mueller et al. 2020, "Detailed Rigid Body Simulation with Extended Position Based
// Dynamics") on the poses of one substep, row by row, as that paper solves joints: a positional
// row along the current error direction and scalar rows (angles, axes, lengths), each with the
// generalized inverse mass
//
//   w = mA + mB + iA (rA x n)^2 + iB (rB x n)^2        (positional, along n)
//   w = iA + iB                                         (angular)
//
// and the joint's compliance alpha (m/N for lengths, rad/(N m) for angles; 0 = rigid), scaled
// to the substep as alphaTilde = alpha / h^2:
//
//   dlambda = (-C - alphaTilde lambda) / (w + alphaTilde),   lambda += dlambda,
//   x += M^-1 J^T dlambda                                   (the poses move at once)
//
// lambda starts at zero each substep (XPBD does not warm-start). After the sweeps, lambda / h is
// the impulse each row applied over the substep: each joint adds it to what its rows applied in
// the velocity iterations (nothing for a compliant joint, whose rows sit those out) and stores
// the sum as its reaction, as the other strategies store their accumulated impulses
// (takeXpbdReactions). With alpha = 0 a row is a
// full nonlinear Gauss-Seidel correction; with alpha > 0 the iterations converge to the pose where
// the row's force lambda / h^2 balances C / alpha, the same for any number of iterations or
// substeps, which is what XPBD adds to PBD. Velocities are derived from the moves afterwards
// (position_phase.cpp). A unilateral row (a limit) acts only while violated.
#pragma once

#include <cmath>

#include "constraints/constraint_bodies.h"
#include "constraints/solver_body.h"
#include "pivot/math.h"

namespace pivot {

/// A constraint's XPBD state for one substep.
struct XpbdRows {
    float alphaTilde = 0.0f;  // compliance / h^2
    float lambda[4] = {};     // per row, accumulated over the substep's iterations, N s^2
    Vec2 point;               // the positional row's lambda n, summed (its n turns)
};

/// The XPBD update of a row with error C and generalized inverse mass w; accumulates lambda.
inline float xpbdDelta(float C, float w, float alphaTilde, float& lambda) {
    const float denominator = w + alphaTilde;
    if (!(denominator > 0.0f)) return 0.0f;  // nothing can move (or the mass is not finite)
    const float delta = (-C - alphaTilde * lambda) / denominator;
    lambda += delta;
    return delta;
}

/// The positional row pinning anchor B to anchor A (the revolute pin, a rigid weld point).
/// Returns |C| before the move.
inline float xpbdPoint(const ConstraintBodies& b, Vec2 localRA, Vec2 localRB, SolverPose* poses,
                       float alphaTilde, float& lambda, Vec2& sum) {
    SolverPose& A = poses[b.indexA];
    SolverPose& B = poses[b.indexB];
    const Vec2 rA = rotate(Rot(A.a), localRA);
    const Vec2 rB = rotate(Rot(B.a), localRB);
    const Vec2 d = B.c + rB - A.c - rA;
    const float C = length(d);
    if (!(C > 0.0f)) return 0.0f;  // no direction to move along
    const Vec2 n = (1.0f / C) * d;
    const float rnA = cross(rA, n);
    const float rnB = cross(rB, n);
    const float w = b.mA + b.mB + b.iA * rnA * rnA + b.iB * rnB * rnB;
    const Vec2 P = xpbdDelta(C, w, alphaTilde, lambda) * n;
    sum += P;
    A.c -= b.mA * P;
    A.a -= b.iA * cross(rA, P);
    B.c += b.mB * P;
    B.a += b.iB * cross(rB, P);
    return C;
}

/// A scalar angular row on aB - aA with error C. Returns |C|.
inline float xpbdAngle(const ConstraintBodies& b, SolverPose* poses, float C, float alphaTilde,
                       float& lambda) {
    const float delta = xpbdDelta(C, b.iA + b.iB, alphaTilde, lambda);
    poses[b.indexA].a -= b.iA * delta;
    poses[b.indexB].a += b.iB * delta;
    return std::fabs(C);
}

/// A lower bound C >= 0 (C < 0 violated): the row acts only while violated.
inline float xpbdLowerBound(float C, float w, float alphaTilde, float& lambda) {
    return C < 0.0f ? xpbdDelta(C, w, alphaTilde, lambda) : 0.0f;
}

}  // namespace pivot
