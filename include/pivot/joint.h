// The revolute joint and the choice of algorithm that corrects its position error.
//
// A revolute joint pins a point of body A to a point of body B: C = (cB + rB) - (cA + rA) = 0,
// where c is a body's centre of mass and r the anchor relative to it. The velocity solver keeps
// dC/dt at zero; because it does so only to first order, C drifts, and each joint's
// PositionSolver says how that drift is removed (see docs/position-correction.md).
#pragma once

#include <cstdint>
#include <optional>

#include "pivot/id.h"
#include "pivot/math.h"
#include "pivot/solvers.h"

namespace pivot {

/// Bounds on the joint angle (angleB - angleA - referenceAngle), rad, lower <= upper. The limit
/// is corrected by the joint's PositionSolver like the pin; it allows kAngularSlop.
struct JointLimit {
    bool enabled = false;
    float lower = 0.0f;
    float upper = 0.0f;
};

/// Drives the joint speed (angular velocity of B relative to A) towards `speed` with at most
/// `maxTorque`. Acts in the velocity phase only, the same for every PositionSolver.
struct JointMotor {
    bool enabled = false;
    float speed = 0.0f;      ///< rad/s
    float maxTorque = 0.0f;  ///< N m, >= 0
};

/// Why the engine let go of a joint.
enum class JointLetGoReason : std::uint8_t {
    /// Its anchors were further apart than its let-go separation when a step reached it (only
    /// when one is set: WorldDef::jointLetGoSeparation, RevoluteJointDef::letGoSeparation).
    Separation,
    /// Its impulses, or the force and torque they stand for, stopped being finite floats: the
    /// solver diverged on it (constraints that contradict each other, extreme lever arms).
    /// Always on: it keeps NaN and infinity out of the world and out of jointReactionForce.
    NonFinite,
};

/// A joint the engine let go during the last step. A let-go joint is not solved (its bodies
/// move as if it were not there) until World::rearmJoint; it still keeps its bodies from
/// colliding unless its def allowed that.
struct JointLetGoEvent {
    JointId joint;
    JointLetGoReason reason = JointLetGoReason::Separation;
    float separation = 0.0f;  ///< m, |anchorB - anchorA| when the step let it go
};

/// Everything needed to create a revolute joint.
struct RevoluteJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, the pin in body A's frame (origin-relative)
    Vec2 localAnchorB;  ///< m, the pin in body B's frame
    /// rad, angleB - angleA when the joint angle is zero.
    float referenceAngle = 0.0f;
    /// When set, the pin is this world point: the local anchors and the reference angle are
    /// taken from the bodies' poses when the joint is created. Set it or the three fields above,
    /// not both: a def with a world anchor and a non-zero local anchor or reference angle is
    /// refused (World::createJoint throws pivot::Error), rather than one of them being ignored.
    std::optional<Vec2> worldAnchor;
    /// Unset: the world's default (WorldDef::defaultPositionSolver, FullNGS unless changed).
    std::optional<PositionSolver> positionSolver;
    /// Fraction of the position error corrected, in [0, 1]. Unset: defaultBiasFactor(solver).
    std::optional<float> biasFactor;
    JointLimit limit;
    JointMotor motor;
    /// m, in [0, kMaxMagnitude]: let the joint go when its anchors are further apart than this
    /// when a step reaches it (World::jointLetGoEvents); 0: never. Unset: the world's setting
    /// (WorldDef::jointLetGoSeparation, never unless changed).
    std::optional<float> letGoSeparation;
    /// Whether the two bodies' shapes may collide with each other.
    bool collideConnected = false;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it

    /// A joint pinning bodyA to bodyB at a world point, at the bodies' current relative angle.
    static RevoluteJointDef atWorldAnchor(BodyId a, BodyId b, Vec2 anchor) {
        RevoluteJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.worldAnchor = anchor;
        return def;
    }
};

/// A mouse joint pulls one point of a body towards a target that the caller moves, like a
/// spring with a damper: the way testbeds let a user drag bodies. It is soft (a spring of the
/// given frequency and damping ratio for the body's mass, its force capped at maxForce) and has
/// no position correction.
struct MouseJointDef {
    BodyId body;                ///< a dynamic body
    Vec2 target;                ///< m, world; the body point under it at creation is the one pulled
    float maxForce = 1000.0f;   ///< N, > 0
    float hertz = 5.0f;         ///< spring frequency, > 0
    float dampingRatio = 0.7f;  ///< >= 0; 1 is critical damping
};

}  // namespace pivot
