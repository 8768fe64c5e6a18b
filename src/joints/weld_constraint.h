// The weld joint as the solver sees it for one step: the point part's anchors and the angle,
// held together as one 3x3 block.
//
//   C    = [ (cB + rB) - (cA + rA) ,  aB - aA - referenceAngle ]     3 rows
//   Cdot = [ vB + wB x rB - vA - wA x rA ,  wB - wA ]
//   K    = [ K2                          -rA.y iA - rB.y iB ]         K2 the pin's 2x2
//          [                              rA.x iA + rB.x iB ]         (point_part.h)
//          [ (sym)                        iA + iB           ]
// An impulse (P, L) acts as P at the anchors and the torque L: vB += mB P,
// wB += iB (rB x P + L), the opposite on A. Solving the block at once keeps a long beam of
// welds from bending where the point and angle rows, solved one after the other, would fight.
//
// Either half may be soft instead (WeldJointDef's springs): a spring on that half's own
// effective mass (K2 for the point, iA + iB for the angle; constraints/soft_factors.h), solved
// before the rigid rows. A soft half has no position correction: the spring is its own. The rigid
// rows are corrected as the joint's strategy says; ModifiedNGS freezes K at the poses the sweeps
// start from, FullNGS rebuilds it at every solve (Box2D 2.4.1's weld, bit for bit when both halves
// are rigid). It offers the strategies the same operations as every joint constraint
// (revolute_constraint.h lists them).
#pragma once

#include <cmath>
#include <cstdint>

#include "constraints/constraint_bodies.h"
#include "constraints/point_part.h"
#include "constraints/soft_factors.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "core/mat33.h"
#include "joints/joint.h"
#include "joints/weld_joint.h"

namespace pivot {

/// The weld's K at radius vectors rA, rB, in Box2D 2.4.1's float order.
inline Mat33 weldEffectiveMass(const ConstraintBodies& b, Vec2 rA, Vec2 rB) {
    const Mat22 k2 = pointEffectiveMass(b, rA, rB);
    const float k13 = -rA.y * b.iA - rB.y * b.iB;
    const float k23 = rA.x * b.iA + rB.x * b.iB;
    return {{k2.cx.x, k2.cx.y, k13}, {k2.cy.x, k2.cy.y, k23}, {k13, k23, b.iA + b.iB}};
}

struct WeldConstraint {
    using Storage = WeldJoint;

    ConstraintBodies bodies;
    Vec2 rA;  // world radius vectors when last measured
    Vec2 rB;
    Mat33 K;     // when last measured (frozen for ModifiedNGS)
    Mat33 mass;  // the velocity rows' inverse: of K when both halves are rigid, else of K2
    float angularMass = 0.0f;  // 1 / (iA + iB), 0 when both are fixed in rotation
    Vec3 impulse;              // accumulated
    Vec3 bias;                 // the rigid rows' velocity bias (Baumgarte, the pseudo pass)
    Vec2 pointError;           // C when last measured
    float angleError = 0.0f;
    bool softPoint = false;
    bool softAngle = false;
    SoftFactors linear;
    SoftFactors angular;
    Vec2 localRA;
    Vec2 localRB;
    float referenceAngle = 0.0f;
    float biasFactor = 0.0f;
    SoftFactors soft;  // SoftStep's (constraints/rows.h)
    XpbdRows xpbd;     // XPBD's (constraints/xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the joint's impulse as
    /// stored. Returns the joint's separation squared, m^2 (WeldJoint::separation).
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const WeldJoint& w = std::get<WeldJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        localRA = joint.localAnchorA - a.localCenter;
        localRB = joint.localAnchorB - b.localCenter;
        referenceAngle = joint.referenceAngle;
        softPoint = w.linearSpring.enabled;
        softAngle = w.angularSpring.enabled;
        measure(poses);
        impulse = w.impulse;
        if (softPoint) linear = SoftFactors::of(w.linearSpring, step.dt);
        if (softAngle) angular = SoftFactors::of(w.angularSpring, step.dt);
        return softPoint ? 0.0f : lengthSquared(pointError);
    }

    /// A later substep: the constraint kept from the one before, its impulses as stored, is
    /// measured again at the current poses (the same operations as in prepare).
    void remeasure(const SolverPose* poses, const StepContext&) { measure(poses); }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        impulse = warmStarting ? dtRatio * impulse : Vec3{};
    }

    /// A let-go joint's constraint: no rows, and its bodies' masses taken as zero.
    void makeInert() {
        WeldConstraint inert;
        inert.bodies = bodies;
        inert.bodies.mA = inert.bodies.mB = inert.bodies.iA = inert.bodies.iB = 0.0f;
        inert.jointIndex = jointIndex;
        *this = inert;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        std::get<WeldJoint>(joint.data).impulse = impulse;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const { apply(velocities, impulse); }

    /// The soft halves, then the rigid ones: what must hold gets the last word.
    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if (softAngle) {
            const float cdot = velocities[bodies.indexB].w - velocities[bodies.indexA].w;
            const float lambda =
                -angular.massScale * angularMass * (cdot + angular.biasRate * angleError) -
                angular.impulseScale * impulse.z;
            impulse.z += lambda;
            apply(velocities, {0.0f, 0.0f, lambda});
        }
        if (softPoint) {
            const Vec2 cdot = pointSpeed(velocities);
            const Vec2 acc{impulse.x, impulse.y};
            const Vec2 lambda =
                -linear.massScale * mul22(mass, cdot + linear.biasRate * pointError) -
                linear.impulseScale * acc;
            impulse.x += lambda.x;
            impulse.y += lambda.y;
            apply(velocities, {lambda.x, lambda.y, 0.0f});
        }
        if constexpr (rows == Rows::None) return;
        const Vec3 applied = solveRigid<rows>(velocities, rows != Rows::Rigid ? bias : Vec3{});
        impulse.x += applied.x;
        impulse.y += applied.y;
        impulse.z += applied.z;
    }

    void setBias(const SolverPose*, float k) {
        bias = {k * pointError.x, k * pointError.y, k * angleError};
    }

    void restartAt(const SolverPose* poses, float) { measure(poses); }

    void solvePseudoVelocity(SolverVelocity* pseudo) { solveRigid(pseudo, bias); }

    void freezeMass(const SolverPose* poses) { measure(poses); }

    /// XPBD on the rigid halves: the angle, then the point (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        if (!softAngle) {
            const float C = poses[bodies.indexB].a - poses[bodies.indexA].a - referenceAngle;
            xpbdAngle(bodies, poses, C, xpbd.alphaTilde, xpbd.lambda[1]);
        }
        if (!softPoint) {
            xpbdPoint(bodies, localRA, localRB, poses, xpbd.alphaTilde, xpbd.lambda[0], xpbd.point);
        }
    }
    /// After the XPBD sweeps: the rigid rows' impulses (the velocity iterations' and the sweeps'),
    /// beside the soft halves' own.
    void takeXpbdReactions(float invH) {
        if (!softPoint) {
            impulse.x += invH * xpbd.point.x;
            impulse.y += invH * xpbd.point.y;
        }
        if (!softAngle) impulse.z += invH * xpbd.lambda[1];
    }

    /// One NGS solve of the rigid rows: the block when both halves are rigid.
    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        if (softPoint && softAngle) return true;
        SolverPose& A = poses[bodies.indexA];
        SolverPose& B = poses[bodies.indexB];
        const Vec2 ra = rotate(Rot(A.a), localRA);
        const Vec2 rb = rotate(Rot(B.a), localRB);
        const Vec2 C1 = B.c + rb - A.c - ra;
        const float C2 = B.a - A.a - referenceAngle;
        const float positionError = softPoint ? 0.0f : length(C1);
        const float angularError = softAngle ? 0.0f : std::fabs(C2);
        const Mat33 k = rebuildMass ? weldEffectiveMass(bodies, ra, rb) : K;
        Vec3 lambda;
        if (!softPoint && !softAngle && k.cz.z > 0.0f) {
            lambda = -biasFactor * k.solve({C1.x, C1.y, C2});
        } else if (!softPoint) {
            const Vec2 l = -biasFactor * k.solve22(C1);
            lambda = {l.x, l.y, 0.0f};
        } else if (k.cz.z > 0.0f) {
            lambda = {0.0f, 0.0f, -biasFactor * C2 / k.cz.z};
        }
        const Vec2 P{lambda.x, lambda.y};
        A.c -= bodies.mA * P;
        A.a -= bodies.iA * (cross(ra, P) + lambda.z);
        B.c += bodies.mB * P;
        B.a += bodies.iB * (cross(rb, P) + lambda.z);
        return positionError <= kLinearSlop && angularError <= kAngularSlop;
    }

private:
    /// Radius vectors, K, the velocity rows' inverse and the errors at the given poses.
    void measure(const SolverPose* poses) {
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        rA = rotate(Rot(A.a), localRA);
        rB = rotate(Rot(B.a), localRB);
        K = weldEffectiveMass(bodies, rA, rB);
        const bool block = !softPoint && !softAngle && K.cz.z != 0.0f;
        mass = block ? K.symmetricInverse() : K.inverse22();
        angularMass = K.cz.z > 0.0f ? 1.0f / K.cz.z : 0.0f;
        pointError = B.c + rB - A.c - rA;
        angleError = B.a - A.a - referenceAngle;
    }

    Vec2 pointSpeed(const SolverVelocity* velocities) const {
        const SolverVelocity& A = velocities[bodies.indexA];
        const SolverVelocity& B = velocities[bodies.indexB];
        return B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
    }

    void apply(SolverVelocity* velocities, Vec3 l) const {
        SolverVelocity& A = velocities[bodies.indexA];
        SolverVelocity& B = velocities[bodies.indexB];
        const Vec2 P{l.x, l.y};
        A.v -= bodies.mA * P;
        A.w -= bodies.iA * (cross(rA, P) + l.z);
        B.v += bodies.mB * P;
        B.w += bodies.iB * (cross(rB, P) + l.z);
    }

    /// One solve of the rigid rows with the given bias, softened under Rows::Soft (the halves
    /// that are springs keep their own softness); returns the impulse applied.
    template <Rows rows = Rows::Biased>
    Vec3 solveRigid(SolverVelocity* velocities, Vec3 rowBias) {
        if (softPoint && softAngle) return {};
        const Vec2 cdot1 = pointSpeed(velocities);
        const float cdot2 = velocities[bodies.indexB].w - velocities[bodies.indexA].w;
        Vec3 lambda;
        if (!softPoint && !softAngle) {
            lambda = -(mass * Vec3{cdot1.x + rowBias.x, cdot1.y + rowBias.y, cdot2 + rowBias.z});
        } else if (!softPoint) {
            const Vec2 l = -mul22(mass, cdot1 + Vec2{rowBias.x, rowBias.y});
            lambda = {l.x, l.y, 0.0f};
        } else {
            lambda = {0.0f, 0.0f, -angularMass * (cdot2 + rowBias.z)};
        }
        if constexpr (rows == Rows::Soft) {
            // Only the rigid rows' own accumulated impulse is relaxed.
            const Vec3 rigidImpulse{softPoint ? 0.0f : impulse.x, softPoint ? 0.0f : impulse.y,
                                    softAngle ? 0.0f : impulse.z};
            lambda = soften<rows>(lambda, rigidImpulse, soft);
        }
        apply(velocities, lambda);
        return lambda;
    }
};

}  // namespace pivot
