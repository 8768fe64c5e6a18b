// The revolute joint and the choice of algorithm that corrects its position error.
//
// A revolute joint pins a point of body A to a point of body B: C = (cB + rB) - (cA + rA) = 0,
// where c is a body's centre of mass and r the anchor relative to it. The velocity solver keeps
// dC/dt at zero; because it does so only to first order, C drifts, and each joint's
// PositionSolver says how that drift is removed (see docs/position-correction.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "pivot/id.h"
#include "pivot/math.h"

namespace pivot {

/// The position-correction algorithms of the seed note, chosen per joint.
enum class PositionSolver : std::uint8_t {
    /// A fraction (bias factor / h) of the position error is added to the velocity constraint.
    /// No position phase. Cheapest; the correction adds momentum (bounce, jitter).
    Baumgarte,
    /// After the velocity iterations and position integration: recompute error, Jacobian and
    /// effective mass once, solve for pseudo velocities that start at zero (no warm start) with
    /// the bias, then add them to the positions. Real momentum is untouched.
    PseudoVelocity,
    /// Per constraint solve: re-measure the error and radius vectors from the current positions
    /// and move the positions at once, with the effective mass frozen at the start of the
    /// position phase. Stops early once every error is below kLinearSlop.
    ModifiedNGS,
    /// As ModifiedNGS, with the effective mass rebuilt at every solve. The default.
    FullNGS,
};

constexpr int kPositionSolverCount = 4;

/// The solver's name as the testbed spells it: baumgarte, pseudo_velocity, modified_ngs,
/// full_ngs. An out-of-range value gives "invalid".
const char* positionSolverName(PositionSolver solver);
/// Parses a name made by positionSolverName; nullopt for anything else.
std::optional<PositionSolver> parsePositionSolver(std::string_view name);
/// The bias factor a joint uses when its def does not set one: 0.2 for Baumgarte and
/// PseudoVelocity, 1.0 for the NGS pair.
float defaultBiasFactor(PositionSolver solver);

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
