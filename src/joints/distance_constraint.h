// The distance joint as the solver sees it for one step: its two bodies and the length part
// (constraints/length_part.h has the maths), with the rod, rope-limit and spring rows the joint's
// settings ask for. It offers the strategies the same operations as every joint constraint
// (revolute_constraint.h lists them). The rod and the limits are position constraints, corrected
// as the joint's strategy says; the spring is soft and only ever solved in the velocity phase.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "constraints/constraint_bodies.h"
#include "constraints/length_part.h"
#include "constraints/rows.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/distance_joint.h"
#include "joints/joint.h"

namespace pivot {

struct DistanceConstraint {
    using Storage = DistanceJoint;

    ConstraintBodies bodies;
    LengthPart part;
    bool rod = false;  // the rows this joint solves (DistanceJoint::isRod, isRope, enableSpring)
    bool limited = false;
    bool spring = false;
    float rodLength = 0.0f;
    float minLength = 0.0f;
    float maxLength = 0.0f;
    float impulse = 0.0f;  // rod or spring, accumulated
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    float rodBias = 0.0f;  // the rod's velocity bias (Baumgarte, the pseudo-velocity pass)
    // Velocity targets added to the limits' Cdot: the speculative C / h while a limit is not
    // reached, a strategy's bias for an overshot one (rows.h).
    BoundTerm lowerTerm;
    BoundTerm upperTerm;
    float springBias = 0.0f;
    float gamma = 0.0f;
    float softMass = 0.0f;  // 1 / (K + gamma)
    float biasFactor = 0.0f;
    SoftFactors soft;  // SoftStep's (rows.h)
    XpbdRows xpbd;     // XPBD's (xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the joint's impulses as
    /// stored. Returns the joint's separation squared, m^2 (DistanceJoint::separation).
    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const DistanceJoint& d = std::get<DistanceJoint>(joint.data);
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
        part.localRA = joint.localAnchorA - a.localCenter;
        part.localRB = joint.localAnchorB - b.localCenter;
        rod = d.isRod();
        limited = d.isRope();
        spring = d.hasSpring();
        rodLength = d.rodLength();
        minLength = d.minLength;
        maxLength = d.maxLength;
        impulse = d.impulse;
        lowerImpulse = limited ? d.lowerImpulse : 0.0f;
        upperImpulse = limited ? d.upperImpulse : 0.0f;
        prepareLength(bodies, part, poses);
        if (part.u == Vec2{}) impulse = lowerImpulse = upperImpulse = 0.0f;
        setLimitTerms(step.invDt);
        if (spring) prepareSpring(d.hertz, d.dampingRatio, d.length, step.dt);
        const float separation = d.separationAt(part.length);
        return separation * separation;
    }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        if (warmStarting) {
            impulse *= dtRatio;
            lowerImpulse *= dtRatio;
            upperImpulse *= dtRatio;
        } else {
            impulse = lowerImpulse = upperImpulse = 0.0f;
        }
    }

    /// A let-go joint's constraint: no rows, and its bodies' masses taken as zero.
    void makeInert() {
        DistanceConstraint inert;
        inert.bodies = bodies;
        inert.bodies.mA = inert.bodies.mB = inert.bodies.iA = inert.bodies.iB = 0.0f;
        inert.jointIndex = jointIndex;
        *this = inert;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        DistanceJoint& d = std::get<DistanceJoint>(joint.data);
        d.impulse = impulse;
        d.lowerImpulse = lowerImpulse;
        d.upperImpulse = upperImpulse;
        d.axis = part.u;
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const {
        applyLengthImpulse(bodies, part, velocities, impulse + lowerImpulse - upperImpulse);
    }

    /// The spring or the rod, then the limits.
    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if (spring) {
            const float cdot =
                lengthSpeed(part, velocities[bodies.indexA], velocities[bodies.indexB]);
            const float lambda = -softMass * (cdot + springBias + gamma * impulse);
            impulse += lambda;
            applyLengthImpulse(bodies, part, velocities, lambda);
        } else if (rod) {
            if constexpr (rows != Rows::None) {
                impulse += solveRod<rows>(velocities, rows != Rows::Rigid ? rodBias : 0.0f);
            }
        }
        if constexpr (rows != Rows::None) {
            if (limited) solveLimits<rows>(velocities);
        }
    }

    /// XPBD: the rod, or the rope's bounds, re-measured (xpbd_rows.h). The spring is its own.
    void solveCompliant(SolverPose* poses) {
        if (rod) {
            moveAlong(
                poses, [&](float L) { return L - rodLength; }, false, xpbd.lambda[0]);
        } else if (limited) {
            moveAlong(
                poses, [&](float L) { return L - minLength; }, true, xpbd.lambda[0]);
            // C = max - L >= 0: the bound pulls along -u.
            moveAlong(
                poses, [&](float L) { return maxLength - L; }, true, xpbd.lambda[1], -1.0f);
        }
    }
    /// After the XPBD sweeps: the impulses they applied, added to the velocity rows' as the
    /// reactions (the spring's are its own).
    void takeXpbdReactions(float invH) {
        if (rod) impulse += invH * xpbd.lambda[0];
        if (limited) {
            lowerImpulse += invH * xpbd.lambda[0];
            upperImpulse += invH * xpbd.lambda[1];
        }
    }

    void setBias(const SolverPose* poses, float k) {
        const float L = currentLength(poses);
        rodBias = k * (L - rodLength);
        if (limited) {
            const float error = lengthLimitError(L, minLength, maxLength);
            if (L - minLength <= 0.0f) lowerTerm = {k * std::min(error, 0.0f), true};
            if (maxLength - L <= 0.0f) upperTerm = {-k * std::max(error, 0.0f), true};
        }
    }

    void restartAt(const SolverPose* poses, float invH) {
        prepareLength(bodies, part, poses);
        lowerImpulse = upperImpulse = 0.0f;
        setLimitTerms(invH);
    }

    void solvePseudoVelocity(SolverVelocity* pseudo) {
        if (rod) solveRod(pseudo, rodBias);
        if (limited) solveLimits(pseudo);
    }

    void freezeMass(const SolverPose* poses) { prepareLength(bodies, part, poses); }

    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        float error = 0.0f;
        if (rod) {
            const float target = rodLength;
            error = solveLengthPosition<rebuildMass>(bodies, part, poses, biasFactor,
                                                     [&](float L) { return L - target; });
        } else if (limited) {
            const float min = minLength, max = maxLength;
            error = solveLengthPosition<rebuildMass>(bodies, part, poses, biasFactor, [&](float L) {
                return lengthLimitError(L, min, max);
            });
        }
        return error <= kLinearSlop;
    }

private:
    // The length along the direction last measured: with the radius vectors of that pose, as
    // the velocity bias of the revolute pin is measured.
    float currentLength(const SolverPose* poses) const {
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        return length(B.c + part.rB - A.c - part.rA);
    }

    /// One XPBD row on the length: C = error(L), acting along sign * u (only while C < 0 when
    /// `bound`).
    template <typename Error>
    void moveAlong(SolverPose* poses, Error error, bool bound, float& lambda, float sign = 1.0f) {
        const LengthMeasure m = measureLength(bodies, part, poses);
        if (m.u == Vec2{}) return;
        const float C = error(m.length);
        const Vec2 u = sign * m.u;
        const float crA = cross(m.rA, u);
        const float crB = cross(m.rB, u);
        const float w = bodies.mA + bodies.iA * crA * crA + bodies.mB + bodies.iB * crB * crB;
        const float delta = bound ? xpbdLowerBound(C, w, xpbd.alphaTilde, lambda)
                                  : xpbdDelta(C, w, xpbd.alphaTilde, lambda);
        moveAlongLength(bodies, m, poses, delta * u);
    }

    void setLimitTerms(float invH) {
        lowerTerm = BoundTerm::speculative(part.length - minLength, invH);
        upperTerm = BoundTerm::speculative(maxLength - part.length, invH);
    }

    void prepareSpring(float hertz, float dampingRatio, float restLength, float h) {
        const float omega = 2.0f * kPi * hertz;
        const float a1 = 2.0f * dampingRatio + h * omega;
        const float invMass = part.axialMass != 0.0f ? 1.0f / part.axialMass : 0.0f;
        gamma = invMass / (h * omega * a1);
        springBias = omega / a1 * (part.length - restLength);
        softMass = invMass + gamma != 0.0f ? 1.0f / (invMass + gamma) : 0.0f;
        if (!std::isfinite(gamma) || !std::isfinite(softMass) || part.u == Vec2{}) {
            gamma = springBias = softMass = 0.0f;
        }
    }

    template <Rows rows = Rows::Biased>
    float solveRod(SolverVelocity* velocities, float bias) {
        const float cdot = lengthSpeed(part, velocities[bodies.indexA], velocities[bodies.indexB]);
        const float lambda = soften<rows>(-part.axialMass * (cdot + bias), impulse, soft);
        applyLengthImpulse(bodies, part, velocities, lambda);
        return lambda;
    }

    template <Rows rows = Rows::Biased>
    void solveLimits(SolverVelocity* velocities) {
        {
            const float cdot =
                lengthSpeed(part, velocities[bodies.indexA], velocities[bodies.indexB]);
            float lambda = lowerTerm.soften<rows>(
                -part.axialMass * (cdot + lowerTerm.target<rows>()), lowerImpulse, soft);
            const float old = lowerImpulse;
            lowerImpulse = std::max(old + lambda, 0.0f);
            applyLengthImpulse(bodies, part, velocities, lowerImpulse - old);
        }
        {
            const float cdot =
                lengthSpeed(part, velocities[bodies.indexA], velocities[bodies.indexB]);
            float lambda = upperTerm.soften<rows>(
                -part.axialMass * (-cdot + upperTerm.target<rows>()), upperImpulse, soft);
            const float old = upperImpulse;
            upperImpulse = std::max(old + lambda, 0.0f);
            applyLengthImpulse(bodies, part, velocities, -(upperImpulse - old));
        }
    }
};

}  // namespace pivot
