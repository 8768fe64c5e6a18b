// The joints, and the choice of algorithm that corrects each one's position error.
//
// A joint constrains two bodies: a revolute joint pins a point of body A to a point of body B,
// C = (cB + rB) - (cA + rA) = 0, where c is a body's centre of mass and r the anchor relative to
// it; a distance joint holds its two anchors a length apart, C = |pB - pA| - length; each other
// type's constraint is described at its def. The velocity solver keeps dC/dt at zero; because it
// does so only to first order, C drifts, and each joint's PositionSolver says how that drift is
// removed (see docs/position-correction.md).
#pragma once

#include <cstdint>
#include <optional>

#include "pivot/constants.h"
#include "pivot/id.h"
#include "pivot/math.h"
#include "pivot/solvers.h"

namespace pivot {

/// The kinds of joint. A JointId names a joint of any type; calls made for one type (such as
/// World::jointLimit, for revolute joints) refuse a joint of another with pivot::Error.
enum class JointType : std::uint8_t {
    Revolute,
    Distance,
    Pulley,
    Friction,
    Motor,
    Prismatic,
    Weld,
    Wheel,
    Gear,
};

/// The type's name: "revolute", "distance", "pulley", "friction", "motor", "prismatic", "weld",
/// "wheel", "gear"; "invalid" for a value out of range.
const char* jointTypeName(JointType type);

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
    /// The force it applied passed its break force (a def's breakForce, World::setJointBreakForce):
    /// a breakable joint.
    Force,
    /// The torque it applied passed its break torque (breakTorque).
    Torque,
};

/// A joint the engine let go during the last step. A let-go joint is not solved (its bodies
/// move as if it were not there) until World::rearmJoint; it still keeps its bodies from
/// colliding unless its def allowed that.
struct JointLetGoEvent {
    JointId joint;
    JointLetGoReason reason = JointLetGoReason::Separation;
    float separation = 0.0f;  ///< m, |anchorB - anchorA| when the step let it go
    /// N (Force) or N m (Torque): the magnitude of the force, or the torque, that passed the
    /// threshold, as jointReactionForce / jointReactionTorque would have reported it; 0 for
    /// the other reasons.
    float reaction = 0.0f;
};

/// How soft a joint holds together under the strategies that make it soft (the others keep it
/// but do not read it).
///  - SoftStep: the position error is pulled back by a spring of `hertz` with `dampingRatio` on
///    the joint's own effective mass, so the stiffness does not depend on the masses it joins.
///    Each substep uses at most kMaxSoftHertzShare of the substep rate (30 Hz at 60 Hz with one
///    substep, 60 Hz from two substeps on).
///  - XPBD: `compliance`, the inverse stiffness of every row of the joint (m/N along lengths,
///    rad/(N m) about angles); 0, the default, is rigid.
struct JointSoftness {
    float hertz = kDefaultJointHertz;                ///< > 0, at most kMaxMagnitude
    float dampingRatio = kDefaultJointDampingRatio;  ///< >= 0, at most kMaxMagnitude; 1: critical
    float compliance = 0.0f;                         ///< >= 0, at most kMaxMagnitude

    friend bool operator==(const JointSoftness& a, const JointSoftness& b) {
        return a.hertz == b.hertz && a.dampingRatio == b.dampingRatio &&
               a.compliance == b.compliance;
    }
    friend bool operator!=(const JointSoftness& a, const JointSoftness& b) { return !(a == b); }
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
    /// In [0, kMaxIterations]: NGS position sweeps this joint asks for beyond the world's
    /// (ModifiedNGS and FullNGS; the other strategies ignore it). When an island's shared sweeps
    /// stop with something still beyond the slop, sweeps over only the joints that asked repeat,
    /// each joint in as many as it asked for, until they are all within it: a joint that matters
    /// can be held tighter without every joint of the island paying for it (as Jolt lets a
    /// constraint raise its own iteration counts). 0, the default: the world's sweeps only.
    int extraPositionIterations = 0;
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    JointLimit limit;
    JointMotor motor;
    /// m, in [0, kMaxMagnitude]: let the joint go when its anchors are further apart than this
    /// when a step reaches it (World::jointLetGoEvents); 0: never. Unset: the world's setting
    /// (WorldDef::jointLetGoSeparation, never unless changed).
    std::optional<float> letGoSeparation;
    /// Whether the two bodies' shapes may collide with each other.
    bool collideConnected = false;
    /// N and N m, each in [0, kMaxMagnitude]; 0 (the default): never. Breakable joints: the
    /// joint is let go (JointLetGoReason::Force, Torque) in the step where the force, or the
    /// torque, it applies to body B passes this, measured over the step: the mean of its
    /// substeps' forces, so that a threshold reads the same at any WorldDef::substepCount (an
    /// impact given within one substep would read substepCount times stronger per substep).
    /// With one substep it is jointReactionForce's length, |jointReactionTorque|.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
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

/// A spring on a joint's free coordinate, soft as a spring of `hertz` with `dampingRatio` on the
/// joint's effective mass would be (so the frequency does not depend on the masses). A spring
/// has no position correction: it is its own.
struct JointSpring {
    bool enabled = false;
    float hertz = 0.0f;         ///< > 0 when enabled, at most kMaxMagnitude
    float dampingRatio = 0.0f;  ///< >= 0; 1 is critical damping
};

/// Bounds on a distance joint's length, m, 0 <= min <= max.
struct LengthLimit {
    bool enabled = false;
    float min = 0.0f;
    float max = 0.0f;
};

/// Everything needed to create a distance joint: a rod, a rope or a spring between two anchors.
///  - spring off, limit off: a rigid rod of `length`;
///  - spring off, limit on: a rope, free while its length is within [min, max] (min == max: a
///    rod of that length);
///  - spring on: a spring towards `length`, and with the limit on, never shorter than min or
///    longer than max.
/// The rod and the limits are corrected by the joint's PositionSolver; the spring is soft.
struct DistanceJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;  ///< m, in body B's frame
    /// m, the rest length, in [kLinearSlop, kMaxCoordinate]. Unset: the anchors' distance when
    /// the joint is created.
    std::optional<float> length;
    LengthLimit limit;
    JointSpring spring;
    /// Unset: the world's default (WorldDef::defaultPositionSolver).
    std::optional<PositionSolver> positionSolver;
    /// Fraction of the position error corrected, in [0, 1]. Unset: defaultBiasFactor(solver).
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as the joint's separation: how far its
    /// length is outside what the joint allows (World::jointSeparation).
    std::optional<float> letGoSeparation;
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it
};

/// Everything needed to create a pulley joint: anchor A hangs from a fixed point in the world
/// (groundAnchorA) and anchor B from another, and a rope over the two wheels keeps
///   lengthA + ratio * lengthB = constant,
/// where each length runs from the ground anchor to the body's anchor. A scalar constraint,
/// corrected by the joint's PositionSolver. As in Box2D the rope pushes as well as pulls (it
/// never goes slack), and a side shorter than kMinPulleyLength has no direction and is not
/// held: keep both loads below their wheels.
struct PulleyJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 groundAnchorA;  ///< m, world
    Vec2 groundAnchorB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;
    /// In [kMinPulleyRatio, 1 / kMinPulleyRatio]. Side B's length changes 1 / ratio as fast as
    /// side A's, and the rope pulls B ratio times as hard as A (a block and tackle).
    float ratio = 1.0f;
    /// m, each at least kMinPulleyLength. Unset: the anchors' distances when the joint is
    /// created.
    std::optional<float> lengthA;
    std::optional<float> lengthB;
    std::optional<PositionSolver> positionSolver;
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as |C| (World::jointSeparation).
    std::optional<float> letGoSeparation;
    bool collideConnected = true;  ///< as Box2D's pulley: the two loads may touch
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;
};

/// Bounds on a prismatic or wheel joint's translation (World::jointTranslation), m,
/// lower <= upper. Both are corrected by the joint's PositionSolver, without slop.
struct TranslationLimit {
    bool enabled = false;
    float lower = 0.0f;
    float upper = 0.0f;
};

/// Drives a joint's translation speed towards `speed` with at most `maxForce`. Acts in the
/// velocity phase only, the same for every PositionSolver.
struct LinearMotor {
    bool enabled = false;
    float speed = 0.0f;     ///< m/s
    float maxForce = 0.0f;  ///< N, >= 0
};

/// Everything needed to create a prismatic joint: body B slides along an axis fixed in body A,
/// without turning relative to it (a piston, an elevator, a drawer). Two position constraints
/// hold it, corrected by the joint's PositionSolver as one 2x2 block: the anchor of B stays on
/// the line through A's anchor along the axis, and the relative angle stays the reference angle.
/// Along the axis, the translation (anchor B - anchor A) . axis is free, within the optional
/// limit (which joins the block, as a 3x3, while reached), driven by the optional motor and
/// pulled towards 0 by the optional spring.
struct PrismaticJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;  ///< m, in body B's frame
    /// The axis in body A's frame; any length above kLinearSlop (it is normalised).
    Vec2 localAxisA{1.0f, 0.0f};
    /// rad, angleB - angleA when the joint holds.
    float referenceAngle = 0.0f;
    /// When set, both anchors are this world point and the reference angle the bodies' current
    /// relative angle (as RevoluteJointDef::worldAnchor; refused together with a non-zero local
    /// anchor or reference angle).
    std::optional<Vec2> worldAnchor;
    /// When set, the axis in world coordinates at creation: localAxisA is taken from body A's
    /// pose (refused together with a localAxisA other than the default (1, 0)).
    std::optional<Vec2> worldAxis;
    TranslationLimit limit;
    LinearMotor motor;
    /// Soft, towards translation 0; no position correction (JointSpring).
    JointSpring spring;
    /// Unset: the world's default (WorldDef::defaultPositionSolver).
    std::optional<PositionSolver> positionSolver;
    /// Fraction of the position error corrected, in [0, 1]. Unset: defaultBiasFactor(solver).
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as the joint's separation: how far anchor B
    /// is off the axis line, and beyond a reached limit (World::jointSeparation).
    std::optional<float> letGoSeparation;
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it

    /// A joint at a world anchor sliding along a world axis, at the bodies' current relative
    /// angle.
    static PrismaticJointDef atWorldAnchor(BodyId a, BodyId b, Vec2 anchor, Vec2 axis) {
        PrismaticJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.worldAnchor = anchor;
        def.worldAxis = axis;
        return def;
    }
};

/// Everything needed to create a weld joint: anchor B held on anchor A and the relative angle
/// at the reference angle, as one 3x3 block corrected by the joint's PositionSolver (a beam of
/// welded boxes, a part glued to another). Either half may be made soft instead: a spring on the
/// point (linearSpring) or on the angle (angularSpring), which has no position correction.
struct WeldJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;  ///< m, in body B's frame
    /// rad, angleB - angleA when the joint holds.
    float referenceAngle = 0.0f;
    /// When set, both anchors are this world point and the reference angle the bodies' current
    /// relative angle (as RevoluteJointDef::worldAnchor; refused together with a non-zero local
    /// anchor or reference angle).
    std::optional<Vec2> worldAnchor;
    JointSpring linearSpring;   ///< soft point, towards anchor B on anchor A
    JointSpring angularSpring;  ///< soft angle, towards the reference angle
    /// Unset: the world's default (WorldDef::defaultPositionSolver).
    std::optional<PositionSolver> positionSolver;
    /// Fraction of the position error corrected, in [0, 1]. Unset: defaultBiasFactor(solver).
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as |anchorB - anchorA| (0 while the point
    /// is soft: World::jointSeparation).
    std::optional<float> letGoSeparation;
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it

    /// A joint welding bodyA to bodyB at a world point, at the bodies' current relative angle.
    static WeldJointDef atWorldAnchor(BodyId a, BodyId b, Vec2 anchor) {
        WeldJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.worldAnchor = anchor;
        return def;
    }
};

/// Everything needed to create a wheel joint: body B (the wheel) turns freely about its anchor,
/// which slides along an axis fixed in body A (the chassis), a car's suspension. The anchor is
/// held on the axis line, a position constraint corrected by the joint's PositionSolver; along
/// the axis the optional spring (the suspension, towards translation 0) and limit act, and the
/// optional motor drives the wheel's rotation relative to A. Without a spring or a limit the
/// wheel slides freely along the axis.
struct WheelJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;  ///< m, in body B's frame; usually its centre
    /// The axis in body A's frame; any length above kLinearSlop (it is normalised).
    Vec2 localAxisA{1.0f, 0.0f};
    /// When set, both anchors are this world point (refused with a non-zero local anchor).
    std::optional<Vec2> worldAnchor;
    /// When set, the axis in world coordinates at creation (refused with a localAxisA other
    /// than the default (1, 0)).
    std::optional<Vec2> worldAxis;
    JointSpring spring;      ///< the suspension, towards translation 0
    TranslationLimit limit;  ///< on the translation along the axis, m
    JointMotor motor;        ///< drives wB - wA towards motor.speed, rad/s, within maxTorque
    /// Unset: the world's default (WorldDef::defaultPositionSolver).
    std::optional<PositionSolver> positionSolver;
    /// Fraction of the position error corrected, in [0, 1]. Unset: defaultBiasFactor(solver).
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as the joint's separation: how far the
    /// anchor is off the axis line, and beyond a reached limit (World::jointSeparation).
    std::optional<float> letGoSeparation;
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it

    /// A wheel at a world anchor whose suspension runs along a world axis.
    static WheelJointDef atWorldAnchor(BodyId a, BodyId b, Vec2 anchor, Vec2 axis) {
        WheelJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.worldAnchor = anchor;
        def.worldAxis = axis;
        return def;
    }
};

/// Everything needed to create a gear joint: it couples two revolute or prismatic joints, each
/// between a base body (its body A) and a moving body (its body B), so that
///   coordinate1 + ratio * coordinate2 = constant,
/// where a revolute joint's coordinate is its angle (World::jointAngle, rad) and a prismatic
/// joint's its translation (World::jointTranslation, m); the constant is the sum when the gear
/// is created. Two wheels that mesh, a rack and pinion, a lever turning a slider. A scalar
/// constraint on four bodies (both joints' bodies: the gear pushes the bases back as well),
/// corrected by the gear's own PositionSolver; the two joints keep theirs.
///
/// The gear's body A is joint1's body B and its body B is joint2's body B; they must differ,
/// and not both be static. (The step finds a gear through its bodies A and B: if both are made
/// static later, it is not solved until one of them moves again.) A coupled joint that is let
/// go is not solved, but still keeps its bodies in the gear's island.
/// While a gear is built on a joint, World::destroyJoint refuses that joint (destroy the gear
/// first); World::destroyBody destroys, with a body's joints, the gears built on them.
struct GearJointDef {
    JointId joint1;  ///< a revolute or prismatic joint
    JointId joint2;  ///< another one
    /// |ratio| in [kMinGearRatio, 1 / kMinGearRatio]. Joint1 moving by d moves joint2 by
    /// -d / ratio: two meshing wheels of radii r1 and r2 (which turn opposite ways) have
    /// ratio r2 / r1; a pinion of radius r on joint1 driving a rack on joint2 has ratio
    /// 1 / r or -1 / r (rad/m), the sign depending on the rack's axis.
    float ratio = 1.0f;
    std::optional<PositionSolver> positionSolver;
    std::optional<float> biasFactor;
    int extraPositionIterations = 0;  ///< as RevoluteJointDef's
    JointSoftness softness;  ///< SoftStep's and XPBD's softness (unused by the others)
    /// As RevoluteJointDef::letGoSeparation, measured as |C| (World::jointSeparation), in
    /// joint1's units: rad for a revolute joint, m for a prismatic one.
    std::optional<float> letGoSeparation;
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;
};

/// Everything needed to create a friction joint: top-down friction between two bodies (a box
/// sliding on a table seen from above, with the table as body A). The relative velocity of the
/// anchors and the relative rotation are resisted with at most maxForce and maxTorque. Velocity
/// only, as in Box2D: it holds nothing in place, so it has no position error and no strategy
/// (World::setJointPositionSolver refuses it).
struct FrictionJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA;  ///< m, in body A's frame (origin-relative)
    Vec2 localAnchorB;
    float maxForce = 0.0f;   ///< N, >= 0
    float maxTorque = 0.0f;  ///< N m, >= 0
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;
};

/// Everything needed to create a motor joint: drives body B's origin towards linearOffset in
/// body A's frame and its angle towards angleA + angularOffset, with at most maxForce and
/// maxTorque, removing correctionFactor of the error per step (a platform following a path, a
/// character's hand). Velocity only, as in Box2D: the correction is its purpose, not a strategy's
/// (World::setJointPositionSolver refuses it).
struct MotorJointDef {
    BodyId bodyA;
    BodyId bodyB;
    /// m, in body A's frame. Unset: where body B's origin is when the joint is created.
    std::optional<Vec2> linearOffset;
    /// rad. Unset: angleB - angleA when the joint is created.
    std::optional<float> angularOffset;
    float maxForce = 1.0f;          ///< N, >= 0
    float maxTorque = 1.0f;         ///< N m, >= 0
    float correctionFactor = 0.3f;  ///< in [0, 1]
    bool collideConnected = false;
    /// As RevoluteJointDef::breakForce and breakTorque.
    float breakForce = 0.0f;
    float breakTorque = 0.0f;
    std::uint64_t userData = 0;
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
