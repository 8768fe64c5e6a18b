// The wheel joint as the solver sees it for one step: its two bodies, the axis part along the
// suspension (spring, limits) and across it (the line the anchor is held on), and the motor on
// the relative rotation (constraints/axis_part.h has the rows' maths).
//
//   d = (cB + rB) - (cA + rA),  u = R(aA) axis,  n = R(aA) perp
//   line    C = n . d                    a position constraint, corrected by the strategy
//   spring  soft on u towards x = u . d = 0 (constraints/soft_factors.h)
//   limits  on x (AxisLimits), corrected by the strategy
//   motor   Cdot = wB - wA - speed, K = iA + iB, impulse within h maxTorque; velocity only
// The velocity phase solves spring, motor, limits, then the line, which gets the last word. An
// NGS solve corrects a reached limit, then the line, each a scalar re-measured at the current
// poses (as Box2D 2.4.1's wheel joint), each capped at kMaxLinearCorrection as the prismatic
// joint's. ModifiedNGS keeps the rows' masses of the poses the sweeps start from, FullNGS
// rebuilds them at every solve. It offers the strategies the same operations as every joint
// constraint (revolute_constraint.h lists them).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "constraints/axis_part.h"
#include "constraints/constraint_bodies.h"
#include "constraints/soft_factors.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/joint.h"
#include "joints/wheel_joint.h"

namespace pivot {

struct WheelConstraint {
    using Storage = WheelJoint;

    ConstraintBodies bodies;
    AxisRow axis;  // when last measured
    AxisRow perp;
    float axialMass = 0.0f;  // 1 / K of each row (0 when K is), as last measured or frozen
    float perpMass = 0.0f;
    float translation = 0.0f;  // x when last measured
    float lineError = 0.0f;    // n . d when last measured
    float impulse = 0.0f;      // the line's, accumulated
    float lineBias = 0.0f;     // the line's velocity bias (Baumgarte, the pseudo-velocity pass)
    AxisLimits limits;
    bool spring = false;
    SoftFactors springFactors;
    float springImpulse = 0.0f;
    bool motorEnabled = false;
    float motorSpeed = 0.0f;
    float maxMotorImpulse = 0.0f;
    float motorImpulse = 0.0f;
    Vec2 localRA;
    Vec2 localRB;
    Vec2 localAxis;
    Vec2 localPerp;
    float biasFactor = 0.0f;
    SoftFactors soft;  // SoftStep's (constraints/rows.h)
    XpbdRows xpbd;     // XPBD's (constraints/xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the joint's impulses as
    /// stored. Returns the joint's separation squared, m^2 (WheelJoint::separation).
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const WheelJoint& w = std::get<WheelJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        localRA = joint.localAnchorA - a.localCenter;
        localRB = joint.localAnchorB - b.localCenter;
        localAxis = w.localAxisA;
        localPerp = w.localPerpA();
        measure(poses);
        impulse = w.impulse;
        spring = w.spring.enabled;
        springImpulse = spring ? w.springImpulse : 0.0f;
        if (spring) springFactors = SoftFactors::of(w.spring, step.dt);
        limits.load(w.enableLimit, w.lowerTranslation, w.upperTranslation, w.lowerImpulse,
                    w.upperImpulse, translation, step.invDt);
        motorEnabled = w.enableMotor && !bodies.fixedRotation();
        motorSpeed = w.motorSpeed;
        maxMotorImpulse = step.dt * w.maxMotorTorque;
        motorImpulse = motorEnabled ? w.motorImpulse : 0.0f;
        const float beyond = limits.enabled ? limits.violation(translation) : 0.0f;
        return lineError * lineError + beyond * beyond;
    }

    /// A later substep: the constraint kept from the one before, its impulses as stored, is
    /// measured again at the current poses (the same operations as in prepare).
    void remeasure(const SolverPose* poses, const StepContext& step) {
        measure(poses);
        limits.setTerms(translation, step.invDt);
    }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        if (warmStarting) {
            impulse *= dtRatio;
            springImpulse *= dtRatio;
            motorImpulse *= dtRatio;
            limits.lowerImpulse *= dtRatio;
            limits.upperImpulse *= dtRatio;
        } else {
            impulse = springImpulse = motorImpulse = 0.0f;
            limits.lowerImpulse = limits.upperImpulse = 0.0f;
        }
    }

    /// A let-go joint's constraint: no rows, and its bodies' masses taken as zero.
    void makeInert() {
        WheelConstraint inert;
        inert.bodies = bodies;
        inert.bodies.mA = inert.bodies.mB = inert.bodies.iA = inert.bodies.iB = 0.0f;
        inert.jointIndex = jointIndex;
        *this = inert;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        WheelJoint& w = std::get<WheelJoint>(joint.data);
        w.impulse = impulse;
        w.springImpulse = springImpulse;
        w.motorImpulse = motorImpulse;
        w.lowerImpulse = limits.lowerImpulse;
        w.upperImpulse = limits.upperImpulse;
        w.axis = axis.u;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const {
        const ConstraintBodies& b = bodies;
        SolverVelocity& A = velocities[b.indexA];
        SolverVelocity& B = velocities[b.indexB];
        const float axial = springImpulse + limits.lowerImpulse - limits.upperImpulse;
        const Vec2 P = impulse * perp.u + axial * axis.u;
        const float LA = impulse * perp.a1 + axial * axis.a1 + motorImpulse;
        const float LB = impulse * perp.a2 + axial * axis.a2 + motorImpulse;
        A.v -= b.mA * P;
        A.w -= b.iA * LA;
        B.v += b.mB * P;
        B.w += b.iB * LB;
    }

    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if (spring) {
            const float cdot =
                axisSpeed(axis, velocities[bodies.indexA], velocities[bodies.indexB]);
            const float lambda = -springFactors.massScale * axialMass *
                                     (cdot + springFactors.biasRate * translation) -
                                 springFactors.impulseScale * springImpulse;
            springImpulse += lambda;
            applyAxisImpulse(bodies, axis, velocities, lambda);
        }
        if (motorEnabled) solveMotor(velocities);
        if (limits.enabled) limits.solve<rows>(bodies, axis, axialMass, velocities, soft);
        if constexpr (rows != Rows::None) {
            impulse += solveLine<rows>(velocities, rows != Rows::Rigid ? lineBias : 0.0f);
        }
    }

    /// XPBD: the limits, then the line across the axis, each re-measured (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        if (limits.enabled) {
            xpbdAxisLimits(bodies, limits, localRA, localRB, localAxis, poses, xpbd.alphaTilde,
                           &xpbd.lambda[1]);
        }
        const AxisFrame f = frameAt(poses);
        const AxisRow n = axisRow(f, rotate(Rot(poses[bodies.indexA].a), localPerp));
        moveAlongAxis(bodies, n, poses,
                      xpbdDelta(dot(n.u, f.d), axisK(bodies, n), xpbd.alphaTilde, xpbd.lambda[0]));
    }
    /// After the XPBD sweeps: the impulses they applied, added to the velocity rows' as the
    /// reactions.
    void takeXpbdReactions(float invH) {
        impulse += invH * xpbd.lambda[0];
        limits.lowerImpulse += invH * xpbd.lambda[1];
        limits.upperImpulse += invH * xpbd.lambda[2];
    }

    void setBias(const SolverPose*, float k) {
        lineBias = k * lineError;
        if (limits.enabled) limits.setBias(translation, k);
    }

    void restartAt(const SolverPose* poses, float invH) {
        measure(poses);
        limits.lowerImpulse = limits.upperImpulse = 0.0f;
        limits.setTerms(translation, invH);
    }

    void solvePseudoVelocity(SolverVelocity* pseudo) {
        if (limits.enabled) limits.solve(bodies, axis, axialMass, pseudo);
        solveLine(pseudo, lineBias);
    }

    void freezeMass(const SolverPose* poses) { measure(poses); }

    /// A reached limit, then the line, each re-measured. Within slop means both were within
    /// kLinearSlop before their corrections.
    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        float linearError = 0.0f;
        if (limits.enabled) {
            const AxisFrame f = frameAt(poses);
            const AxisRow u = axisRow(f, rotate(Rot(poses[bodies.indexA].a), localAxis));
            const float x = dot(u.u, f.d);
            if (limits.active(x)) {
                const float C = limits.positionError(x);
                linearError = limits.equal() ? std::fabs(x - limits.lower) : limits.violation(x);
                move(poses, u, rebuildMass ? axisMass(bodies, u) : axialMass, C);
            }
        }
        const AxisFrame f = frameAt(poses);
        const AxisRow n = axisRow(f, rotate(Rot(poses[bodies.indexA].a), localPerp));
        const float C = dot(n.u, f.d);
        linearError = std::max(linearError, std::fabs(C));
        move(poses, n, rebuildMass ? axisMass(bodies, n) : perpMass, C);
        return linearError <= kLinearSlop;
    }

private:
    /// Rows, masses, translation and line error at the given poses.
    void measure(const SolverPose* poses) {
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        const AxisFrame f = axisFrameForVelocities(A, B, localRA, localRB);
        const Rot qA(A.a);
        axis = axisRow(f, rotate(qA, localAxis));
        perp = axisRow(f, rotate(qA, localPerp));
        axialMass = axisMass(bodies, axis);
        perpMass = axisMass(bodies, perp);
        translation = dot(axis.u, f.d);
        lineError = dot(perp.u, f.d);
    }

    AxisFrame frameAt(const SolverPose* poses) const {
        return axisFrameForPositions(poses[bodies.indexA], poses[bodies.indexB], localRA, localRB);
    }

    /// Moves the poses by the impulse -beta mass C along the row, C capped.
    void move(SolverPose* poses, const AxisRow& r, float mass, float C) const {
        const float capped = std::clamp(C, -kMaxLinearCorrection, kMaxLinearCorrection);
        moveAlongAxis(bodies, r, poses, -biasFactor * mass * capped);
    }

    void solveMotor(SolverVelocity* velocities) {
        float& wA = velocities[bodies.indexA].w;
        float& wB = velocities[bodies.indexB].w;
        const float cdot = wB - wA - motorSpeed;
        float lambda = -cdot / (bodies.iA + bodies.iB);
        const float old = motorImpulse;
        motorImpulse = std::clamp(old + lambda, -maxMotorImpulse, maxMotorImpulse);
        lambda = motorImpulse - old;
        wA -= bodies.iA * lambda;
        wB += bodies.iB * lambda;
    }

    /// One solve of the line row with the given bias; returns the impulse applied.
    template <Rows rows = Rows::Biased>
    float solveLine(SolverVelocity* velocities, float bias) {
        const float cdot = axisSpeed(perp, velocities[bodies.indexA], velocities[bodies.indexB]);
        const float lambda = soften<rows>(-perpMass * (cdot + bias), impulse, soft);
        applyAxisImpulse(bodies, perp, velocities, lambda);
        return lambda;
    }
};

}  // namespace pivot
