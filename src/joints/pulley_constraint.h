// The pulley joint as the solver sees it for one step: its two bodies and the pulley part
// (constraints/pulley_part.h has the maths). It offers the strategies the same operations as
// every joint constraint (revolute_constraint.h lists them).
#pragma once

#include <cstdint>

#include "constraints/constraint_bodies.h"
#include "constraints/pulley_part.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/joint.h"
#include "joints/pulley_joint.h"

namespace pivot {

struct PulleyConstraint {
    using Storage = PulleyJoint;

    ConstraintBodies bodies;
    PulleyPart part;
    float impulse = 0.0f;  // accumulated
    float bias = 0.0f;     // velocity bias (Baumgarte, the pseudo-velocity pass)
    float biasFactor = 0.0f;
    SoftFactors soft;  // SoftStep's (constraints/rows.h)
    XpbdRows xpbd;     // XPBD's (constraints/xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the stored impulse.
    /// Returns the joint's separation squared, C^2.
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext&) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const PulleyJoint& p = std::get<PulleyJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        part.localRA = joint.localAnchorA - a.localCenter;
        part.localRB = joint.localAnchorB - b.localCenter;
        part.groundA = p.groundAnchorA;
        part.groundB = p.groundAnchorB;
        part.ratio = p.ratio;
        part.constant = p.constant();
        impulse = p.impulse;
        const float C = preparePulley(bodies, part, poses);
        return C * C;
    }

    /// A later substep: the constraint kept from the one before, its impulses as stored, is
    /// measured again at the current poses (the same operations as in prepare).
    void remeasure(const SolverPose* poses, const StepContext&) {
        preparePulley(bodies, part, poses);
    }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        impulse = warmStarting ? impulse * dtRatio : 0.0f;
    }

    void makeInert() {
        PulleyConstraint inert;
        inert.bodies = bodies;
        inert.bodies.mA = inert.bodies.mB = inert.bodies.iA = inert.bodies.iB = 0.0f;
        inert.jointIndex = jointIndex;
        *this = inert;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        PulleyJoint& p = std::get<PulleyJoint>(joint.data);
        p.impulse = impulse;
        p.axisB = part.uB;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const {
        applyPulleyImpulse(bodies, part, velocities, impulse);
    }

    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if constexpr (rows != Rows::None) {
            impulse += solveRow<rows>(velocities, rows != Rows::Rigid ? bias : 0.0f);
        }
    }

    /// XPBD on the rope's length, re-measured (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        const PulleyMeasure m = measurePulley(bodies, part, poses);
        const float mass = pulleyMass(bodies, part, m);
        const float C = part.constant - m.lengthA - part.ratio * m.lengthB;
        const float lambda =
            mass > 0.0f ? xpbdDelta(C, 1.0f / mass, xpbd.alphaTilde, xpbd.lambda[0]) : 0.0f;
        movePulley(bodies, part, m, poses, lambda);
    }
    /// After the XPBD sweeps: the impulse they applied, added to the velocity row's as the
    /// reaction.
    void takeXpbdReactions(float invH) { impulse += invH * xpbd.lambda[0]; }

    void setBias(const SolverPose* poses, float k) {
        // At the radius vectors and directions last measured, as the other joints' biases.
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        const float lengthA = length(A.c + part.rA - part.groundA);
        const float lengthB = length(B.c + part.rB - part.groundB);
        bias = k * (part.constant - lengthA - part.ratio * lengthB);
    }

    void restartAt(const SolverPose* poses, float) { preparePulley(bodies, part, poses); }

    void solvePseudoVelocity(SolverVelocity* pseudo) { solveRow(pseudo, bias); }

    void freezeMass(const SolverPose* poses) { preparePulley(bodies, part, poses); }

    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        return solvePulleyPosition<rebuildMass>(bodies, part, poses, biasFactor) <= kLinearSlop;
    }

private:
    template <Rows rows = Rows::Biased>
    float solveRow(SolverVelocity* velocities, float b) {
        const float cdot = pulleySpeed(part, velocities[bodies.indexA], velocities[bodies.indexB]);
        const float lambda = soften<rows>(-part.mass * (cdot + b), impulse, soft);
        applyPulleyImpulse(bodies, part, velocities, lambda);
        return lambda;
    }
};

}  // namespace pivot
