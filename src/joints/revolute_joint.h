// Revolute joint storage: what persists between steps. The per-step solver state lives in
// RevoluteConstraint (revolute_constraint.h), built afresh for each island each step.
#pragma once

#include <cmath>
#include <cstdint>

#include "model/body_edge.h"
#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

struct RevoluteJoint {
    BodyEdge edges[2];  // edges[0].body is body A, edges[1].body is body B
    Vec2 localAnchorA;  // origin-relative, in body A's frame
    Vec2 localAnchorB;
    float referenceAngle = 0.0f;
    PositionSolver solver = PositionSolver::FullNGS;
    bool hasBiasOverride = false;
    float biasOverride = 0.0f;
    bool collideConnected = false;
    // Let go (World::isJointLetGo): no longer solved until rearmed. The reason and separation
    // are those of the step that let it go.
    bool letGo = false;
    JointLetGoReason letGoReason = JointLetGoReason::Separation;
    float letGoAt = 0.0f;           // m, the separation then
    bool hasLetGoOverride = false;  // letGoOverride replaces WorldDef::jointLetGoSeparation
    float letGoOverride = 0.0f;     // m; 0: never
    std::uint64_t userData = 0;
    bool enableLimit = false;
    float lowerAngle = 0.0f;  // rad
    float upperAngle = 0.0f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;      // rad/s
    float maxMotorTorque = 0.0f;  // N m

    // Accumulated impulses of the last step solved (warm starting, reactions).
    Vec2 impulse;               // pin, N s
    float motorImpulse = 0.0f;  // N m s
    float lowerImpulse = 0.0f;
    float upperImpulse = 0.0f;
    float impulseInvDt = 0.0f;  // 1/dt of that step: impulse * impulseInvDt is the force

    std::int32_t bodyA() const { return edges[0].body; }
    std::int32_t bodyB() const { return edges[1].body; }
    float biasFactor() const { return hasBiasOverride ? biasOverride : defaultBiasFactor(solver); }
    /// m, beyond which the joint is let go; 0: never.
    float letGoSeparation(float worldSetting) const {
        return hasLetGoOverride ? letGoOverride : worldSetting;
    }
    /// Whether the stored impulses, and the force and torques they stand for (impulse / dt),
    /// are all finite: what jointReactionForce and jointReactionTorque report must be.
    bool hasFiniteReactions() const {
        const float angular = motorImpulse + lowerImpulse - upperImpulse;
        return isFinite(impulseInvDt * impulse) && std::isfinite(impulseInvDt * angular) &&
               std::isfinite(impulseInvDt * motorImpulse) &&
               std::isfinite(impulseInvDt * lowerImpulse) &&
               std::isfinite(impulseInvDt * upperImpulse);
    }
    /// Lets the joint go: it keeps no impulse and is not solved until rearmed.
    void letGoFor(JointLetGoReason reason, float separation) {
        letGo = true;
        letGoReason = reason;
        letGoAt = separation;
        impulse = Vec2{};
        motorImpulse = lowerImpulse = upperImpulse = 0.0f;
    }
};

}  // namespace pivot
