// The prismatic joint as the solver sees it for one step: its two bodies, the axis part along
// the slide (spring, motor, limits) and the block that holds the slide straight: the axis part
// across it (perp) and the angle, solved together.
//
//   d = (cB + rB) - (cA + rA), u = R(aA) axis, n = R(aA) perp    (constraints/axis_part.h)
//   block C = [ n . d ,  aB - aA - referenceAngle ]               2 rows, position constraints
//   K2 = [ mA + mB + iA s1^2 + iB s2^2   iA s1 + iB s2 ]         s1 = (d + rA) x n, s2 = rB x n
//        [ iA s1 + iB s2                 iA + iB       ]         (iA + iB = 0: 1, the row idle)
// An impulse (p, L) of the block acts as p n at the anchors and the torque L: vB += mB p n,
// wB += iB (p s2 + L), the opposite on A.
//
// Along u the translation x = u . d is free but for the rows the joint's settings ask for: the
// spring (soft, towards x = 0, as the distance joint's), the motor (velocity only) and the
// limits (AxisLimits). In the velocity phase each axis row is a scalar solve before the block;
// in the NGS solves a reached limit joins the block as a third row, C = limit error, with
//   K3 = [ K2           k13 ]   k13 = iA s1 a1 + iB s2 a2,  k23 = iA a1 + iB a2,
//        [ k13 k23      k33 ]   k33 = mA + mB + iA a1^2 + iB a2^2,   a1, a2 the axis row's,
// so that correcting the limit does not undo the slide, nor the slide the limit. ModifiedNGS
// freezes K2 and K3 at the poses the sweeps start from; FullNGS rebuilds them at every solve.
// Each NGS solve corrects at most kMaxLinearCorrection of the line and limit errors and
// kMaxAngularCorrection of the angle. Box2D 2.4.1's prismatic joint has no such cap (its earlier
// versions had); without it, in random tests, joints created far from their reference angle and
// line diverged within a step under both NGS strategies: the lever arm of the line row about
// A, d + rA, changes with every correction, and a full Newton step on a large error overshoots.
// Below the caps (every ordinary step) the solves are Box2D's, bit for bit.
// It offers the strategies the same operations as every joint constraint (revolute_constraint.h
// lists them).
#pragma once

#include <cmath>
#include <cstdint>

#include "constraints/axis_part.h"
#include "constraints/constraint_bodies.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "core/mat33.h"
#include "joints/joint.h"
#include "joints/prismatic_joint.h"

namespace pivot {

/// The block's K2 from the perp row.
inline Mat22 slideBlockMass(const ConstraintBodies& b, const AxisRow& perp) {
    const float k12 = b.iA * perp.a1 + b.iB * perp.a2;
    float k22 = b.iA + b.iB;
    if (k22 == 0.0f) k22 = 1.0f;
    return {{axisK(b, perp), k12}, {k12, k22}};
}

/// The block with the limit's row: K3 from the perp and axis rows.
inline Mat33 slideLimitBlockMass(const ConstraintBodies& b, const AxisRow& perp,
                                 const AxisRow& axis) {
    const Mat22 k2 = slideBlockMass(b, perp);
    const float k13 = b.iA * perp.a1 * axis.a1 + b.iB * perp.a2 * axis.a2;
    const float k23 = b.iA * axis.a1 + b.iB * axis.a2;
    return {{k2.cx.x, k2.cx.y, k13}, {k2.cy.x, k2.cy.y, k23}, {k13, k23, axisK(b, axis)}};
}

struct PrismaticConstraint {
    using Storage = PrismaticJoint;

    ConstraintBodies bodies;
    AxisRow axis;  // when last measured
    AxisRow perp;
    float axialMass = 0.0f;    // 1 / K of the axis row (0 when K is)
    Mat22::Cramer block{};     // K2 as solved (start of step; frozen for ModifiedNGS)
    Mat33 limitBlock;          // K3, frozen for ModifiedNGS
    Vec2 impulse;              // the block's, accumulated
    Vec2 bias;                 // the block's velocity bias (Baumgarte, the pseudo-velocity pass)
    float translation = 0.0f;  // x when last measured
    Vec2 blockError;           // the block's C when last measured
    AxisLimits limits;
    bool motorEnabled = false;
    bool spring = false;
    float motorSpeed = 0.0f;
    float maxMotorImpulse = 0.0f;
    float motorImpulse = 0.0f;
    float springImpulse = 0.0f;
    float springBias = 0.0f;
    float gamma = 0.0f;
    float softMass = 0.0f;
    Vec2 localRA;
    Vec2 localRB;
    Vec2 localAxis;
    Vec2 localPerp;
    float referenceAngle = 0.0f;
    float biasFactor = 0.0f;
    SoftFactors soft;  // SoftStep's (constraints/rows.h)
    XpbdRows xpbd;     // XPBD's (constraints/xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the joint's impulses as
    /// stored. Returns the joint's separation squared, m^2 (PrismaticJoint::separation).
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const PrismaticJoint& p = std::get<PrismaticJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        localRA = joint.localAnchorA - a.localCenter;
        localRB = joint.localAnchorB - b.localCenter;
        localAxis = p.localAxisA;
        localPerp = p.localPerpA();
        referenceAngle = joint.referenceAngle;
        measure(poses);
        impulse = p.impulse;
        limits.load(p.enableLimit, p.lowerTranslation, p.upperTranslation, p.lowerImpulse,
                    p.upperImpulse, translation, step.invDt);
        motorEnabled = p.enableMotor;
        motorSpeed = p.motorSpeed;
        maxMotorImpulse = step.dt * p.maxMotorForce;
        motorImpulse = p.enableMotor ? p.motorImpulse : 0.0f;
        spring = p.enableSpring;
        springImpulse = spring ? p.springImpulse : 0.0f;
        if (spring) prepareSpring(p.hertz, p.dampingRatio, step.dt);
        const float beyond = limits.enabled ? limits.violation(translation) : 0.0f;
        return blockError.x * blockError.x + beyond * beyond;
    }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        if (warmStarting) {
            impulse = dtRatio * impulse;
            motorImpulse *= dtRatio;
            limits.lowerImpulse *= dtRatio;
            limits.upperImpulse *= dtRatio;
            springImpulse *= dtRatio;
        } else {
            impulse = Vec2{};
            motorImpulse = limits.lowerImpulse = limits.upperImpulse = springImpulse = 0.0f;
        }
    }

    /// A let-go joint's constraint: no rows, and its bodies' masses taken as zero.
    void makeInert() {
        PrismaticConstraint inert;
        inert.bodies = bodies;
        inert.bodies.mA = inert.bodies.mB = inert.bodies.iA = inert.bodies.iB = 0.0f;
        inert.jointIndex = jointIndex;
        *this = inert;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        PrismaticJoint& p = std::get<PrismaticJoint>(joint.data);
        p.impulse = impulse;
        p.motorImpulse = motorImpulse;
        p.lowerImpulse = limits.lowerImpulse;
        p.upperImpulse = limits.upperImpulse;
        p.springImpulse = springImpulse;
        p.axis = axis.u;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const {
        const ConstraintBodies& b = bodies;
        SolverVelocity& A = velocities[b.indexA];
        SolverVelocity& B = velocities[b.indexB];
        const float axial =
            springImpulse + motorImpulse + limits.lowerImpulse - limits.upperImpulse;
        const Vec2 P = impulse.x * perp.u + axial * axis.u;
        const float LA = impulse.x * perp.a1 + impulse.y + axial * axis.a1;
        const float LB = impulse.x * perp.a2 + impulse.y + axial * axis.a2;
        A.v -= b.mA * P;
        A.w -= b.iA * LA;
        B.v += b.mB * P;
        B.w += b.iB * LB;
    }

    /// Spring, motor, limits, then the block: holding the slide straight gets the last word.
    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if (spring) {
            const float cdot =
                axisSpeed(axis, velocities[bodies.indexA], velocities[bodies.indexB]);
            const float lambda = -softMass * (cdot + springBias + gamma * springImpulse);
            springImpulse += lambda;
            applyAxisImpulse(bodies, axis, velocities, lambda);
        }
        if (motorEnabled) solveMotor(velocities);
        if (limits.enabled) limits.solve<rows>(bodies, axis, axialMass, velocities, soft);
        if constexpr (rows != Rows::None) {
            impulse += solveBlock<rows>(velocities, rows != Rows::Rigid ? bias : Vec2{});
        }
    }

    /// XPBD: the limits, the angle, then the line across the axis, each re-measured
    /// (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        if (limits.enabled) {
            xpbdAxisLimits(bodies, limits, localRA, localRB, localAxis, poses, xpbd.alphaTilde,
                           &xpbd.lambda[2]);
        }
        const float angle = poses[bodies.indexB].a - poses[bodies.indexA].a - referenceAngle;
        xpbdAngle(bodies, poses, angle, xpbd.alphaTilde, xpbd.lambda[1]);
        const AxisFrame f =
            axisFrameForPositions(poses[bodies.indexA], poses[bodies.indexB], localRA, localRB);
        const AxisRow n = axisRow(f, rotate(Rot(poses[bodies.indexA].a), localPerp));
        moveAlongAxis(bodies, n, poses,
                      xpbdDelta(dot(n.u, f.d), axisK(bodies, n), xpbd.alphaTilde, xpbd.lambda[0]));
    }
    /// After the XPBD sweeps: the impulses they applied, added to the velocity rows' as the
    /// reactions.
    void takeXpbdReactions(float invH) {
        impulse += Vec2{invH * xpbd.lambda[0], invH * xpbd.lambda[1]};
        limits.lowerImpulse += invH * xpbd.lambda[2];
        limits.upperImpulse += invH * xpbd.lambda[3];
    }

    void setBias(const SolverPose*, float k) {
        bias = k * blockError;
        if (limits.enabled) limits.setBias(translation, k);
    }

    void restartAt(const SolverPose* poses, float invH) {
        measure(poses);
        limits.lowerImpulse = limits.upperImpulse = 0.0f;
        limits.setTerms(translation, invH);
    }

    void solvePseudoVelocity(SolverVelocity* pseudo) {
        if (limits.enabled) limits.solve(bodies, axis, axialMass, pseudo);
        solveBlock(pseudo, bias);
    }

    void freezeMass(const SolverPose* poses) {
        const AxisFrame f =
            axisFrameForPositions(poses[bodies.indexA], poses[bodies.indexB], localRA, localRB);
        const Rot qA(poses[bodies.indexA].a);
        const AxisRow n = axisRow(f, rotate(qA, localPerp));
        const AxisRow u = axisRow(f, rotate(qA, localAxis));
        block = slideBlockMass(bodies, n).cramer();
        limitBlock = slideLimitBlockMass(bodies, n, u);
    }

    /// One NGS solve of the block, with the limit's row while it is reached. Within slop means
    /// the slide within kLinearSlop of its line and kAngularSlop of its angle, and the limit
    /// within kLinearSlop, as measured before the correction.
    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        SolverPose& A = poses[bodies.indexA];
        SolverPose& B = poses[bodies.indexB];
        const AxisFrame f = axisFrameForPositions(A, B, localRA, localRB);
        const Rot qA(A.a);
        const AxisRow u = axisRow(f, rotate(qA, localAxis));
        const AxisRow n = axisRow(f, rotate(qA, localPerp));
        const Vec2 measured{dot(n.u, f.d), B.a - A.a - referenceAngle};
        float linearError = std::fabs(measured.x);
        const float angularError = std::fabs(measured.y);
        const Vec2 C1{std::clamp(measured.x, -kMaxLinearCorrection, kMaxLinearCorrection),
                      std::clamp(measured.y, -kMaxAngularCorrection, kMaxAngularCorrection)};
        Vec3 lambda;
        const float x = dot(u.u, f.d);
        if (limits.active(x)) {
            const float C2 =
                std::clamp(limits.positionError(x), -kMaxLinearCorrection, kMaxLinearCorrection);
            const Vec3 C{C1.x, C1.y, C2};
            linearError = std::fmax(
                linearError, limits.equal() ? std::fabs(x - limits.lower) : limits.violation(x));
            const Mat33 K = rebuildMass ? slideLimitBlockMass(bodies, n, u) : limitBlock;
            lambda = biasFactor * K.solve(-C);
        } else {
            const Vec2 l = biasFactor *
                           (rebuildMass ? slideBlockMass(bodies, n).solve(-C1) : solveCached(-C1));
            lambda = {l.x, l.y, 0.0f};
        }
        const Vec2 P = lambda.x * n.u + lambda.z * u.u;
        const float LA = lambda.x * n.a1 + lambda.y + lambda.z * u.a1;
        const float LB = lambda.x * n.a2 + lambda.y + lambda.z * u.a2;
        A.c -= bodies.mA * P;
        A.a -= bodies.iA * LA;
        B.c += bodies.mB * P;
        B.a += bodies.iB * LB;
        return linearError <= kLinearSlop && angularError <= kAngularSlop;
    }

private:
    /// Rows, masses, translation and block error at the given poses (start of step, or the
    /// pseudo-velocity pass's restart).
    void measure(const SolverPose* poses) {
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        const AxisFrame f = axisFrameForVelocities(A, B, localRA, localRB);
        const Rot qA(A.a);
        axis = axisRow(f, rotate(qA, localAxis));
        perp = axisRow(f, rotate(qA, localPerp));
        axialMass = axisMass(bodies, axis);
        block = slideBlockMass(bodies, perp).cramer();
        translation = dot(axis.u, f.d);
        blockError = {dot(perp.u, f.d), B.a - A.a - referenceAngle};
    }

    Vec2 solveCached(Vec2 b) const {
        return {block.invDet * (block.a22 * b.x - block.a12 * b.y),
                block.invDet * (block.a11 * b.y - block.a21 * b.x)};
    }

    void solveMotor(SolverVelocity* velocities) {
        const float cdot = axisSpeed(axis, velocities[bodies.indexA], velocities[bodies.indexB]);
        float lambda = axialMass * (motorSpeed - cdot);
        const float old = motorImpulse;
        motorImpulse = std::clamp(old + lambda, -maxMotorImpulse, maxMotorImpulse);
        lambda = motorImpulse - old;
        applyAxisImpulse(bodies, axis, velocities, lambda);
    }

    /// One solve of K2 (p, L) = -(Cdot + bias), softened under Rows::Soft; returns the impulse
    /// applied.
    template <Rows rows = Rows::Biased>
    Vec2 solveBlock(SolverVelocity* velocities, Vec2 blockBias) {
        SolverVelocity& A = velocities[bodies.indexA];
        SolverVelocity& B = velocities[bodies.indexB];
        const Vec2 cdot{axisSpeed(perp, A, B), B.w - A.w};
        const Vec2 df = soften<rows>(solveCached(-(cdot + blockBias)), impulse, soft);
        const Vec2 P = df.x * perp.u;
        const float LA = df.x * perp.a1 + df.y;
        const float LB = df.x * perp.a2 + df.y;
        A.v -= bodies.mA * P;
        A.w -= bodies.iA * LA;
        B.v += bodies.mB * P;
        B.w += bodies.iB * LB;
        return df;
    }

    /// The spring as the distance joint's (length_part.h), on the axis row towards x = 0.
    void prepareSpring(float hertz, float dampingRatio, float h) {
        const float omega = 2.0f * kPi * hertz;
        const float a1 = 2.0f * dampingRatio + h * omega;
        const float invMass = axialMass != 0.0f ? 1.0f / axialMass : 0.0f;
        gamma = invMass / (h * omega * a1);
        springBias = omega / a1 * translation;
        softMass = invMass + gamma != 0.0f ? 1.0f / (invMass + gamma) : 0.0f;
        if (!std::isfinite(gamma) || !std::isfinite(softMass)) {
            gamma = springBias = softMass = 0.0f;
        }
    }
};

}  // namespace pivot
