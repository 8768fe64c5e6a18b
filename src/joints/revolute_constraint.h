// The revolute joint as the solver sees it for one step: its two bodies, the point part and the
// angle part (motor and limits), built from the stored joint into the group of its strategy.
//
// These are the operations every joint constraint offers the strategies
// (src/strategies/position_strategies.h); a strategy decides which of them run in which phase
// and with what factor, the joint only how each maps onto its parts:
//   warmStart                apply the accumulated impulses
//   solveVelocity<rows>      motor, limits, then the pin; the position rows Rigid, Biased by
//                            setBias, or Soft with the factors in `soft` (constraints/rows.h)
//   setBias(k)               velocity bias k C from the error at the current radius vectors
//   remeasure                at a later substep, what prepare measures at the poses (where
//                            offered: the others are rebuilt, CanRemeasure)
//   restartAt(h)             re-measure radius vectors, effective mass and angle at the given
//                            poses as at the start of a step of length h, limits unloaded
//   solvePseudoVelocity      the velocity rows with the bias and without the motor, not
//                            accumulated into the velocity phase's impulses
//   freezeMass               radius vectors and effective mass at the given poses
//   solvePosition<rebuild>   one nonlinear Gauss-Seidel solve on the poses; true if within slop
#pragma once

#include <cstdint>

#include "constraints/angle_part.h"
#include "constraints/constraint_bodies.h"
#include "constraints/point_part.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/joint.h"
#include "joints/revolute_joint.h"

namespace pivot {

struct RevoluteConstraint {
    using Storage = RevoluteJoint;

    ConstraintBodies bodies;
    PointPart point;
    AnglePart angle;
    float biasFactor = 0.0f;
    SoftFactors soft;             // SoftStep's (rows.h)
    XpbdRows xpbd;                // XPBD's (xpbd_rows.h)
    std::int32_t jointIndex = 0;  // where the impulses are stored back

    /// Builds the constraint at the island's start-of-step poses, all but its impulses (which
    /// startImpulses takes from the joint). Returns the anchors' separation squared, m^2.
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        load(joint, index, inputs, slots, step);
        return remeasure(poses, step);
    }
    /// The same, with each solver slot's rotation at these poses given (the same values).
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const Rot* rotations,
                  const StepContext& step) {
        load(joint, index, inputs, slots, step);
        return remeasure(poses, rotations, step);
    }

    /// What prepare measures at the poses; alone, at a later substep, the constraint kept from
    /// the one before (its impulses as stored) measured again. Returns the separation squared.
    float remeasure(const SolverPose* poses, const StepContext& step) {
        const Vec2 separation = preparePoint(bodies, point, poses);
        prepareAngle(bodies, angle, poses, step.invDt);
        return lengthSquared(separation);
    }
    /// The same, with each solver slot's rotation at these poses given (the same values).
    float remeasure(const SolverPose* poses, const Rot* rotations, const StepContext& step) {
        const Vec2 separation =
            preparePoint(bodies, point, poses, rotations[bodies.indexA], rotations[bodies.indexB]);
        prepareAngle(bodies, angle, poses, step.invDt);
        return lengthSquared(separation);
    }

    /// Warm starting: impulses scale with the step, so that they keep the force they stand
    /// for when dt changes. Without it, every impulse starts at zero.
    /// The angle's impulses are taken from the joint here, as the point's, where a motor or limit
    /// in use keeps them (prepareAngle's rule), rather than copied in load and scaled here:
    /// copied as two floats and read back as one pair, the limits' impulses stalled the
    /// processor (a store it cannot forward), 15% of the joints' set-up in many_chains.
    void startImpulses(const Joint& joint, bool warmStarting, float dtRatio) {
        if (warmStarting) {
            const RevoluteJoint& revolute = std::get<RevoluteJoint>(joint.data);
            const bool turns = !bodies.fixedRotation();
            point.impulse = dtRatio * revolute.impulse;
            angle.motorImpulse =
                angle.motorEnabled && turns ? dtRatio * revolute.motorImpulse : 0.0f;
            const bool limits = angle.limitEnabled && turns;
            angle.lowerImpulse = limits ? dtRatio * revolute.lowerImpulse : 0.0f;
            angle.upperImpulse = limits ? dtRatio * revolute.upperImpulse : 0.0f;
        } else {
            angle.motorImpulse = 0.0f;
            angle.lowerImpulse = 0.0f;
            angle.upperImpulse = 0.0f;
        }
    }

    /// A let-go joint's constraint: its bodies' masses are taken as zero, so every solve of it
    /// applies a zero impulse.
    void makeInert() {
        *this = RevoluteConstraint{bodies,        PointPart{}, AnglePart{}, 0.0f,
                                   SoftFactors{}, XpbdRows{},  jointIndex};
        bodies.mA = bodies.mB = bodies.iA = bodies.iB = 0.0f;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        RevoluteJoint& revolute = std::get<RevoluteJoint>(joint.data);
        revolute.impulse = point.impulse;
        revolute.motorImpulse = angle.motorImpulse;
        revolute.lowerImpulse = angle.lowerImpulse;
        revolute.upperImpulse = angle.upperImpulse;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const {
        const ConstraintBodies& b = bodies;
        SolverVelocity& A = velocities[b.indexA];
        SolverVelocity& B = velocities[b.indexB];
        Vec2 P = point.impulse;
        float axial = angle.axialImpulse();
        A.v -= b.mA * P;
        A.w -= b.iA * (cross(point.rA, P) + axial);
        B.v += b.mB * P;
        B.w += b.iB * (cross(point.rB, P) + axial);
    }

    /// Motor, limits, then the pin: it gets the last word, because a joint that comes apart is
    /// worse than one that turns a little too far.
    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        const Vec2 bias = rows != Rows::Rigid ? point.bias : Vec2{};
        solveAngleVelocity<true, rows>(bodies, angle, velocities, soft);
        if constexpr (rows != Rows::None) {
            point.impulse += solvePointVelocity<rows>(bodies, point, velocities, bias, soft);
        }
    }

    void setBias(const SolverPose* poses, float k) {
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        Vec2 C = B.c + point.rB - A.c - point.rA;
        point.bias = k * C;
        setLimitBias(angle, k);
    }

    void restartAt(const SolverPose* poses, float invH) {
        preparePoint(bodies, point, poses);
        angle.angle = jointAngle(angle, poses, bodies);
        angle.lowerImpulse = 0.0f;
        angle.upperImpulse = 0.0f;
        setLimitTerms(angle, invH);
    }

    void solvePseudoVelocity(SolverVelocity* pseudo) {
        solveAngleVelocity<false>(bodies, angle, pseudo);
        solvePointVelocity(bodies, point, pseudo, point.bias);
    }

    void freezeMass(const SolverPose* poses) { preparePoint(bodies, point, poses); }

    /// XPBD: the limits, then the pin, each re-measured (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        xpbdLimits(bodies, angle, poses, xpbd.alphaTilde, &xpbd.lambda[1]);
        xpbdPoint(bodies, point.localRA, point.localRB, poses, xpbd.alphaTilde, xpbd.lambda[0],
                  xpbd.point);
    }
    /// After the XPBD sweeps: the impulses they applied, added to the velocity rows' as the
    /// reactions.
    void takeXpbdReactions(float invH) {
        point.impulse += invH * xpbd.point;
        angle.lowerImpulse += invH * xpbd.lambda[1];
        angle.upperImpulse += invH * xpbd.lambda[2];
    }

    /// The limit, then the pin. Within slop means both were, as measured before their
    /// corrections (|C| <= kLinearSlop, limit error <= kAngularSlop).
    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        float angularError = solveLimitPosition(bodies, angle, poses, biasFactor);
        float linearError = solvePointPosition<rebuildMass>(bodies, point, poses, biasFactor);
        return linearError <= kLinearSlop && angularError <= kAngularSlop;
    }

private:
    // What prepare takes from the joint and its bodies, before anything is measured at the poses.
    void load(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
              const JointSlots& slots, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const RevoluteJoint& revolute = std::get<RevoluteJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        point.localRA = joint.localAnchorA - a.localCenter;
        point.localRB = joint.localAnchorB - b.localCenter;
        angle.referenceAngle = joint.referenceAngle;
        angle.limitEnabled = revolute.enableLimit;
        angle.lower = revolute.lowerAngle;
        angle.upper = revolute.upperAngle;
        angle.motorEnabled = revolute.enableMotor;
        angle.motorSpeed = revolute.motorSpeed;
        angle.maxMotorImpulse = step.dt * revolute.maxMotorTorque;
        // The impulses: startImpulses (or makeInert) sets them.
    }
};

}  // namespace pivot
