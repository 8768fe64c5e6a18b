// The velocity-only joints as the solver sees them for one step (storage and purpose in
// velocity_joints.h). Each is a point part (2x2: the anchors' relative velocity) and an angle
// row, both clamped by the joint's maximum force and torque.
//
//   angular: Cdot = wB - wA (+ the motor's correction), lambda clamped to +-h maxTorque
//   linear:  Cdot = vB + wB x rB - vA - wA x rA (+ the motor's correction),
//            P = -K^-1 Cdot accumulated and clamped to |P| <= h maxForce
// with the motor's correction beta / h times its position error, beta its correction factor:
//   linear error  = cB + rB - cA - rA   (rA: to the offset, in A's frame; rB: to B's origin)
//   angular error = aB - aA - angularOffset
// Every strategy hook that concerns a position error does nothing: there is none. The float
// operations are those of Box2D 2.4.1's friction and motor joints, in their order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "constraints/constraint_bodies.h"
#include "constraints/point_part.h"
#include "constraints/rows.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/joint.h"
#include "joints/velocity_joints.h"

namespace pivot {

/// What the friction and motor constraints share: the bodies, the radius vectors, the masses,
/// the clamped impulses and every no-op strategy hook.
struct ClampedVelocityRows {
    /// No position rows: what a strategy does to those (relax them, leave them out of the warm
    /// start) does not apply, so these joints solve the same under every strategy.
    static constexpr bool kVelocityOnly = true;

    ConstraintBodies bodies;
    Vec2 rA;
    Vec2 rB;
    Mat22 linearMass;
    float angularMass = 0.0f;
    Vec2 linearImpulse;
    float angularImpulse = 0.0f;
    float maxLinear = 0.0f;   // h maxForce
    float maxAngular = 0.0f;  // h maxTorque
    bool correcting = false;  // the motor's rows drive out its position error; friction's do not
    Vec2 linearBias;          // the motor's correction velocity
    float angularBias = 0.0f;
    float biasFactor = 0.0f;
    SoftFactors soft;  // unused: no position rows
    XpbdRows xpbd;     // unused likewise
    std::int32_t jointIndex = 0;

    void setMasses() {
        const ConstraintBodies& b = bodies;
        Mat22 K;
        K.cx.x = b.mA + b.mB + b.iA * rA.y * rA.y + b.iB * rB.y * rB.y;
        K.cx.y = -b.iA * rA.x * rA.y - b.iB * rB.x * rB.y;
        K.cy.x = K.cx.y;
        K.cy.y = b.mA + b.mB + b.iA * rA.x * rA.x + b.iB * rB.x * rB.x;
        linearMass = K.inverse();
        angularMass = b.iA + b.iB;
        if (angularMass > 0.0f) angularMass = 1.0f / angularMass;
    }

    void startImpulses(bool warmStarting, float dtRatio) {
        if (warmStarting) {
            linearImpulse *= dtRatio;
            angularImpulse *= dtRatio;
        } else {
            linearImpulse = Vec2{};
            angularImpulse = 0.0f;
        }
    }

    void warmStart(SolverVelocity* velocities) const {
        const ConstraintBodies& b = bodies;
        SolverVelocity& A = velocities[b.indexA];
        SolverVelocity& B = velocities[b.indexB];
        const Vec2 P = linearImpulse;
        A.v -= b.mA * P;
        A.w -= b.iA * (cross(rA, P) + angularImpulse);
        B.v += b.mB * P;
        B.w += b.iB * (cross(rB, P) + angularImpulse);
    }

    /// The angle row, then the point rows, each clamped.
    template <Rows>
    void solveVelocity(SolverVelocity* velocities) {
        const ConstraintBodies& b = bodies;
        SolverVelocity& A = velocities[b.indexA];
        SolverVelocity& B = velocities[b.indexB];
        {
            float cdot = B.w - A.w;
            if (correcting) cdot += angularBias;
            float impulse = -angularMass * cdot;
            const float old = angularImpulse;
            angularImpulse = std::clamp(old + impulse, -maxAngular, maxAngular);
            impulse = angularImpulse - old;
            A.w -= b.iA * impulse;
            B.w += b.iB * impulse;
        }
        {
            Vec2 cdot = B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
            if (correcting) cdot += linearBias;
            Vec2 impulse = -(linearMass * cdot);
            const Vec2 old = linearImpulse;
            linearImpulse += impulse;
            if (lengthSquared(linearImpulse) > maxLinear * maxLinear) {
                // Scaled back onto the circle of the largest impulse (a zero-length impulse
                // cannot be over it).
                const float invLength = 1.0f / length(linearImpulse);
                linearImpulse = maxLinear * (invLength * linearImpulse);
            }
            impulse = linearImpulse - old;
            A.v -= b.mA * impulse;
            A.w -= b.iA * cross(rA, impulse);
            B.v += b.mB * impulse;
            B.w += b.iB * cross(rB, impulse);
        }
    }

    void makeInert() {
        linearImpulse = Vec2{};
        angularImpulse = 0.0f;
        maxLinear = maxAngular = 0.0f;
        bodies.mA = bodies.mB = bodies.iA = bodies.iB = 0.0f;
    }

    // No position error: the strategies' position hooks have nothing to act on.
    void setBias(const SolverPose*, float) {}
    void restartAt(const SolverPose*, float) {}
    void solvePseudoVelocity(SolverVelocity*) {}
    void freezeMass(const SolverPose*) {}
    void solveCompliant(SolverPose*) {}
    void takeXpbdReactions(float) {}
    template <bool>
    bool solvePosition(SolverPose*) const {
        return true;
    }

protected:
    void prepareBodies(std::int32_t index, const Joint& joint, const SolverBodyInputs& a,
                       const SolverBodyInputs& b, const JointSlots& slots) {
        jointIndex = index;
        biasFactor = joint.biasFactor();
        bodies = constraintBodies(slots, a, b);
    }
};

struct FrictionConstraint : ClampedVelocityRows {
    using Storage = FrictionJoint;

    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const FrictionJoint& f = std::get<FrictionJoint>(joint.data);
        prepareBodies(index, joint, a, b, slots);
        rA = rotate(Rot(poses[bodies.indexA].a), joint.localAnchorA - a.localCenter);
        rB = rotate(Rot(poses[bodies.indexB].a), joint.localAnchorB - b.localCenter);
        setMasses();
        linearImpulse = f.linearImpulse;
        angularImpulse = f.angularImpulse;
        maxLinear = step.dt * f.maxForce;
        maxAngular = step.dt * f.maxTorque;
        return 0.0f;
    }
    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        ClampedVelocityRows::startImpulses(warmStarting, dtRatio);
    }
    void storeImpulses(Joint& joint, float invDt) const {
        FrictionJoint& f = std::get<FrictionJoint>(joint.data);
        f.linearImpulse = linearImpulse;
        f.angularImpulse = angularImpulse;
        joint.impulseInvDt = invDt;
    }
};

struct MotorConstraint : ClampedVelocityRows {
    using Storage = MotorJoint;

    float prepare(const Joint& joint, std::int32_t index, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext& step) {
        const SolverBodyInputs& a = inputs[slots[0]];
        const SolverBodyInputs& b = inputs[slots[1]];
        const MotorJoint& m = std::get<MotorJoint>(joint.data);
        prepareBodies(index, joint, a, b, slots);
        const SolverPose& A = poses[bodies.indexA];
        const SolverPose& B = poses[bodies.indexB];
        const Rot qA(A.a), qB(B.a);
        // The anchor on A is the offset, the one on B its origin.
        rA = rotate(qA, m.linearOffset - a.localCenter);
        rB = rotate(qB, -b.localCenter);
        setMasses();
        const Vec2 linearError = B.c + rB - A.c - rA;
        const float angularError = B.a - A.a - m.angularOffset;
        linearImpulse = m.linearImpulse;
        angularImpulse = m.angularImpulse;
        maxLinear = step.dt * m.maxForce;
        maxAngular = step.dt * m.maxTorque;
        correcting = true;
        linearBias = (step.invDt * m.correctionFactor) * linearError;
        angularBias = step.invDt * m.correctionFactor * angularError;
        return 0.0f;
    }
    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        ClampedVelocityRows::startImpulses(warmStarting, dtRatio);
    }
    void storeImpulses(Joint& joint, float invDt) const {
        MotorJoint& m = std::get<MotorJoint>(joint.data);
        m.linearImpulse = linearImpulse;
        m.angularImpulse = angularImpulse;
        joint.impulseInvDt = invDt;
    }
};

}  // namespace pivot
