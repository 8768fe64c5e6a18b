// The World: owns bodies, shapes and joints, and advances them with World::step.
//
// Every call that takes an id or a def checks it first; bad input throws pivot::Error (see
// error.h) naming the field and value, and leaves the world unchanged. Bad input is a null,
// stale or foreign id, an enum value out of range, a degenerate polygon, or a number that is
// not finite, a denormal, or outside the input limits of constants.h (kMaxCoordinate for
// positions and sizes, kMinDensity to kMaxDensity, kMaxSpeed and kMaxAngularSpeed for
// velocities, kMaxGravity, kMaxGravityScale, kMaxFriction, kMaxMagnitude for everything else).
// Every state the engine reports is one these checks accept, so it can be set again.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "pivot/body.h"
#include "pivot/broad_phase_boxes.h"
#include "pivot/constants.h"
#include "pivot/continuous_collision.h"
#include "pivot/debug_draw.h"
#include "pivot/id.h"
#include "pivot/joint.h"
#include "pivot/math.h"
#include "pivot/query.h"
#include "pivot/shape.h"
#include "pivot/solvers.h"
#include "pivot/step_tasks.h"

namespace pivot {

struct WorldDef {
    Vec2 gravity{0.0f, -10.0f};  ///< m/s^2, each component within +-kMaxGravity
    /// The position solver of joints whose def leaves it unset (the seed note recommends
    /// FullNGS: robust, and cheaper per iteration than it sounds thanks to the early exit).
    PositionSolver defaultPositionSolver = PositionSolver::FullNGS;
    /// Start each step from the previous step's impulses (scaled by the ratio of time steps).
    bool warmStarting = true;
    ContactCorrection contactCorrection = ContactCorrection::NGS;
    /// Fraction of a contact's penetration (beyond kLinearSlop) removed per step (Baumgarte)
    /// or per solve (NGS), in [0, 1].
    float contactBiasFactor = kDefaultContactBias;
    /// ContactCorrection::Soft's spring: hertz (> 0; used at most at kMaxSoftHertzShare of the
    /// substep rate), damping ratio (>= 0) and the fastest it pushes bodies apart (m/s, > 0),
    /// each at most kMaxMagnitude.
    float contactHertz = kDefaultContactHertz;
    float contactDampingRatio = kDefaultContactDampingRatio;
    float contactPushSpeed = kDefaultContactPushSpeed;
    /// m/s: contacts closing slower than this do not bounce.
    float restitutionThreshold = kRestitutionThreshold;
    /// m/s, in [0, kMaxSpeed]: the approach speed above which a contact of a shape with
    /// ShapeDef::enableHitEvents reports a World::contactHitEvents entry.
    float hitEventThreshold = kDefaultHitEventThreshold;
    /// Let islands that have come to rest sleep (see BodyDef::allowSleep).
    bool enableSleep = true;
    /// Continuous collision: after each step, a dynamic body that passed into or through
    /// static geometry (under Substeps kinematic too; a bullet: any body) is taken back to the
    /// moment it touched, so fast bodies do not tunnel; continuousCollision says how.
    /// BodyDef::continuous and BodyDef::bullet choose per body; docs/contacts.md says what it costs
    /// and where it differs from a smaller time step.
    bool enableContinuous = true;
    /// Which continuous collision runs (when enableContinuous): Substeps, Box2D 2.4.1's, the
    /// default; or FastBodies, Box2D v3's, which sweeps only the bodies that moved far in the step
    /// (continuous_collision.h).
    ContinuousCollision continuousCollision = ContinuousCollision::Substeps;
    /// Threads that step the world, the caller's included, in [1, 64]. Independent islands,
    /// contact updates and broad-phase queries are shared among them; results are bit-for-bit
    /// the same for every count.
    int workerCount = 1;
    /// With workerCount > 1: each step runs on all the workers or on the caller alone,
    /// whichever was faster when the world last timed a few steps on each (it does every 64
    /// to 1,024 steps). On an idle machine that is usually all of them; while another process
    /// keeps a core busy it can be the caller alone, which is then not held up by a worker that
    /// has lost its core. Where all of them are not at least 3% faster, the caller alone (the
    /// other cores are left to the rest of the program). The results are the same bits either
    /// way. false: always all of them.
    bool adaptWorkerCount = true;
    /// A game's own task system to run the step's shared work on (pivot/step_tasks.h says
    /// how), as Box2D v3 offers: both set, or neither. Set, the world starts no thread of its
    /// own; each parallel stage of a step hands enqueueTask one task per helper (workerCount - 1
    /// of them, none while the caller alone is faster), and a task that the game runs late, or
    /// drops unstarted in finishTask, holds nobody up. The same bits as with the world's own
    /// threads, or with none. An exception either lets out is held, and World::step throws the
    /// first once the step is done (the world then is as that step left it; an enqueueTask
    /// that threw handed out no task, and the calling thread did the helper's share). While
    /// the step runs, neither they nor any other thread may change the world, and they may read
    /// only what a step does not change (World, "callbacks"). Empty, the default: threads of the
    /// world's own.
    EnqueueTaskFunction enqueueTask = nullptr;
    FinishTaskFunction finishTask = nullptr;
    /// m, in [0, kMaxMagnitude]. Opt-in breaking: a joint whose anchors are further apart than
    /// this when a step reaches it is let go (World::jointLetGoEvents, JointLetGoReason). 0, the
    /// default: joints are never let go for their separation, however far they are pulled
    /// apart, as in Box2D. A joint's RevoluteJointDef::letGoSeparation overrides it.
    float jointLetGoSeparation = 0.0f;
    /// In [1, kMaxSubsteps]. Each World::step is solved as this many substeps of dt / n, the
    /// collision found once at its start: per substep, gravity and forces, every constraint
    /// rebuilt at the bodies' current poses and warm-started from the last substep, the velocity
    /// iterations, integration and the position phase of each joint's strategy (so a step costs
    /// about n times as much as one substep). The default, kDefaultSubstepCount (8), with 2
    /// velocity iterations and 1 position iteration, was chosen from the study in
    /// docs/position-correction.md ("Defaults"); 1 with 8 and 3 is the pipeline Box2D 2.4.1
    /// has and agrees with it bit for bit (box2d241()). "Substeps" there says what each strategy
    /// does per substep.
    int substepCount = kDefaultSubstepCount;
    /// Iterations of the velocity phase and of the position phase in each substep, each in
    /// [0, kMaxIterations], used by World::step(dt) (World::step(dt, velocity, position) gives a
    /// step its own). The position phase stops early once its joints and contacts are within
    /// the slop, so its count is a most.
    int velocityIterations = kDefaultVelocityIterations;
    int positionIterations = kDefaultPositionIterations;
    /// How the broad phase sizes its boxes: Compact, the default, is Box2D v3's (tight boxes,
    /// fewer contacts between shapes that never touch); Predictive is Box2D 2.4.1's, needed to
    /// agree with it bit for bit. Same behaviour either way, except which non-touching pairs
    /// have contacts (and so the order contacts are made and solved in, and the bits that
    /// follow). docs/contacts.md says what each costs.
    BroadPhaseBoxes broadPhaseBoxes = BroadPhaseBoxes::Compact;

    /// Box2D 2.4.1's pipeline: one substep of 8 velocity and 3 position iterations and its
    /// broad-phase boxes, the rest as the defaults (FullNGS joints, NGS contacts, continuous
    /// collision by substeps). Built with it, a world agrees with Box2D 2.4.1 bit for bit where
    /// their features meet (the reference tests); it costs less than the defaults and holds less.
    static WorldDef box2d241() {
        WorldDef def;
        def.substepCount = 1;
        def.velocityIterations = kBox2D241VelocityIterations;
        def.positionIterations = kBox2D241PositionIterations;
        def.broadPhaseBoxes = BroadPhaseBoxes::Predictive;
        return def;
    }
};

/// A touching contact as seen from outside, measured at the bodies' current poses.
struct ContactPoint {
    Vec2 point;                   ///< m, midway between the two surfaces
    float separation = 0.0f;      ///< m, negative when the shapes overlap
    float normalImpulse = 0.0f;   ///< N s, of the last step
    float tangentImpulse = 0.0f;  ///< N s, of the last step
};

struct ContactData {
    ShapeId shapeA;
    ShapeId shapeB;
    Vec2 normal;  ///< unit, from shape A to shape B
    int pointCount = 0;
    ContactPoint points[2];
};

/// A sensor shape and a shape it started or stopped overlapping during the last step (or when
/// a shape was destroyed or stopped being a sensor).
struct SensorEvent {
    ShapeId sensor;
    ShapeId visitor;
};

/// Two shapes that started or stopped touching during the last step.
struct ContactEvent {
    ShapeId shapeA;
    ShapeId shapeB;
};

/// A contact that took a hit during the last step: of a shape with ShapeDef::enableHitEvents,
/// touching after the step, with a point that approached faster than
/// WorldDef::hitEventThreshold and that the solver pushed apart.
struct ContactHitEvent {
    ShapeId shapeA;
    ShapeId shapeB;
    Vec2 point;                  ///< m, the fastest approaching point, where the step left it
    Vec2 normal;                 ///< unit, from shape A to shape B
    float approachSpeed = 0.0f;  ///< m/s, how fast the point closed when the step began
};

/// A body the last step moved (or that fell asleep in it): for syncing a game object to it.
struct BodyMoveEvent {
    BodyId body;
    Transform transform;      ///< where the step left its origin
    bool fellAsleep = false;  ///< the step put it to sleep: no move events until it wakes
};

/// World::setPreSolveCallback: called with a touching contact (measured at the poses the step
/// starts from) of a shape with ShapeDef::enablePreSolve, before the step solves it; return
/// false to leave the contact out of this step (it pushes nothing, and continuous collision
/// does not stop at it), true to keep it.
using PreSolveCallback = std::function<bool(const ContactData& contact)>;
/// World::setCustomFilterCallback: called for two shapes whose filters (pivot::Filter) and
/// bodies allow a contact, when the pair is about to make one or is re-filtered; return false
/// to keep them from colliding.
using CustomFilterCallback = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;

/// A body the last step held at the edge of the world: its origin would have left
/// +-kMaxCoordinate, the range every position the API takes must be in. It was put back on the
/// edge it crossed and its velocity outwards across that edge was stopped, so that every
/// position the engine reports is one the API accepts (setBodyTransform, anchors, targets).
struct WorldEdgeEvent {
    BodyId body;
    Vec2 reached;  ///< m, where the step would have put the body's origin
};

/// What the last call to World::step did.
struct StepStats {
    int islandCount = 0;
    int bodyCount = 0;   ///< bodies simulated (in an island)
    int jointCount = 0;  ///< joints solved
    /// Bodies whose move this step was limited by kMaxTranslation / kMaxRotation (with
    /// substeps, each substep's limit is its share of the step's: a body is counted once per
    /// substep that limited it), and bodies whose final velocity was held at kMaxSpeed /
    /// kMaxAngularSpeed (relax sweeps act after the move's limit).
    int translationClamps = 0;
    int rotationClamps = 0;
    /// The most NGS position iterations any island ran, summed over its substeps (fewer than
    /// asked when every error was within slop early). 0 when no island has an NGS joint or NGS
    /// contact.
    int positionIterations = 0;
    /// Joint solves of the extra NGS sweeps that joints asked for (extraPositionIterations),
    /// over every island and substep: the cost of that knob, beyond the shared sweeps.
    int extraPositionSolves = 0;
    int contactCount = 0;       ///< contacts in the world (broad-phase boxes overlapping)
    int touchingCount = 0;      ///< of which touching (manifold with points)
    int sleepingBodyCount = 0;  ///< dynamic and kinematic bodies asleep after the step
    /// Joints let go this step (World::jointLetGoEvents lists them).
    int letGoJointCount = 0;
    /// Bodies whose solved state this step was not finite: each kept its pose, at rest
    /// (World::discardedBodies lists them).
    int discardedBodyCount = 0;
    /// Bodies held at the world's edge this step (World::worldEdgeEvents lists them).
    int edgeBodyCount = 0;
    /// Impacts continuous collision solved this step: bodies taken back to the moment they
    /// touched something they would otherwise have passed into or through.
    int impactCount = 0;
    /// Workers the step ran on, the caller included: WorldDef::workerCount, or 1 while the
    /// caller alone was found faster, or no slower (WorldDef::adaptWorkerCount).
    int workersUsed = 1;
};

class World {
public:
    explicit World(const WorldDef& def = WorldDef{});
    ~World();
    // A world owns memory its ids point into: it is neither copied nor moved. Hold it by
    // value where it lives, or in a std::unique_ptr.
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // --- simulation -------------------------------------------------------------------------
    /// Advance by dt seconds, in [kMinTimeStep, kMaxTimeStep], with the world's iteration counts
    /// (WorldDef::velocityIterations and positionIterations), each run in every substep
    /// (WorldDef::substepCount; dt divided by it must still be at least kMinTimeStep). Contact
    /// and joint impulses of the previous step warm-start this one scaled by the ratio of the
    /// steps, but never scaled up: after a step much shorter than this one its impulses say
    /// little about this step's forces (see docs/position-correction.md, "Changing the time
    /// step").
    void step(float dt);
    /// The same with this step's own iteration counts, each in [0, kMaxIterations] (the world's
    /// are unchanged).
    void step(float dt, int velocityIterations, int positionIterations);
    const StepStats& lastStepStats() const;
    /// WorldDef::substepCount. Changing it takes effect at the next step; the warm start scales
    /// the last substep's impulses by the ratio of the substeps' lengths, as for a change of dt.
    int substepCount() const;
    void setSubstepCount(int count);
    /// WorldDef::velocityIterations and positionIterations, what World::step(dt) runs in each
    /// substep; a change takes effect at the next step.
    int velocityIterations() const;
    int positionIterations() const;
    void setIterations(int velocityIterations, int positionIterations);

    Vec2 gravity() const;
    /// Changes gravity and wakes every body, so sleeping bodies feel the change.
    void setGravity(Vec2 gravity);
    PositionSolver defaultPositionSolver() const;
    /// WorldDef::broadPhaseBoxes (fixed for the world's life; a snapshot carries it).
    BroadPhaseBoxes broadPhaseBoxes() const;
    ContactCorrection contactCorrection() const;
    void setContactCorrection(ContactCorrection correction);
    /// Switching sleep off wakes every body.
    void setSleepEnabled(bool enabled);
    bool isSleepEnabled() const;
    /// WorldDef::enableContinuous; takes effect at the next step.
    void setContinuousEnabled(bool enabled);
    bool isContinuousEnabled() const;
    /// WorldDef::continuousCollision; takes effect at the next step (a snapshot carries it).
    void setContinuousCollision(ContinuousCollision policy);
    ContinuousCollision continuousCollision() const;
    /// WorldDef::hitEventThreshold; takes effect at the next step.
    float hitEventThreshold() const;
    void setHitEventThreshold(float speed);

    // --- callbacks ---------------------------------------------------------------------------
    // The two callbacks run during World::step, on the thread that called it (never on a
    // worker), in contact order, so the same world calls them in the same order with the same
    // arguments on any worker count. A callback may read the world; a call that would change it
    // (any setter, create, destroy, apply, restore or step) throws pivot::Error from inside the
    // callback. An exception a callback lets out is held: the step carries on as if the
    // callback had returned true, and World::step throws that exception when the step is
    // complete (the world then is as that step left it).
    //
    // The task system's callbacks (WorldDef::enqueueTask, finishTask, and the StepTasks they
    // run) are user code a step runs too, while its workers write the world. From them, and
    // from any other thread while a step runs, every call that changes the world throws
    // pivot::Error, and so does every read but these, which a step does not change: the
    // settings' getters (gravity, substepCount, defaultPositionSolver, broadPhaseBoxes,
    // contactCorrection, isSleepEnabled, isContinuousEnabled, continuousCollision,
    // hitEventThreshold), bodyCount, shapeCount, jointCount and isValid. Read anything else from
    // the pre-solve or custom-filter callback, or after World::step returns.
    /// The pre-solve callback (pivot::PreSolveCallback), or an empty one to stop asking. It is
    /// asked each step about every touching contact of a shape with ShapeDef::enablePreSolve
    /// whose bodies are awake, and again before continuous collision stops a body at one.
    void setPreSolveCallback(PreSolveCallback callback);
    /// The custom filter (pivot::CustomFilterCallback), or an empty one for none. It is asked
    /// about every new pair, and about the contacts re-filtered after setShapeFilter,
    /// setBodyType or a joint's creation or destruction. Setting it does not re-ask existing
    /// contacts: call setShapeFilter for the shapes that should be asked again.
    void setCustomFilterCallback(CustomFilterCallback callback);

    // --- bodies -----------------------------------------------------------------------------
    BodyId createBody(const BodyDef& def);
    /// Destroys the body, its shapes, its contacts, every joint attached to it (and the gear
    /// joints built on those) and its mouse joints, and wakes every body it touched or was
    /// jointed to.
    void destroyBody(BodyId id);
    bool isValid(BodyId id) const;
    int bodyCount() const;
    /// Every body, in creation-slot order.
    std::vector<BodyId> bodyIds() const;
    /// The body's shapes, newest first.
    std::vector<ShapeId> bodyShapes(BodyId id) const;
    /// The joints attached to the body (mouse joints aside), newest first.
    std::vector<JointId> bodyJoints(BodyId id) const;
    /// The body's touching contacts, as World::contacts reports them.
    std::vector<ContactData> bodyContacts(BodyId id) const;

    BodyType bodyType(BodyId id) const;
    /// Changes the body's type between steps. Mass, centre of mass and inertia are recomputed
    /// from its shapes (as createBody and createShape do); pending forces are dropped; a body
    /// made static stops (its velocities become zero), one made kinematic keeps the velocity of
    /// its origin. The body and everything touching it or jointed to it are woken. Contacts
    /// that can no longer collide (static-static, kinematic-static, kinematic-kinematic) are
    /// dropped at the next step's contact update, with an end event if they touched; pairs that
    /// may now collide are found at the next step. Joints stay as they are (a joint between two
    /// non-dynamic bodies holds nothing). A mouse joint on a body that stops being dynamic stays
    /// but pulls nothing until the body is dynamic again.
    ///
    /// Making a body dynamic needs every one of its shapes to have density > 0, the rule
    /// createShape enforces; a body with a zero-density shape is refused (pivot::Error, nothing
    /// changed): give the shape a density with setShapeDensity first. A dynamic body without
    /// shapes moves as a 1 kg point mass, as one made by createBody does.
    void setBodyType(BodyId id, BodyType type);
    Vec2 bodyPosition(BodyId id) const;  ///< m, world position of the body origin
    float bodyAngle(BodyId id) const;    ///< rad
    Transform bodyTransform(BodyId id) const;
    Vec2 bodyWorldCenter(BodyId id) const;       ///< m, centre of mass in world coordinates
    Vec2 bodyLocalCenter(BodyId id) const;       ///< m, centre of mass in the body frame
    Vec2 bodyLinearVelocity(BodyId id) const;    ///< m/s, of the centre of mass
    float bodyAngularVelocity(BodyId id) const;  ///< rad/s
    float bodyMass(BodyId id) const;             ///< kg; 0 for static and kinematic bodies
    /// kg m^2, about the centre of mass; 0 for non-dynamic or fixed-rotation bodies.
    float bodyRotationalInertia(BodyId id) const;
    /// BodyDef::fixedRotation: the body never turns.
    bool bodyFixedRotation(BodyId id) const;
    /// Fixing the rotation stops the body's spin and drops its pending torque; either way its
    /// rotational inertia is recomputed (its centre of mass stays) and it is woken.
    void setBodyFixedRotation(BodyId id, bool fixedRotation);
    /// BodyDef::linearDamping, angularDamping (1/s, >= 0) and gravityScale (within
    /// +-kMaxGravityScale); the setters wake the body.
    float bodyLinearDamping(BodyId id) const;
    void setBodyLinearDamping(BodyId id, float damping);
    float bodyAngularDamping(BodyId id) const;
    void setBodyAngularDamping(BodyId id, float damping);
    float bodyGravityScale(BodyId id) const;
    void setBodyGravityScale(BodyId id, float scale);
    Vec2 bodyWorldPoint(BodyId id, Vec2 localPoint) const;
    Vec2 bodyLocalPoint(BodyId id, Vec2 worldPoint) const;

    bool isBodyAwake(BodyId id) const;
    /// Wakes a body (and, at the next step, its island) or puts it to sleep at once.
    void setBodyAwake(BodyId id, bool awake);
    /// Whether the body may sleep; forbidding it wakes the body.
    void setBodySleepAllowed(BodyId id, bool allowed);
    bool isBodySleepAllowed(BodyId id) const;
    /// BodyDef::continuous and BodyDef::bullet; take effect at the next step.
    bool isBodyContinuous(BodyId id) const;
    void setBodyContinuous(BodyId id, bool continuous);
    bool isBodyBullet(BodyId id) const;
    void setBodyBullet(BodyId id, bool bullet);
    /// The value of BodyDef::userData, or the last one set; pivot2d never reads it.
    std::uint64_t bodyUserData(BodyId id) const;
    void setBodyUserData(BodyId id, std::uint64_t userData);

    // Every call below that moves or pushes a body wakes it. One rule for the velocity setters
    // and for forces, torques and impulses: a call that could have no effect is refused
    // (pivot::Error) rather than silently dropped. A static body takes none of them; forces,
    // torques and impulses act on dynamic bodies only (a kinematic body has infinite mass: set
    // its velocity); a body with fixed rotation takes no torque, angular impulse or non-zero
    // angular velocity. A call is also refused if it would take what the body accumulates past
    // a limit: the velocities impulses add up to (kMaxSpeed, kMaxAngularSpeed), the pending force
    // and torque, and the accelerations they give (kMaxMagnitude N, N m, m/s^2, rad/s^2).
    /// Teleport: moves the body origin to `position` at `angle`, keeping its velocity. Every
    /// position the engine reports is within the limits this takes (WorldEdgeEvent).
    void setBodyTransform(BodyId id, Vec2 position, float angle);
    void setBodyLinearVelocity(BodyId id, Vec2 velocity);  ///< m/s, of the centre of mass
    void setBodyAngularVelocity(BodyId id, float omega);   ///< rad/s
    /// N, applied at a world point until the end of the next step. On a body with fixed
    /// rotation only its linear part acts (and no torque is kept).
    void applyForce(BodyId id, Vec2 force, Vec2 worldPoint);
    void applyForceToCenter(BodyId id, Vec2 force);
    void applyTorque(BodyId id, float torque);  ///< N m
    /// N s, changes the velocity at once.
    void applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint);
    void applyAngularImpulse(BodyId id, float impulse);  ///< N m s

    // --- shapes -----------------------------------------------------------------------------
    // createShape, destroyShape, setShapeDensity and setBodyType move a dynamic body's centre
    // of mass, and the centre's velocity changes by w x the move: a call that would take it past
    // kMaxSpeed (a fast-turning body, a shape far out) is refused; slow the body first.
    /// Attaches a shape and updates the body's mass. A sleeping body stays asleep (as in
    /// Box2D): a body made with BodyDef::isAwake false keeps sleeping with its shapes until
    /// something wakes it (an awake body that touches it, for one).
    ShapeId createShape(BodyId body, const ShapeDef& def, const Circle& circle);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    /// On a static or kinematic body only (a segment has no mass).
    ShapeId createShape(BodyId body, const ShapeDef& def, const Segment& segment);
    /// One one-sided segment with its ghosts; on a static or kinematic body only.
    ShapeId createShape(BodyId body, const ShapeDef& def, const ChainSegment& segment);
    /// A chain (pivot::Chain) on a static or kinematic body: one ChainSegment shape per segment,
    /// in chain order, each with `def`'s material, filter and user data (density is ignored:
    /// segments have no mass). Every point is checked first (each finite, within
    /// kMaxCoordinate, at least kLinearSlop from the next; at least 4 points for an open chain,
    /// 3 for a loop); on any error pivot::Error is thrown and no shape is made. The segments
    /// are separate shapes: each can be queried, filtered and destroyed on its own (its
    /// neighbours keep their ghosts, so a body can then fall into the gap).
    std::vector<ShapeId> createChain(BodyId body, const ShapeDef& def, const Chain& chain);
    /// Destroys the shape and its contacts and wakes its body.
    void destroyShape(ShapeId id);
    bool isValid(ShapeId id) const;
    int shapeCount() const;
    BodyId shapeBody(ShapeId id) const;
    Filter shapeFilter(ShapeId id) const;
    float shapeDensity(ShapeId id) const;  ///< kg/m^2
    /// ShapeDef::friction (in [0, kMaxFriction]) and restitution (in [0, 1]). A change is mixed
    /// into the shape's contacts at once (they keep the mix, as ShapeDef describes) and wakes
    /// the body.
    float shapeFriction(ShapeId id) const;
    void setShapeFriction(ShapeId id, float friction);
    float shapeRestitution(ShapeId id) const;
    void setShapeRestitution(ShapeId id, float restitution);
    /// ShapeDef::isSensor. Switching it drops the shape's contacts or sensor overlaps (with end
    /// events for those that touched) and finds its pairs again at the next step.
    bool isShapeSensor(ShapeId id) const;
    void setShapeSensor(ShapeId id, bool sensor);
    /// Changes the shape's density (0, or in [kMinDensity, kMaxDensity]) and recomputes its
    /// body's mass, centre of mass and inertia, keeping the body's motion; wakes the body. A
    /// shape on a dynamic body needs density > 0. Static and kinematic bodies keep the density
    /// for when they become dynamic.
    void setShapeDensity(ShapeId id, float density);
    ShapeType shapeType(ShapeId id) const;
    /// The shape's geometry in its body's frame. Asking a shape for another type's geometry
    /// throws pivot::Error. Polygons come back counter-clockwise.
    Circle shapeCircle(ShapeId id) const;
    Polygon shapePolygon(ShapeId id) const;
    Segment shapeSegment(ShapeId id) const;
    ChainSegment shapeChainSegment(ShapeId id) const;
    Capsule shapeCapsule(ShapeId id) const;
    /// Takes effect at the next step: existing contacts are re-filtered, new pairs found.
    void setShapeFilter(ShapeId id, const Filter& filter);
    /// ShapeDef::enableHitEvents and enablePreSolve; take effect at the next step (enabling
    /// pre-solve wakes the body, so its resting contacts are asked).
    bool shapeHitEventsEnabled(ShapeId id) const;
    void setShapeHitEventsEnabled(ShapeId id, bool enabled);
    bool shapePreSolveEnabled(ShapeId id) const;
    void setShapePreSolveEnabled(ShapeId id, bool enabled);
    /// The value of ShapeDef::userData, or the last one set; pivot2d never reads it.
    std::uint64_t shapeUserData(ShapeId id) const;
    void setShapeUserData(ShapeId id, std::uint64_t userData);

    /// The shape's box at its body's current pose (its collision skin included), as the broad
    /// phase and queryAABB see it.
    AABB shapeAABB(ShapeId id) const;

    // --- queries (pivot/query.h) -------------------------------------------------------------
    // They read the shapes where the last step, or the last call that moved a body, left them.
    // A callback may read the world and change its bodies' motion and settings (velocities,
    // forces, impulses, damping, sleep, materials, filters, user data, joint and world
    // settings: an explosion pushing what a query finds), but not its structure, which the
    // query is walking: a call that creates or destroys anything (a body, shape, chain, joint
    // or mouse joint), changes a body's type, teleports a body (setBodyTransform), switches a
    // shape's sensor flag, restores or steps throws pivot::Error from inside a callback, and
    // changes nothing. Bad arguments (not finite, a box with lower > upper, points outside
    // kMaxCoordinate, a Transform whose rotation is not a unit one within kMaxRotationError)
    // throw pivot::Error.
    /// Every shape the filter sees that the ray from `origin` through origin + translation
    /// enters, in the tree's order; the callback steers the cast (pivot::RayCallback). A zero
    /// translation hits nothing.
    void castRay(Vec2 origin, Vec2 translation, const QueryFilter& filter,
                 RayCallback callback) const;
    /// The first shape the ray enters, if any (of two at the same fraction, either).
    std::optional<RayHit> castRayClosest(Vec2 origin, Vec2 translation,
                                         const QueryFilter& filter = {}) const;
    /// The same ray against one shape, whatever its filter.
    std::optional<RayHit> castRayOnShape(ShapeId id, Vec2 origin, Vec2 translation) const;
    /// Every shape the filter sees whose box (shapeAABB) overlaps `box`, in the tree's order;
    /// the callback returns false to stop.
    void queryAABB(const AABB& box, const QueryFilter& filter, ShapeCallback callback) const;
    /// Every shape the filter sees that contains `point` (on its boundary counts; a polygon's
    /// skin does not; a segment contains none), in the tree's order; the callback returns false
    /// to stop. What the testbed's drags use to pick the body under the pointer.
    void queryPoint(Vec2 point, const QueryFilter& filter, ShapeCallback callback) const;
    /// Every shape the filter sees that overlaps a circle, capsule or polygon placed at `xf`
    /// (touching counts; polygon and segment skins do not), in the tree's order; the callback
    /// returns false to stop. The shape is checked as World::createShape checks it.
    void queryShape(const Circle& circle, const Transform& xf, const QueryFilter& filter,
                    ShapeCallback callback) const;
    void queryShape(const Polygon& polygon, const Transform& xf, const QueryFilter& filter,
                    ShapeCallback callback) const;
    void queryShape(const Capsule& capsule, const Transform& xf, const QueryFilter& filter,
                    ShapeCallback callback) const;
    /// Every shape the filter sees that a circle, capsule or polygon at `xf`, moved by
    /// `translation` without turning, would touch on the way, as castRay reports rays:
    /// RayHit::fraction is where it first comes within a quarter of kLinearSlop of the shape, point
    /// the shape's closest point then and normal its outward normal there; a shape it overlaps at
    /// the start is hit at fraction 0 with a zero normal. The callback steers it as castRay's does.
    void castShape(const Circle& circle, const Transform& xf, Vec2 translation,
                   const QueryFilter& filter, RayCallback callback) const;
    void castShape(const Polygon& polygon, const Transform& xf, Vec2 translation,
                   const QueryFilter& filter, RayCallback callback) const;
    void castShape(const Capsule& capsule, const Transform& xf, Vec2 translation,
                   const QueryFilter& filter, RayCallback callback) const;
    /// The first shape the moving circle, capsule or polygon would touch, if any.
    std::optional<RayHit> castShapeClosest(const Circle& circle, const Transform& xf,
                                           Vec2 translation, const QueryFilter& filter = {}) const;
    std::optional<RayHit> castShapeClosest(const Polygon& polygon, const Transform& xf,
                                           Vec2 translation, const QueryFilter& filter = {}) const;
    std::optional<RayHit> castShapeClosest(const Capsule& capsule, const Transform& xf,
                                           Vec2 translation, const QueryFilter& filter = {}) const;

    // --- contacts ---------------------------------------------------------------------------
    // Every list the API returns (contacts, events, bodyIds, jointIds, bodyShapes) is a copy,
    // so destroying bodies, shapes or joints while iterating one is safe; the ids in it may go
    // stale meanwhile (check with isValid). The user code a step runs is the two callbacks
    // (setPreSolveCallback, setCustomFilterCallback) and the task system's (WorldDef::
    // enqueueTask): none of it may change the world ("callbacks" above).
    /// Every touching contact, measured at the current poses.
    std::vector<ContactData> contacts() const;
    /// Contacts that started / stopped touching during the last step: the change the step made.
    /// Its begin events, then its end events, applied to the pairs touching before it give the
    /// pairs touching after it; a pair is in both lists only if it began and then ended within
    /// the step (one that parted and touched again, when continuous collision met it again
    /// within the step, is in neither). Destroying a shape (or its body) that touched another
    /// adds its end event at once, until the next step clears the list: the event's shape ids
    /// are then already stale.
    std::vector<ContactEvent> contactBeginEvents() const;
    std::vector<ContactEvent> contactEndEvents() const;
    /// Sensor overlaps that began and ended during the last step (ShapeDef::isSensor), in
    /// contact order; an end is also reported, at once, when a sensor or the shape it overlaps
    /// is destroyed or the sensor flag is switched off.
    std::vector<SensorEvent> sensorBeginEvents() const;
    std::vector<SensorEvent> sensorEndEvents() const;
    /// The hits of the last step (pivot::ContactHitEvent), at most one per contact: those of the
    /// discrete solve in island order, then continuous collision's impacts in the order they
    /// were solved (the same for every worker count).
    std::vector<ContactHitEvent> contactHitEvents() const;
    /// Every dynamic and kinematic body the last step simulated (awake, in an island), with its
    /// transform after the step, in island order (the same for every worker count). A body
    /// moved by setBodyTransform between steps is not listed until a step moves it.
    std::vector<BodyMoveEvent> bodyMoveEvents() const;
    /// The bodies held at the edge of the world during the last step, in the order the step
    /// reached them (the same for every worker count). Cleared when the next step starts.
    std::vector<WorldEdgeEvent> worldEdgeEvents() const;
    /// The bodies whose solved state the last step discarded because it was not finite (a
    /// solver diverging on constraints it cannot satisfy): each kept its pose from before the
    /// step, a dynamic one at rest. In the order the step reached them; cleared when the next
    /// step starts.
    std::vector<BodyId> discardedBodies() const;

    // --- joints -----------------------------------------------------------------------------
    JointId createJoint(const RevoluteJointDef& def);
    JointId createJoint(const DistanceJointDef& def);
    JointId createJoint(const PulleyJointDef& def);
    JointId createJoint(const FrictionJointDef& def);
    JointId createJoint(const MotorJointDef& def);
    JointId createJoint(const PrismaticJointDef& def);
    JointId createJoint(const WeldJointDef& def);
    JointId createJoint(const WheelJointDef& def);
    JointId createJoint(const GearJointDef& def);
    /// Refuses a joint that a gear joint is built on: destroy the gear first.
    void destroyJoint(JointId id);
    bool isValid(JointId id) const;
    int jointCount() const;
    /// Every joint, in creation-slot order.
    std::vector<JointId> jointIds() const;

    JointType jointType(JointId id) const;
    BodyId jointBodyA(JointId id) const;
    BodyId jointBodyB(JointId id) const;
    /// m, the joint's anchor on body A in world coordinates (a motor joint's: body A's origin).
    Vec2 jointAnchorA(JointId id) const;
    /// m, the anchors in their bodies' frames, as the def gave them (or as a world anchor made
    /// them); a motor joint's are the origins.
    Vec2 jointLocalAnchorA(JointId id) const;
    Vec2 jointLocalAnchorB(JointId id) const;
    /// rad, angleB - angleA when the joint angle is zero (revolute, prismatic, weld; 0 for the
    /// others).
    float jointReferenceAngle(JointId id) const;
    /// The def's collideConnected. Changing it re-filters the contacts between the two bodies
    /// at the next step (made or ended, with their events) and wakes them.
    bool jointCollideConnected(JointId id) const;
    void setJointCollideConnected(JointId id, bool collide);
    Vec2 jointAnchorB(JointId id) const;  ///< m, the anchor on body B (a motor joint's: B's origin)
    /// m, how far the joint has come apart: for a revolute joint |anchorB - anchorA|, for a
    /// distance joint how far its length is from its rest length (a rod) or outside its limit,
    /// for a pulley joint |lengthA + ratio lengthB - the same at creation|, for a weld joint
    /// |anchorB - anchorA| (0 while its point is soft), for a prismatic or wheel joint
    /// how far anchor B is off the axis line, combined (root of the sum of squares) with how far
    /// the translation is beyond its limit, for a gear joint |coordinate1 + ratio coordinate2 -
    /// constant| in its joint1's units (rad or m: GearJointDef).
    float jointSeparation(JointId id) const;
    /// m, |anchorB - anchorA|.
    float jointLength(JointId id) const;
    /// Whether the engine has let go of the joint (JointLetGoReason says when it does). A
    /// let-go joint is not solved, so it cannot drag NaN or energy into everything it touches;
    /// it stays let go until rearmJoint.
    bool isJointLetGo(JointId id) const;
    /// Solves a let-go joint again from the next step, starting from zero impulses, and wakes
    /// its bodies. If its anchors are still beyond its let-go separation at that step it is let
    /// go again: move the bodies together first (setBodyTransform). A joint that is not let go
    /// is left as it is.
    void rearmJoint(JointId id);
    /// m, the separation beyond which the joint is let go: its own setting if it has one, else
    /// WorldDef::jointLetGoSeparation. 0: never.
    float jointLetGoSeparation(JointId id) const;
    /// A value in [0, kMaxMagnitude] m (0: never let go for separation), or nullopt to follow
    /// WorldDef::jointLetGoSeparation. Takes effect at the next step.
    void setJointLetGoSeparation(JointId id, std::optional<float> separation);
    /// The joints let go during the last step, for their separation, their break force or
    /// torque or a diverged solve (JointLetGoReason), in the order the step reached them (the
    /// same for every worker count). Cleared when the next step starts.
    std::vector<JointLetGoEvent> jointLetGoEvents() const;
    /// The def's breakForce (N) and breakTorque (N m), each in [0, kMaxMagnitude]; 0: never.
    /// Take effect at the next step (the setters wake the joint's bodies); a let-go joint stays
    /// let go (rearmJoint).
    float jointBreakForce(JointId id) const;
    void setJointBreakForce(JointId id, float force);
    float jointBreakTorque(JointId id) const;
    void setJointBreakTorque(JointId id, float torque);
    /// rad, angleB - angleA - referenceAngle (revolute, prismatic and weld joints have a
    /// reference angle; for the others it is 0).
    float jointAngle(JointId id) const;
    /// rad/s, angular velocity of B relative to A.
    float jointSpeed(JointId id) const;
    /// N, the force the joint applied to body B in the last step that solved it (a sleeping
    /// joint keeps reporting the force it held when it fell asleep).
    Vec2 jointReactionForce(JointId id) const;
    /// N m, the torque the joint applied to body B in that step (revolute: motor plus limits;
    /// friction and motor: their angular row; prismatic and weld: what holds their angle;
    /// wheel: its motor; gear: its row's, on body B; distance and pulley joints apply none).
    float jointReactionTorque(JointId id) const;

    // Revolute joints (the calls from here to setJointMotor refuse other types, but for the
    // motor calls, which wheel joints answer too).
    /// N m, the motor's share of the reaction torque.
    float jointMotorTorque(JointId id) const;
    JointLimit jointLimit(JointId id) const;
    /// Changing the limit wakes the joint's bodies and restarts the limit's impulses.
    void setJointLimit(JointId id, const JointLimit& limit);
    JointMotor jointMotor(JointId id) const;
    /// Wakes the joint's bodies.
    void setJointMotor(JointId id, const JointMotor& motor);

    // Distance joints (these calls refuse other types). Each setter wakes the joint's bodies;
    // changing the limit restarts its impulses.
    float distanceJointRestLength(JointId id) const;
    /// m, in [kLinearSlop, kMaxCoordinate].
    void setDistanceJointRestLength(JointId id, float length);
    LengthLimit distanceJointLimit(JointId id) const;
    void setDistanceJointLimit(JointId id, const LengthLimit& limit);
    JointSpring distanceJointSpring(JointId id) const;
    void setDistanceJointSpring(JointId id, const JointSpring& spring);

    // Pulley joints (these calls refuse other types).
    Vec2 pulleyJointGroundAnchorA(JointId id) const;
    Vec2 pulleyJointGroundAnchorB(JointId id) const;
    float pulleyJointRatio(JointId id) const;
    /// m, the lengths the rope was cut to (PulleyJointDef::lengthA, lengthB).
    float pulleyJointRestLengthA(JointId id) const;
    float pulleyJointRestLengthB(JointId id) const;
    /// m, the current length of side A (ground anchor A to anchor A), and of side B.
    float pulleyJointLengthA(JointId id) const;
    float pulleyJointLengthB(JointId id) const;

    // Prismatic and wheel joints.
    /// m, (anchorB - anchorA) . axis, the axis turning with body A.
    float jointTranslation(JointId id) const;
    /// m/s, the rate of change of jointTranslation.
    float jointTranslationSpeed(JointId id) const;
    // Prismatic joints (these calls refuse other types). Each setter wakes the joint's bodies;
    // changing the limit restarts its impulses.
    /// The axis in world coordinates (unit).
    Vec2 prismaticJointAxis(JointId id) const;
    TranslationLimit prismaticJointLimit(JointId id) const;
    void setPrismaticJointLimit(JointId id, const TranslationLimit& limit);
    LinearMotor prismaticJointMotor(JointId id) const;
    void setPrismaticJointMotor(JointId id, const LinearMotor& motor);
    JointSpring prismaticJointSpring(JointId id) const;
    void setPrismaticJointSpring(JointId id, const JointSpring& spring);
    /// N, the motor's share of the reaction force, along the axis.
    float prismaticJointMotorForce(JointId id) const;

    // Wheel joints (these calls refuse other types; jointMotor and setJointMotor drive a
    // wheel). Each setter wakes the joint's bodies; changing the limit restarts its impulses.
    /// The axis in world coordinates (unit), turning with body A.
    Vec2 wheelJointAxis(JointId id) const;
    JointSpring wheelJointSpring(JointId id) const;
    void setWheelJointSpring(JointId id, const JointSpring& spring);
    TranslationLimit wheelJointLimit(JointId id) const;
    void setWheelJointLimit(JointId id, const TranslationLimit& limit);

    // Gear joints (these calls refuse other types).
    JointId gearJointJoint1(JointId id) const;
    JointId gearJointJoint2(JointId id) const;
    float gearJointRatio(JointId id) const;
    /// |ratio| in [kMinGearRatio, 1 / kMinGearRatio]. The gear keeps its present error: the
    /// constant is chosen again so that C is what it was, and nothing jumps. Wakes the gear's
    /// bodies.
    void setGearJointRatio(JointId id, float ratio);

    // Weld joints (these calls refuse other types). Each setter wakes the joint's bodies; an
    // enabled spring makes that half soft from the next step.
    JointSpring weldJointLinearSpring(JointId id) const;
    void setWeldJointLinearSpring(JointId id, const JointSpring& spring);
    JointSpring weldJointAngularSpring(JointId id) const;
    void setWeldJointAngularSpring(JointId id, const JointSpring& spring);

    // Friction and motor joints (these calls refuse other types). Each setter wakes the joint's
    // bodies.
    float jointMaxForce(JointId id) const;
    /// N, >= 0.
    void setJointMaxForce(JointId id, float force);
    float jointMaxTorque(JointId id) const;
    /// N m, >= 0.
    void setJointMaxTorque(JointId id, float torque);
    // Motor joints.
    Vec2 motorJointLinearOffset(JointId id) const;
    void setMotorJointLinearOffset(JointId id, Vec2 offset);
    float motorJointAngularOffset(JointId id) const;
    void setMotorJointAngularOffset(JointId id, float offset);
    float motorJointCorrectionFactor(JointId id) const;
    /// In [0, 1].
    void setMotorJointCorrectionFactor(JointId id, float factor);

    PositionSolver jointPositionSolver(JointId id) const;
    /// Takes effect from the next step and wakes the joint's bodies. A bias factor left to its
    /// default follows the new solver's default. Refused for friction and motor joints, which
    /// have no position error to correct.
    void setJointPositionSolver(JointId id, PositionSolver solver);
    float jointBiasFactor(JointId id) const;
    /// A value in [0, 1], or nullopt for the solver's default. Refused for friction and motor
    /// joints.
    void setJointBiasFactor(JointId id, std::optional<float> biasFactor);
    /// The NGS sweeps the joint asks for beyond the world's (the defs'
    /// extraPositionIterations): in [0, kMaxIterations]. The setter wakes the joint's bodies and
    /// is refused for friction and motor joints.
    int jointExtraPositionIterations(JointId id) const;
    void setJointExtraPositionIterations(JointId id, int count);
    /// The stiffness a SoftStep joint holds with (JointSoftness; kept, unread, by the other
    /// strategies). The setter checks it as the defs do, wakes the joint's bodies, and is
    /// refused for friction and motor joints.
    JointSoftness jointSoftness(JointId id) const;
    void setJointSoftness(JointId id, const JointSoftness& softness);
    /// The value of the def's userData, or the last one set; pivot2d never reads it.
    std::uint64_t jointUserData(JointId id) const;
    void setJointUserData(JointId id, std::uint64_t userData);

    // --- mouse joints -------------------------------------------------------------------------
    MouseJointId createMouseJoint(const MouseJointDef& def);
    void destroyMouseJoint(MouseJointId id);
    bool isValid(MouseJointId id) const;
    /// Moves the target (m, world) and wakes the body.
    void setMouseTarget(MouseJointId id, Vec2 target);
    Vec2 mouseTarget(MouseJointId id) const;
    BodyId mouseJointBody(MouseJointId id) const;
    /// MouseJointDef::maxForce (N, > 0), hertz (> 0) and dampingRatio (>= 0), each at most
    /// kMaxMagnitude; the setters wake the body.
    float mouseJointMaxForce(MouseJointId id) const;
    void setMouseJointMaxForce(MouseJointId id, float force);
    float mouseJointHertz(MouseJointId id) const;
    float mouseJointDampingRatio(MouseJointId id) const;
    void setMouseJointSpring(MouseJointId id, float hertz, float dampingRatio);

    // --- debug drawing (pivot/debug_draw.h) ----------------------------------------------------
    /// Describes the world to `draw`: what `options` choose, shapes coloured by their body's
    /// state (debug_colors), in slot order. The drawing calls may read the world; a call that
    /// would change it throws pivot::Error from inside them.
    void debugDraw(DebugDraw& draw, const DebugDrawOptions& options = {}) const;
    /// Draws one body's shapes placed at `xf` rather than where the body is: at a pose between
    /// two steps (render interpolation), or, with the identity, in the body's own frame. The
    /// rotation must be a unit one (within kMaxRotationError): normalise an interpolated one.
    void debugDrawBody(BodyId id, const Transform& xf, DebugDraw& draw) const;

    // --- snapshots (docs/snapshots.md) ---------------------------------------------------------
    /// The whole state of the world as bytes: settings, bodies, shapes, joints, mouse joints,
    /// contacts with their manifolds and impulses, the broad phase, and the last step's events
    /// and statistics. Not in it: the worker count, the task system and the callbacks, which
    /// belong to the world a snapshot is restored into. The bytes are read by the same pivot2d
    /// version (format version 7), on a machine of the same float behaviour as stateHash needs.
    std::vector<std::uint8_t> snapshot() const;
    /// Replaces this world's state with a snapshot's, so that stepping on gives, bit for bit,
    /// what stepping the snapshotted world gives (the same stateHash at once and after any
    /// number of steps, on any worker count). Ids keep their index and generation and are
    /// stamped with this world: restoring a snapshot of this world's own lineage (a rollback),
    /// the ids a game held then work again; restoring any other, the world takes a new id and
    /// every id it issued before is refused from then on (take the new ones from bodyIds(),
    /// jointIds(), bodyShapes() or user data). Bytes that are not a pivot2d snapshot, of
    /// another format version, truncated or corrupted, or re-sealed with contents the reader
    /// refuses (docs/snapshots.md lists its checks), throw pivot::Error saying which, and the
    /// world is left unchanged. Restoring n bytes allocates at most 16 n bytes plus a few
    /// kilobytes; the steps after a restore allocate nothing once the world has stepped a
    /// state as large.
    void restore(const std::vector<std::uint8_t>& bytes);
    void restore(const std::uint8_t* data, std::size_t size);

    // --- inspection -------------------------------------------------------------------------
    /// A 64-bit hash of the exact bits of the state a snapshot holds (its lineage aside):
    /// everything that decides what later calls do and report, from the settings and every
    /// object's fields to the pools' generations and free lists (the ids to come), the broad
    /// phase's trees and the last step's events and statistics. Two worlds that hash alike give
    /// the same ids and bits to the same calls; a refused call leaves it unchanged. Values are
    /// not promised across compilers or CPUs.
    std::uint64_t stateHash() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace pivot
