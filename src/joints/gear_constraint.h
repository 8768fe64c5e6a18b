// The gear joint as the solver sees it for one step: one scalar constraint on four bodies.
//
// Each joint the gear couples (a side, s = 1, 2) has a base body (its body A: the gear's C for
// joint1, D for joint2) and a moving body (its body B: the gear's A and B), and a coordinate
//   revolute:   q = aMover - aBase - referenceAngle
//   prismatic:  q = ((cMover + rMover) - (cBase + rBase)) . u,      u = R(aBase) localAxis
// The gear holds
//   C = q1 + ratio q2 - constant,
// so with the scale k = 1 for side 1 and k = ratio for side 2, side s adds to dC/dt
//   revolute:   k (wMover - wBase)
//   prismatic:  k (u . (vMover - vBase) + (rMover x u) wMover - (dMover x u) wBase),
//               dMover = cMover + rMover - cBase (the axis turns with the base),
// that is the Jacobian rows  mover: ( k u, k jM ),  base: ( -k u, -k jB )  with jM = rMover x u
// and jB = dMover x u (revolute: u = 0, jM = jB = 1), and
//   K = sum over the sides of k^2 (mMover + mBase) + iMover (k jM)^2 + iBase (k jB)^2
// (revolute: k^2 (iMover + iBase)), plus, for a body that is on both sides (joint2 hangs from
// joint1's moving body, or both joints from one base), the cross term 2 (m Jv . Jv' + i Jw Jw')
// of its two rows. An impulse lambda changes each body's velocity by M^-1 J^T lambda, row by
// row, each in place, so a body on both sides receives both rows.
//
// The operations follow Box2D 2.4.1's gear in its order, so that with bases that never move (a
// static ground) the two agree bit for bit. Where bases move, two terms differ from Box2D's:
// jB includes the turn of the axis (Box2D's uses rBase x u, which is exact only while the base
// does not turn), and K has the cross terms of a shared body (Box2D's omits them). Box2D's
// position solve reports every gear as within slop; this one reports |C| <= kAngularSlop when
// joint1 is revolute (C is then an angle) and |C| <= kLinearSlop when it is prismatic.
#pragma once

#include <cmath>
#include <cstdint>

#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/gear_joint.h"
#include "joints/joint.h"
#include "pivot/constants.h"

namespace pivot {

struct GearConstraint {
    using Storage = GearJoint;

    // Bodies 0 and 1 are the moving bodies of sides 1 and 2 (the gear's A and B), 2 and 3
    // their bases (C and D): side s moves body s and pushes body 2 + s.
    JointSlots index{};
    float m[4] = {};  // inverse masses
    float i[4] = {};  // inverse rotational inertias
    struct Side {
        bool prismatic = false;
        float scale = 1.0f;  // k
        float referenceAngle = 0.0f;
        Vec2 localAxis;
        Vec2 localRMover;  // anchors relative to the centres of mass, in the bodies' frames
        Vec2 localRBase;
    };
    /// The Jacobian and K at some poses.
    struct Jacobian {
        Vec2 jv[2];  // k u of each side
        float jwMover[2] = {};
        float jwBase[2] = {};
        float k = 0.0f;  // K
        float mass() const { return k > 0.0f ? 1.0f / k : 0.0f; }
    };
    Side side[2];
    Jacobian jacobian;  // when last measured
    float ratio = 1.0f;
    float constant = 0.0f;
    float mass = 0.0f;  // 1 / K when last measured (0 when K is)
    float impulse = 0.0f;
    float bias = 0.0f;
    float biasFactor = 0.0f;
    float slop = kLinearSlop;
    SoftFactors soft;  // SoftStep's (constraints/rows.h)
    XpbdRows xpbd;     // XPBD's (constraints/xpbd_rows.h)
    std::int32_t jointIndex = 0;

    /// Builds the constraint at the island's start-of-step poses, with the stored impulse.
    /// Returns C^2.
    float prepare(const Joint& joint, std::int32_t jointAt, const SolverBodyInputs* inputs,
                  const JointSlots& slots, const SolverPose* poses, const StepContext&) {
        const GearJoint& gear = std::get<GearJoint>(joint.data);
        jointIndex = jointAt;
        biasFactor = joint.biasFactor();
        index = slots;
        // Slots 2 and 3 are the bases (island_builder.cpp: Joint::extraBodies, in side order).
        const SolverBodyInputs* bodies[4] = {&inputs[slots[0]], &inputs[slots[1]],
                                             &inputs[slots[2]], &inputs[slots[3]]};
        for (int n = 0; n < 4; ++n) {
            m[n] = bodies[n]->invMass;
            i[n] = bodies[n]->invInertia;
        }
        const GearSide* stored[2] = {&gear.side1, &gear.side2};
        for (int s = 0; s < 2; ++s) {
            Side& sd = side[s];
            sd.prismatic = stored[s]->prismatic;
            sd.scale = s == 0 ? 1.0f : gear.ratio;
            sd.referenceAngle = stored[s]->referenceAngle;
            sd.localAxis = stored[s]->localAxis;
            sd.localRMover = stored[s]->localAnchorMover - bodies[s]->localCenter;
            sd.localRBase = stored[s]->localAnchorBase - bodies[2 + s]->localCenter;
        }
        ratio = gear.ratio;
        constant = gear.constant;
        impulse = gear.impulse;
        slop = gear.side1.prismatic ? kLinearSlop : kAngularSlop;
        const float C = measure(poses);
        return C * C;
    }

    /// A later substep: the constraint kept from the one before, its impulses as stored, is
    /// measured again at the current poses (the same operations as in prepare).
    void remeasure(const SolverPose* poses, const StepContext&) { measure(poses); }

    void startImpulses(const Joint&, bool warmStarting, float dtRatio) {
        impulse = warmStarting ? impulse * dtRatio : 0.0f;
    }

    void makeInert() {
        for (int n = 0; n < 4; ++n) m[n] = i[n] = 0.0f;
        impulse = bias = 0.0f;
        jacobian = Jacobian{};
        mass = 0.0f;
    }

    void storeImpulses(Joint& joint, float invDt) const {
        GearJoint& gear = std::get<GearJoint>(joint.data);
        gear.impulse = impulse;
        gear.linearB = jacobian.jv[1];
        gear.angularB = jacobian.jwMover[1];
        joint.impulseInvDt = invDt;
    }

    void warmStart(SolverVelocity* velocities) const { apply(velocities, impulse); }

    template <Rows rows>
    void solveVelocity(SolverVelocity* velocities) {
        if constexpr (rows != Rows::None) {
            impulse += solveRow<rows>(velocities, rows != Rows::Rigid ? bias : 0.0f);
        }
    }

    /// XPBD on the coupling, re-measured (xpbd_rows.h).
    void solveCompliant(SolverPose* poses) {
        Jacobian now;
        const float C = measure(poses, now);
        applyToPoses(now, poses, xpbdDelta(C, now.k, xpbd.alphaTilde, xpbd.lambda[0]));
    }
    /// After the XPBD sweeps: the impulse they applied, added to the velocity row's as the
    /// reaction.
    void takeXpbdReactions(float invH) { impulse += invH * xpbd.lambda[0]; }

    /// factor C at these poses (C depends on the coordinates only, not on the rows).
    void setBias(const SolverPose* poses, float factor) { bias = factor * error(poses); }

    void restartAt(const SolverPose* poses, float) { measure(poses); }

    void solvePseudoVelocity(SolverVelocity* pseudo) { solveRow(pseudo, bias); }

    void freezeMass(const SolverPose* poses) { measure(poses); }

    /// One nonlinear Gauss-Seidel solve: re-measure the rows and C, and move the bodies by
    /// -beta C / K, with K of these poses (rebuildMass) or as frozen.
    template <bool rebuildMass>
    bool solvePosition(SolverPose* poses) const {
        Jacobian now;
        const float C = measure(poses, now);
        const float K = rebuildMass ? now.k : jacobian.k;
        const float lambda = K > 0.0f ? -(biasFactor * C) / K : 0.0f;
        applyToPoses(now, poses, lambda);
        return std::fabs(C) <= slop;
    }

private:
    /// The coordinate of side s at these poses.
    float coordinate(const Side& sd, const SolverPose& mover, const SolverPose& base) const {
        if (!sd.prismatic) return mover.a - base.a - sd.referenceAngle;
        const Vec2 rMover = rotate(Rot(mover.a), sd.localRMover);
        const Vec2 offset = inverseRotate(Rot(base.a), rMover + (mover.c - base.c));
        return dot(offset - sd.localRBase, sd.localAxis);
    }

    float error(const SolverPose* poses) const {
        const float q1 = coordinate(side[0], poses[index[0]], poses[index[2]]);
        const float q2 = coordinate(side[1], poses[index[1]], poses[index[3]]);
        return (q1 + ratio * q2) - constant;
    }

    /// The rows and K at these poses, into `out`; returns C.
    float measure(const SolverPose* poses, Jacobian& out) const {
        float K = 0.0f;
        for (int s = 0; s < 2; ++s) {
            const Side& sd = side[s];
            const SolverPose& mover = poses[index[s]];
            const SolverPose& base = poses[index[2 + s]];
            const float mM = m[s], mB = m[2 + s], iM = i[s], iB = i[2 + s];
            if (!sd.prismatic) {
                out.jv[s] = Vec2{};
                out.jwMover[s] = sd.scale;
                out.jwBase[s] = sd.scale;
                K += sd.scale * sd.scale * (iM + iB);
                continue;
            }
            const Vec2 u = rotate(Rot(base.a), sd.localAxis);
            const Vec2 rMover = rotate(Rot(mover.a), sd.localRMover);
            out.jv[s] = sd.scale * u;
            out.jwBase[s] = sd.scale * cross(rMover + (mover.c - base.c), u);
            out.jwMover[s] = sd.scale * cross(rMover, u);
            K += sd.scale * sd.scale * (mB + mM) + iB * out.jwBase[s] * out.jwBase[s] +
                 iM * out.jwMover[s] * out.jwMover[s];
        }
        out.k = K + sharedBodyTerms(out);
        return error(poses);
    }

    /// Measures and keeps the rows; returns C.
    float measure(const SolverPose* poses) {
        const float C = measure(poses, jacobian);
        mass = jacobian.mass();
        return C;
    }

    /// The cross terms of K for a body on both sides (see the top of the file); 0 when none.
    float sharedBodyTerms(const Jacobian& r) const {
        float terms = 0.0f;
        const auto moves = [&](int n) { return m[n] != 0.0f || i[n] != 0.0f; };
        if (index[0] == index[3] && moves(0)) {  // joint2 hangs from joint1's moving body
            terms -= 2.0f * (m[0] * dot(r.jv[0], r.jv[1]) + i[0] * r.jwMover[0] * r.jwBase[1]);
        }
        if (index[1] == index[2] && moves(1)) {  // joint1 hangs from joint2's moving body
            terms -= 2.0f * (m[1] * dot(r.jv[1], r.jv[0]) + i[1] * r.jwMover[1] * r.jwBase[0]);
        }
        if (index[2] == index[3] && moves(2)) {  // both joints hang from one body
            terms += 2.0f * (m[2] * dot(r.jv[0], r.jv[1]) + i[2] * r.jwBase[0] * r.jwBase[1]);
        }
        return terms;
    }

    float speed(const SolverVelocity* v) const {
        const SolverVelocity& A = v[index[0]];
        const SolverVelocity& B = v[index[1]];
        const SolverVelocity& C = v[index[2]];
        const SolverVelocity& D = v[index[3]];
        const float linear = dot(jacobian.jv[0], A.v - C.v) + dot(jacobian.jv[1], B.v - D.v);
        return linear + ((jacobian.jwMover[0] * A.w - jacobian.jwBase[0] * C.w) +
                         (jacobian.jwMover[1] * B.w - jacobian.jwBase[1] * D.w));
    }

    void apply(SolverVelocity* v, float lambda) const {
        v[index[0]].v += (m[0] * lambda) * jacobian.jv[0];
        v[index[0]].w += i[0] * lambda * jacobian.jwMover[0];
        v[index[1]].v += (m[1] * lambda) * jacobian.jv[1];
        v[index[1]].w += i[1] * lambda * jacobian.jwMover[1];
        v[index[2]].v -= (m[2] * lambda) * jacobian.jv[0];
        v[index[2]].w -= i[2] * lambda * jacobian.jwBase[0];
        v[index[3]].v -= (m[3] * lambda) * jacobian.jv[1];
        v[index[3]].w -= i[3] * lambda * jacobian.jwBase[1];
    }

    void applyToPoses(const Jacobian& r, SolverPose* p, float lambda) const {
        p[index[0]].c += m[0] * lambda * r.jv[0];
        p[index[0]].a += i[0] * lambda * r.jwMover[0];
        p[index[1]].c += m[1] * lambda * r.jv[1];
        p[index[1]].a += i[1] * lambda * r.jwMover[1];
        p[index[2]].c -= m[2] * lambda * r.jv[0];
        p[index[2]].a -= i[2] * lambda * r.jwBase[0];
        p[index[3]].c -= m[3] * lambda * r.jv[1];
        p[index[3]].a -= i[3] * lambda * r.jwBase[1];
    }

    template <Rows rows = Rows::Biased>
    float solveRow(SolverVelocity* velocities, float b) {
        const float lambda = soften<rows>(-mass * (speed(velocities) + b), impulse, soft);
        apply(velocities, lambda);
        return lambda;
    }
};

}  // namespace pivot
