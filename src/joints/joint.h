// Joint storage: what persists between steps for every joint, whatever its type. The fields all
// types share are here; each type's own settings and accumulated impulses are its alternative of
// `data` (revolute_joint.h, distance_joint.h, pulley_joint.h, velocity_joints.h,
// prismatic_joint.h, weld_joint.h, wheel_joint.h, gear_joint.h), in the order of
// joints/joint_types.h and of the public JointType. The per-step solver state lives in each
// type's constraint, built afresh for each island each step.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "core/slot_pool.h"
#include "joints/distance_joint.h"
#include "joints/gear_joint.h"
#include "joints/prismatic_joint.h"
#include "joints/pulley_joint.h"
#include "joints/revolute_joint.h"
#include "joints/velocity_joints.h"
#include "joints/weld_joint.h"
#include "joints/wheel_joint.h"
#include "model/body.h"
#include "model/body_edge.h"
#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

using JointData = std::variant<RevoluteJoint, DistanceJoint, PulleyJoint, FrictionJoint, MotorJoint,
                               PrismaticJoint, WeldJoint, WheelJoint, GearJoint>;

struct Joint {
    // edges[0].body is body A, edges[1].body is body B. A gear also acts on two more bodies
    // (extraBodies), which do not list it: it is reached through A and B.
    BodyEdge edges[2];
    Vec2 localAnchorA;  // origin-relative, in body A's frame
    Vec2 localAnchorB;
    float referenceAngle = 0.0f;  // rad, angleB - angleA when the joint angle is zero
    PositionSolver solver = PositionSolver::FullNGS;
    bool hasBiasOverride = false;
    float biasOverride = 0.0f;
    std::int32_t extraPositionIterations = 0;  // NGS sweeps beyond the world's, [0, kMaxIterations]
    JointSoftness softness;  // SoftStep's
    bool collideConnected = false;
    std::uint64_t userData = 0;
    JointData data;
    float impulseInvDt = 0.0f;  // 1/dt of the last step solved: impulse * impulseInvDt is a force
    // Let go (World::isJointLetGo): no longer solved until rearmed. The reason and separation
    // are those of the step that let it go.
    bool letGo = false;
    JointLetGoReason letGoReason = JointLetGoReason::Separation;
    float letGoAt = 0.0f;           // m, the separation then
    float letGoReaction = 0.0f;     // N or N m, the force or torque that broke it (Force, Torque)
    float breakForce = 0.0f;        // N; 0: never (the def's breakForce)
    float breakTorque = 0.0f;       // N m; 0: never
    // A breakable joint's reaction force and torque summed over the substeps of the step being
    // solved: the break thresholds compare their mean, the force over the step. Scratch within
    // one step (set at its first substep), so no snapshot or hash needs it.
    Vec2 stepForceSum;
    float stepTorqueSum = 0.0f;
    bool hasLetGoOverride = false;  // letGoOverride replaces WorldDef::jointLetGoSeparation
    float letGoOverride = 0.0f;     // m; 0: never
    std::int32_t gearCount = 0;     // gear joints built on this one (destroyed before it)

    std::int32_t bodyA() const { return edges[0].body; }
    std::int32_t bodyB() const { return edges[1].body; }
    /// The bodies the joint acts on besides A and B, -1 for none: a gear's C and D (the bodies
    /// its two joints hang from).
    std::array<std::int32_t, 2> extraBodies() const {
        if (const auto* gear = std::get_if<GearJoint>(&data)) {
            return {gear->side1.base, gear->side2.base};
        }
        return {-1, -1};
    }
    /// The position in joints/joint_types.h's list.
    int typeIndex() const { return static_cast<int>(data.index()); }
    float biasFactor() const { return hasBiasOverride ? biasOverride : defaultBiasFactor(solver); }
    /// m, beyond which the joint is let go; 0: never.
    float letGoSeparation(float worldSetting) const {
        return hasLetGoOverride ? letGoOverride : worldSetting;
    }
    JointType type() const { return static_cast<JointType>(data.index()); }
    /// Friction and motor joints act in the velocity phase only: no position error, no strategy.
    bool isVelocityOnly() const {
        return std::holds_alternative<FrictionJoint>(data) ||
               std::holds_alternative<MotorJoint>(data);
    }
    /// m, |anchorB - anchorA| with the bodies at these transforms.
    float anchorDistance(const Transform& xfA, const Transform& xfB) const {
        return distance(transformPoint(xfA, localAnchorA), transformPoint(xfB, localAnchorB));
    }
    /// m (a gear's: in its joint1's units), how far the joint is from what it allows with its
    /// bodies where they are.
    float separation(const SlotPool<Body>& bodies) const {
        const Body& a = bodies[bodyA()];
        const Body& b = bodies[bodyB()];
        const Vec2 pA = transformPoint(a.xf, localAnchorA);
        const Vec2 pB = transformPoint(b.xf, localAnchorB);
        return std::visit(
            [&](const auto& d) {
                if constexpr (std::is_same_v<std::decay_t<decltype(d)>, GearJoint>) {
                    return std::fabs(d.error(a, b, bodies[d.side1.base], bodies[d.side2.base]));
                } else {
                    return d.separation(a.xf.q, pA, pB);
                }
            },
            data);
    }
    /// Whether the stored impulses, and the forces and torques they stand for (impulse / dt),
    /// are all finite: what the reaction queries report must be. D is the joint's type (the
    /// solver knows it: no dispatch on the variant).
    template <typename D>
    bool hasFiniteReactionsAs() const {
        return std::get<D>(data).hasFiniteReactions(impulseInvDt);
    }
    /// N and N m: the force and torque the stored impulses applied to body B (impulse / dt).
    Vec2 reactionForce() const;
    float reactionTorque() const;
    /// Lets the joint go: it keeps no impulse and is not solved until rearmed.
    void letGoFor(JointLetGoReason reason, float separation, float reaction = 0.0f) {
        letGo = true;
        letGoReason = reason;
        letGoAt = separation;
        letGoReaction = reaction;
        std::visit([](auto& d) { d.clearImpulses(); }, data);
    }
};

}  // namespace pivot
