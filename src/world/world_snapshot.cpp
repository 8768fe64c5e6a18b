// World::snapshot and World::restore (docs/snapshots.md): the whole world as bytes, read back so
// that stepping on continues bit for bit.
//
// Layout: an 8-byte magic "PIVOT2DS", the format version (u32), the payload's size (u64), the
// payload, and a 64-bit FNV-1a checksum of the payload. The payload is the settings, the five
// object pools slot by slot (generations and free lists included, so ids keep working and new
// objects get the slots they would have got), the broad phase's tree node for node, and the last
// step's events and statistics. Each part describes its fields once (the `describe` functions
// below, core/snapshot_io.h) for both writing and reading.
//
// Restoring decodes everything into new pools first and checks it: the header (foreign,
// version), the size (truncated), the checksum (corrupted), then every field as it is read and
// every link between objects (lists, edges, ids, the tree's leaves). Only a snapshot that passes
// all of that replaces the world's state, so a refused one changes nothing.
#include <algorithm>
#include <iterator>
#include <unordered_set>
#include <utility>
#include <variant>

#include "core/snapshot_io.h"
#include "world/world_impl.h"

namespace pivot {

namespace {

constexpr std::uint8_t kMagic[8] = {'P', 'I', 'V', 'O', 'T', '2', 'D', 'S'};
constexpr std::uint32_t kFormatVersion = 7;
constexpr std::size_t kHeaderSize = sizeof kMagic + 4 + 8;
constexpr std::size_t kChecksumSize = 8;
constexpr int kBodyTypes = 3;
constexpr int kShapeTypes = 5;
constexpr int kJointTypes = 9;
constexpr int kLetGoReasons = 4;
constexpr int kContactCorrections = 3;
constexpr int kManifoldTypes = 3;
constexpr int kContinuousCollisions = 2;

// What restore sizes by each pool's slots, per slot, for kSnapshotMemoryPerByte's count: the
// event lists, marks and island arrays a step fills (World::Impl::reserveEventBuffers,
// ContactManager::reserveForPools, Stepper::reserveStepBuffers, whose arrays are rounded up to a
// power of two), and the reader's checks. Measured by SnapshotMemory.RestoreTakesAtMostItsBound
// (tests/alloc), which holds restore to the bound.
constexpr std::size_t kSizedByBodies = 384;
constexpr std::size_t kSizedByShapes = 32;
constexpr std::size_t kSizedByJoints = 192;
constexpr std::size_t kSizedByContacts = 448;
constexpr std::size_t kSizedByMouseJoints = 64;

// --- field lists: B is the type or the const type (writing) ----------------------------------

template <typename Io, typename B>
void describeBody(Io& io, B& b) {
    io.enumValue(b.type, kBodyTypes);
    io.value(b.xf);
    io.value(b.localCenter);
    io.value(b.center);
    io.value(b.angle);
    io.value(b.linearVelocity);
    io.value(b.angularVelocity);
    io.value(b.force);
    io.value(b.torque);
    io.value(b.mass);
    io.value(b.invMass);
    io.value(b.inertia);
    io.value(b.invInertia);
    io.value(b.linearDamping);
    io.value(b.angularDamping);
    io.value(b.gravityScale);
    io.value(b.fixedRotation);
    io.value(b.userData);
    io.value(b.center0);
    io.value(b.angle0);
    io.value(b.alpha0);
    io.value(b.bullet);
    io.value(b.continuous);
    io.value(b.minExtent);
    io.value(b.maxExtent);
    io.value(b.shapeList);
    io.value(b.jointList);
    io.value(b.contactList);
    io.value(b.mouseList);
    io.value(b.shapeCount);
    io.value(b.islandIndex);
    io.value(b.awake);
    io.value(b.allowSleep);
    io.value(b.sleepTime);
    io.value(b.heldAtEdge);
    io.value(b.edgeReached);
    io.value(b.discarded);
}

template <typename Io, typename S>
void describeShape(Io& io, S& s) {
    io.value(s.body);
    io.enumValue(s.type, kShapeTypes);
    io.value(s.circle.center);
    io.value(s.circle.radius);
    for (auto& v : s.polygon.vertices) io.value(v);
    for (auto& n : s.polygon.normals) io.value(n);
    io.value(s.polygon.count);
    io.value(s.polygon.radius);
    io.value(s.polygon.centroid);
    io.value(s.ghost1);
    io.value(s.ghost2);
    io.value(s.density);
    io.value(s.friction);
    io.value(s.restitution);
    io.value(s.filter.categoryBits);
    io.value(s.filter.maskBits);
    io.value(s.filter.groupIndex);
    io.value(s.userData);
    io.value(s.sensor);
    io.value(s.hitEvents);
    io.value(s.preSolve);
    io.value(s.proxyId);
    io.value(s.box);
    io.value(s.prev);
    io.value(s.next);
    if constexpr (Io::kReading) {
        const int count = s.polygon.count;
        const bool round = s.type == ShapeType::Circle;
        const bool two = s.type != ShapeType::Polygon && !round;
        if (round ? count != 0 : two ? count != 2 : count < 3 || count > kMaxPolygonVertices) {
            io.corrupt("a shape of type " + std::to_string(int(s.type)) + " has " +
                       std::to_string(count) + " vertices");
        }
    }
}

template <typename Io, typename E>
void describeEdges(Io& io, E (&edges)[2]) {
    for (auto& e : edges) {
        io.value(e.body);
        io.value(e.prevKey);
        io.value(e.nextKey);
    }
}

template <typename Io, typename C>
void describeContact(Io& io, C& c) {
    describeEdges(io, c.edges);
    io.value(c.shapeA);
    io.value(c.shapeB);
    auto& m = c.manifold;
    for (auto& p : m.points) {
        io.value(p.localPoint);
        io.value(p.normalImpulse);
        io.value(p.tangentImpulse);
        io.value(p.approachSpeed);
        io.value(p.id);
    }
    io.value(m.localNormal);
    io.value(m.localPoint);
    io.enumValue(m.type, kManifoldTypes);
    io.value(m.pointCount);
    if constexpr (Io::kReading) {
        if (m.pointCount < 0 || m.pointCount > 2) io.corrupt("a manifold has a bad point count");
    }
    io.value(c.friction);
    io.value(c.restitution);
    io.value(c.touching);
    io.value(c.needsFiltering);
    io.value(c.sensor);
    io.value(c.enabled);
    io.value(c.serial);
    // Continuous collision's time of impact once lived here; it lasts only within a step, so
    // "none known" is written in its place (the format stays) and what is read is dropped.
    float toi = 1.0f;
    std::uint8_t toiCount = 0;
    bool toiKnown = false;
    bool toiDisabled = false;
    io.value(toi);
    io.value(toiCount);
    io.value(toiKnown);
    io.value(toiDisabled);
}

template <typename Io, typename Spring>
void describeSpring(Io& io, Spring& s) {
    io.value(s.enabled);
    io.value(s.hertz);
    io.value(s.dampingRatio);
}

// One per joint type, in the fields' declaration order.
template <typename Io, typename J>
void describeData(Io& io, J& j, const RevoluteJoint*) {
    io.value(j.enableLimit);
    io.value(j.lowerAngle);
    io.value(j.upperAngle);
    io.value(j.enableMotor);
    io.value(j.motorSpeed);
    io.value(j.maxMotorTorque);
    io.value(j.impulse);
    io.value(j.motorImpulse);
    io.value(j.lowerImpulse);
    io.value(j.upperImpulse);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const DistanceJoint*) {
    io.value(j.length);
    io.value(j.enableLimit);
    io.value(j.minLength);
    io.value(j.maxLength);
    io.value(j.enableSpring);
    io.value(j.hertz);
    io.value(j.dampingRatio);
    io.value(j.impulse);
    io.value(j.lowerImpulse);
    io.value(j.upperImpulse);
    io.value(j.axis);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const PulleyJoint*) {
    io.value(j.groundAnchorA);
    io.value(j.groundAnchorB);
    io.value(j.lengthA);
    io.value(j.lengthB);
    io.value(j.ratio);
    io.value(j.impulse);
    io.value(j.axisB);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const FrictionJoint*) {
    io.value(j.maxForce);
    io.value(j.maxTorque);
    io.value(j.linearImpulse);
    io.value(j.angularImpulse);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const MotorJoint*) {
    io.value(j.linearOffset);
    io.value(j.angularOffset);
    io.value(j.maxForce);
    io.value(j.maxTorque);
    io.value(j.correctionFactor);
    io.value(j.linearImpulse);
    io.value(j.angularImpulse);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const PrismaticJoint*) {
    io.value(j.localAxisA);
    io.value(j.enableLimit);
    io.value(j.lowerTranslation);
    io.value(j.upperTranslation);
    io.value(j.enableMotor);
    io.value(j.motorSpeed);
    io.value(j.maxMotorForce);
    io.value(j.enableSpring);
    io.value(j.hertz);
    io.value(j.dampingRatio);
    io.value(j.impulse);
    io.value(j.motorImpulse);
    io.value(j.lowerImpulse);
    io.value(j.upperImpulse);
    io.value(j.springImpulse);
    io.value(j.axis);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const WeldJoint*) {
    describeSpring(io, j.linearSpring);
    describeSpring(io, j.angularSpring);
    io.value(j.impulse.x);
    io.value(j.impulse.y);
    io.value(j.impulse.z);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const WheelJoint*) {
    io.value(j.localAxisA);
    describeSpring(io, j.spring);
    io.value(j.enableLimit);
    io.value(j.lowerTranslation);
    io.value(j.upperTranslation);
    io.value(j.enableMotor);
    io.value(j.motorSpeed);
    io.value(j.maxMotorTorque);
    io.value(j.impulse);
    io.value(j.springImpulse);
    io.value(j.lowerImpulse);
    io.value(j.upperImpulse);
    io.value(j.motorImpulse);
    io.value(j.axis);
}
template <typename Io, typename Side>
void describeGearSide(Io& io, Side& s) {
    io.value(s.prismatic);
    io.value(s.joint);
    io.value(s.base);
    io.value(s.localAnchorBase);
    io.value(s.localAnchorMover);
    io.value(s.localAxis);
    io.value(s.referenceAngle);
}
template <typename Io, typename J>
void describeData(Io& io, J& j, const GearJoint*) {
    describeGearSide(io, j.side1);
    describeGearSide(io, j.side2);
    io.value(j.ratio);
    io.value(j.constant);
    io.value(j.impulse);
    io.value(j.linearB);
    io.value(j.angularB);
}

// The alternative of JointData for a type, default-constructed.
template <std::size_t... I>
JointData jointDataOfType(JointType type, std::index_sequence<I...>) {
    JointData data;
    ((static_cast<std::size_t>(type) == I ? (data.template emplace<I>(), 0) : 0), ...);
    return data;
}

template <typename Io, typename J>
void describeJoint(Io& io, J& j) {
    describeEdges(io, j.edges);
    io.value(j.localAnchorA);
    io.value(j.localAnchorB);
    io.value(j.referenceAngle);
    io.enumValue(j.solver, kPositionSolverCount);
    io.value(j.hasBiasOverride);
    io.value(j.biasOverride);
    io.value(j.extraPositionIterations);
    if constexpr (Io::kReading) {
        // A count the setter refuses would stall the step (kMaxIterations).
        if (j.extraPositionIterations < 0 || j.extraPositionIterations > kMaxIterations) {
            io.corrupt("a joint's extra position iterations are " +
                       std::to_string(j.extraPositionIterations));
        }
    }
    io.value(j.softness.hertz);
    io.value(j.softness.dampingRatio);
    io.value(j.softness.compliance);
    io.value(j.collideConnected);
    io.value(j.userData);
    JointType type = j.type();
    io.enumValue(type, kJointTypes);
    if constexpr (Io::kReading) {
        j.data = jointDataOfType(type, std::make_index_sequence<std::variant_size_v<JointData>>{});
    }
    std::visit(
        [&](auto& data) {
            using Data = std::decay_t<decltype(data)>;
            describeData(io, data, static_cast<const Data*>(nullptr));
        },
        j.data);
    io.value(j.impulseInvDt);
    io.value(j.letGo);
    io.enumValue(j.letGoReason, kLetGoReasons);
    io.value(j.letGoAt);
    io.value(j.letGoReaction);
    io.value(j.breakForce);
    io.value(j.breakTorque);
    io.value(j.hasLetGoOverride);
    io.value(j.letGoOverride);
    io.value(j.gearCount);
}

template <typename Io, typename M>
void describeMouse(Io& io, M& m) {
    io.value(m.body);
    io.value(m.next);
    io.value(m.localAnchor);
    io.value(m.target);
    io.value(m.maxForce);
    io.value(m.hertz);
    io.value(m.dampingRatio);
    io.value(m.impulse);
}

// Everything of the world but the contact manager's part, in one struct so that restore can
// decode into it and check it before anything of the world changes.
struct WorldState {
    WorldSettings settings;
    float previousInvDt = 0.0f;
    SlotPool<Body> bodies;
    SlotPool<Shape> shapes;
    SlotPool<Joint> joints;
    SlotPool<Contact> contacts;
    SlotPool<MouseJoint> mouseJoints;
    std::vector<JointLetGoEvent> letGoEvents;
    std::vector<WorldEdgeEvent> edgeEvents;
    std::vector<BodyId> discarded;
    std::vector<ContactHitEvent> hitEvents;
    std::vector<BodyMoveEvent> moveEvents;
    StepStats stats;
};

// The settings, scalars, pools and the world's event lists; W is World::Impl or WorldState.
template <typename Io, typename W>
void describeWorld(Io& io, W& w, std::uint32_t worldId) {
    io.value(w.settings.gravity);
    io.enumValue(w.settings.defaultPositionSolver, kPositionSolverCount);
    io.value(w.settings.warmStarting);
    io.enumValue(w.settings.contactCorrection, kContactCorrections);
    io.value(w.settings.contactBiasFactor);
    io.value(w.settings.contactHertz);
    io.value(w.settings.contactDampingRatio);
    io.value(w.settings.contactPushSpeed);
    io.value(w.settings.restitutionThreshold);
    io.value(w.settings.enableSleep);
    io.value(w.settings.enableContinuous);
    io.enumValue(w.settings.continuousCollision, kContinuousCollisions);
    io.value(w.settings.jointLetGoSeparation);
    io.value(w.settings.substepCount);
    io.value(w.settings.velocityIterations);
    io.value(w.settings.positionIterations);
    io.value(w.settings.hitEventThreshold);
    io.value(w.previousInvDt);
    using Bodies = std::remove_reference_t<decltype(w.bodies)>;
    using Shapes = std::remove_reference_t<decltype(w.shapes)>;
    using Joints = std::remove_reference_t<decltype(w.joints)>;
    using Contacts = std::remove_reference_t<decltype(w.contacts)>;
    using Mice = std::remove_reference_t<decltype(w.mouseJoints)>;
    // Each slot costs restore the decoded slot, the world's copy and what is sized by the pools.
    Bodies::describe(
        io, w.bodies, [](Io& o, auto& b) { describeBody(o, b); },
        sizeof(typename Bodies::Slot) + kSizedByBodies);
    Shapes::describe(
        io, w.shapes, [](Io& o, auto& s) { describeShape(o, s); },
        sizeof(typename Shapes::Slot) + kSizedByShapes);
    Joints::describe(
        io, w.joints, [](Io& o, auto& j) { describeJoint(o, j); },
        sizeof(typename Joints::Slot) + kSizedByJoints);
    Contacts::describe(
        io, w.contacts, [](Io& o, auto& c) { describeContact(o, c); },
        sizeof(typename Contacts::Slot) + kSizedByContacts);
    Mice::describe(
        io, w.mouseJoints, [](Io& o, auto& m) { describeMouse(o, m); },
        sizeof(typename Mice::Slot) + kSizedByMouseJoints);

    io.sequence(w.letGoEvents, [&](auto& e) {
        snapshotHandle(io, e.joint, worldId);
        io.enumValue(e.reason, kLetGoReasons);
        io.value(e.separation);
        io.value(e.reaction);
    });
    io.sequence(w.edgeEvents, [&](auto& e) {
        snapshotHandle(io, e.body, worldId);
        io.value(e.reached);
    });
    io.sequence(w.discarded, [&](auto& b) { snapshotHandle(io, b, worldId); });
    io.sequence(w.hitEvents, [&](auto& e) {
        snapshotHandle(io, e.shapeA, worldId);
        snapshotHandle(io, e.shapeB, worldId);
        io.value(e.point);
        io.value(e.normal);
        io.value(e.approachSpeed);
    });
    io.sequence(w.moveEvents, [&](auto& e) {
        snapshotHandle(io, e.body, worldId);
        io.value(e.transform);
        io.value(e.fellAsleep);
    });
    auto& s = w.stats;
    for (auto* value :
         {&s.islandCount, &s.bodyCount, &s.jointCount, &s.translationClamps, &s.rotationClamps,
          &s.positionIterations, &s.extraPositionSolves, &s.contactCount, &s.touchingCount, &s.sleepingBodyCount,
          &s.letGoJointCount, &s.discardedBodyCount, &s.edgeBodyCount, &s.impactCount}) {
        io.value(*value);
    }
}

// --- the links between objects, checked before a decoded world is taken ---------------------

// Walks a body's edge list (joints or contacts), checking each key names a live owner whose
// edge on that side is this body and links back; marks each edge seen once.
template <typename T>
void checkEdgeList(SnapshotReader& in, std::int32_t body, std::int32_t head,
                   const SlotPool<T>& pool, std::vector<std::uint8_t>& seen, const char* what) {
    std::int32_t previous = -1;
    for (std::int32_t key = head; key != -1;) {
        const std::int32_t owner = edgeOwner(key);
        const int side = edgeSide(key);
        if (key < 0 || !pool.isAlive(owner))
            in.corrupt(std::string("a ") + what + " list is broken");
        const BodyEdge& edge = pool[owner].edges[side];
        std::uint8_t& mark = seen[static_cast<std::size_t>(key)];
        if (edge.body != body || edge.prevKey != previous || mark) {
            in.corrupt(std::string("a ") + what + " list does not match its edges");
        }
        mark = 1;
        previous = key;
        key = edge.nextKey;
    }
}

// A body lists its contacts newest first, as they were made: the island search relies on it
// (island_builder.h), and the contacts to come must be newer than every one there is.
void checkContactOrder(SnapshotReader& in, const WorldState& w, std::int32_t head,
                       std::uint64_t contactsMade) {
    std::uint64_t newer = contactsMade + 1;
    for (std::int32_t key = head; key != -1;) {
        const Contact& contact = w.contacts[edgeOwner(key)];
        if (contact.serial >= newer) in.corrupt("a contact list is out of its making order");
        newer = contact.serial;
        key = contact.edges[edgeSide(key)].nextKey;
    }
}

// A gear is made from two live revolute or prismatic joints, and copies what it needs of them
// (gear_joint.h): its bodies are their moving bodies (B), its sides' bases their bodies A, its
// anchors, axes and reference angles theirs. The island search and the solver rely on it: a
// base that is not its joint's body A may be a body of another island.
void checkGear(SnapshotReader& in, const WorldState& w, std::int32_t index, const Joint& joint,
               const GearJoint& gear) {
    if (gear.side1.joint == gear.side2.joint) in.corrupt("a gear joint couples a joint to itself");
    const std::int32_t movers[2] = {joint.bodyA(), joint.bodyB()};
    const Vec2 moverAnchors[2] = {joint.localAnchorA, joint.localAnchorB};
    int k = 0;
    for (const GearSide* side : {&gear.side1, &gear.side2}) {
        const std::int32_t m = movers[k];
        const Vec2 moverAnchor = moverAnchors[k++];
        if (!w.joints.isAlive(side->joint) || side->joint == index) {
            in.corrupt("a gear joint names a joint it cannot be built on");
        }
        const Joint& on = w.joints[side->joint];
        const JointType expected = side->prismatic ? JointType::Prismatic : JointType::Revolute;
        if (on.type() != expected) in.corrupt("a gear joint names a joint it cannot be built on");
        if (side->base != on.bodyA() || m != on.bodyB()) {
            in.corrupt("a gear joint's bodies are not those of the joints it couples");
        }
        const bool axisKept =
            !side->prismatic || side->localAxis == std::get<PrismaticJoint>(on.data).localAxisA;
        if (side->localAnchorBase != on.localAnchorA || side->localAnchorMover != on.localAnchorB ||
            moverAnchor != on.localAnchorB || side->referenceAngle != on.referenceAngle ||
            !axisKept) {
            in.corrupt("a gear joint's copy of a joint it couples differs from the joint");
        }
    }
}

// A contact is one the contact manager could have made (ContactManager::addPair): its shapes
// in the narrow phase's order (segments first, circles last; two segments never), marked a
// sensor contact exactly when a shape is a sensor, and, unless it waits to be filtered again,
// between bodies that may collide (a solid contact needs a dynamic body, a sensor a non-static
// one).
void checkContactPair(SnapshotReader& in, const WorldState& w, const Contact& contact) {
    const Shape& a = w.shapes[contact.shapeA];
    const Shape& b = w.shapes[contact.shapeB];
    auto order = [](ShapeType type) {
        return isSegmentLike(type) ? 0 : type == ShapeType::Circle ? 2 : 1;
    };
    if (order(a.type) > order(b.type) || (isSegmentLike(a.type) && isSegmentLike(b.type))) {
        in.corrupt("a contact's shapes are of types no contact is made of, or out of order");
    }
    if (contact.sensor != (a.sensor || b.sensor) || (a.sensor && b.sensor)) {
        in.corrupt("a contact's sensor flag does not match its shapes");
    }
    if (contact.needsFiltering) return;
    const BodyType typeA = w.bodies[a.body].type;
    const BodyType typeB = w.bodies[b.body].type;
    const bool mayTouch = contact.sensor ? typeA != BodyType::Static || typeB != BodyType::Static
                                         : typeA == BodyType::Dynamic || typeB == BodyType::Dynamic;
    if (!mayTouch) in.corrupt("a contact joins bodies that cannot collide");
}

void checkLinks(SnapshotReader& in, const WorldState& w, const BroadPhase& broadPhase,
                std::uint64_t contactsMade) {
    std::vector<std::uint8_t> shapeSeen(static_cast<std::size_t>(w.shapes.capacity()), 0);
    std::vector<std::uint8_t> proxySeen(broadPhase.indexBound(), 0);
    std::vector<std::uint8_t> jointEdges(2 * static_cast<std::size_t>(w.joints.capacity()), 0);
    std::vector<std::uint8_t> contactEdges(2 * static_cast<std::size_t>(w.contacts.capacity()), 0);
    std::vector<std::uint8_t> mouseSeen(static_cast<std::size_t>(w.mouseJoints.capacity()), 0);
    w.bodies.forEach([&](std::int32_t b, const Body& body) {
        std::int32_t previous = -1;
        std::int32_t count = 0;
        for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
            if (!w.shapes.isAlive(s) || shapeSeen[static_cast<std::size_t>(s)] ||
                w.shapes[s].body != b || w.shapes[s].prev != previous) {
                in.corrupt("a body's shape list is broken");
            }
            shapeSeen[static_cast<std::size_t>(s)] = 1;
            previous = s;
            ++count;
        }
        if (count != body.shapeCount) in.corrupt("a body's shape count is wrong");
        checkEdgeList(in, b, body.jointList, w.joints, jointEdges, "joint");
        checkEdgeList(in, b, body.contactList, w.contacts, contactEdges, "contact");
        checkContactOrder(in, w, body.contactList, contactsMade);
        for (std::int32_t m = body.mouseList; m != -1; m = w.mouseJoints[m].next) {
            if (!w.mouseJoints.isAlive(m) || mouseSeen[static_cast<std::size_t>(m)] ||
                w.mouseJoints[m].body != b) {
                in.corrupt("a body's mouse joint list is broken");
            }
            mouseSeen[static_cast<std::size_t>(m)] = 1;
        }
    });
    int proxies = 0;
    w.shapes.forEach([&](std::int32_t s, const Shape& shape) {
        if (!shapeSeen[static_cast<std::size_t>(s)]) in.corrupt("a shape is on no body's list");
        const std::int32_t proxy = shape.proxyId;
        if (!broadPhase.isProxy(proxy) || broadPhase.userData(proxy) != s ||
            proxySeen[broadPhase.indexOf(proxy)]) {
            in.corrupt("a shape's broad-phase proxy is wrong");
        }
        // The tree a proxy is in decides whom it is paired with.
        const bool staticTree = (proxy & BroadPhase::kStaticTag) != 0;
        if (staticTree != (broadPhase.boxes() == BroadPhaseBoxes::Compact &&
                           w.bodies[shape.body].type == BodyType::Static)) {
            in.corrupt("a shape's broad-phase proxy is in the wrong tree");
        }
        proxySeen[broadPhase.indexOf(proxy)] = 1;
        ++proxies;
    });
    if (proxies != broadPhase.proxyCount()) in.corrupt("the broad phase has proxies of no shape");
    auto bothEdgesSeen = [](const std::vector<std::uint8_t>& seen, std::int32_t index) {
        return seen[2 * static_cast<std::size_t>(index)] &&
               seen[2 * static_cast<std::size_t>(index) + 1];
    };
    std::vector<std::int32_t> gearsOn(static_cast<std::size_t>(w.joints.capacity()), 0);
    w.joints.forEach([&](std::int32_t j, const Joint& joint) {
        if (!bothEdgesSeen(jointEdges, j) || joint.bodyA() == joint.bodyB()) {
            in.corrupt("a joint is not on its bodies' lists");
        }
        if (const auto* gear = std::get_if<GearJoint>(&joint.data)) {
            checkGear(in, w, j, joint, *gear);
            ++gearsOn[static_cast<std::size_t>(gear->side1.joint)];
            ++gearsOn[static_cast<std::size_t>(gear->side2.joint)];
        }
    });
    w.joints.forEach([&](std::int32_t j, const Joint& joint) {
        if (joint.gearCount != gearsOn[static_cast<std::size_t>(j)]) {
            in.corrupt("a joint's gear count is wrong");
        }
    });
    std::unordered_set<std::uint64_t> pairs;
    w.contacts.forEach([&](std::int32_t c, const Contact& contact) {
        if (!bothEdgesSeen(contactEdges, c)) in.corrupt("a contact is not on its bodies' lists");
        const bool shapesLive = w.shapes.isAlive(contact.shapeA) &&
                                w.shapes.isAlive(contact.shapeB) &&
                                contact.shapeA != contact.shapeB;
        if (!shapesLive || w.shapes[contact.shapeA].body != contact.bodyA() ||
            w.shapes[contact.shapeB].body != contact.bodyB() ||
            !pairs.insert(PairMap::key(contact.shapeA, contact.shapeB)).second) {
            in.corrupt("a contact's shapes do not match its bodies");
        }
        checkContactPair(in, w, contact);
    });
    w.mouseJoints.forEach([&](std::int32_t m, const MouseJoint&) {
        if (!mouseSeen[static_cast<std::size_t>(m)]) in.corrupt("a mouse joint is on no list");
    });
}

// The state: everything of the world that decides what later calls do and report, as the
// snapshot's payload holds it after its lineage. stateHash hashes exactly this.
void describeState(SnapshotWriter& out, const World::Impl& w) {
    describeWorld(out, w, w.id);
    w.contactManager.saveState(out);
}

}  // namespace

std::vector<std::uint8_t> World::snapshot() const {
    impl_->requireRead("World::snapshot");
    const Impl& w = *impl_;
    SnapshotWriter payload;
    // The lineage: the world whose ids the snapshot's ids are (World::restore).
    payload.value(w.id);
    describeState(payload, w);
    payload.padding();

    SnapshotWriter out;
    out.raw(kMagic, sizeof kMagic);
    out.value(kFormatVersion);
    out.value(static_cast<std::uint64_t>(payload.size()));
    out.raw(payload.data(), payload.size());
    out.value(snapshotChecksum(payload.data(), payload.size()));
    return out.take();
}

// A hash of the state a snapshot holds (its lineage aside): two worlds that hash alike take the
// same calls to the same results, ids included (docs/snapshots.md, "What the hash covers").
std::uint64_t World::stateHash() const {
    impl_->requireRead("World::stateHash");
    SnapshotWriter state(SnapshotWriter::Sink::Hash);
    describeState(state, *impl_);
    return state.hash();
}

void World::restore(const std::vector<std::uint8_t>& bytes) {
    restore(bytes.data(), bytes.size());
}

void World::restore(const std::uint8_t* data, std::size_t size) {
    const char* call = "World::restore";
    Impl& w = *impl_;
    w.requireStructureChange(call);
    if (data == nullptr && size != 0) fail(call, "data is null");
    if (size < sizeof kMagic || !std::equal(std::begin(kMagic), std::end(kMagic), data)) {
        fail(call, "these bytes are not a pivot2d snapshot (they do not start with \"PIVOT2DS\")");
    }
    SnapshotReader header(call, data + sizeof kMagic, size - sizeof kMagic);
    std::uint32_t version = 0;
    std::uint64_t payloadSize = 0;
    header.value(version);
    if (version != kFormatVersion) {
        fail(call, "the snapshot is of format version " + std::to_string(version) +
                       "; this pivot2d reads version " + std::to_string(kFormatVersion));
    }
    header.value(payloadSize);
    if (payloadSize > size - kHeaderSize || size - kHeaderSize - payloadSize < kChecksumSize) {
        fail(call, "the snapshot is truncated: " + std::to_string(size) +
                       " bytes, its header says " +
                       std::to_string(kHeaderSize + payloadSize + kChecksumSize));
    }
    if (size - kHeaderSize - payloadSize > kChecksumSize) {
        fail(call, "the snapshot has " +
                       std::to_string(size - kHeaderSize - payloadSize - kChecksumSize) +
                       " bytes after its end");
    }
    const std::uint8_t* payload = data + kHeaderSize;
    const auto length = static_cast<std::size_t>(payloadSize);
    SnapshotReader trailer(call, payload + length, kChecksumSize);
    std::uint64_t checksum = 0;
    trailer.value(checksum);
    if (checksum != snapshotChecksum(payload, length)) {
        fail(call, "the snapshot is corrupted: its checksum does not match its contents");
    }

    SnapshotReader in(call, payload, length);
    // A snapshot of this world's own lineage brings its ids back (a rollback). Any other takes
    // the world to a new id, so that no id this world issued before can name what it restores.
    std::uint32_t lineage = 0;
    in.value(lineage);
    const std::uint32_t stamp = lineage == w.id ? w.id : newWorldId(call);
    WorldState state;
    describeWorld(in, state, stamp);
    ContactManager::State contactState = ContactManager::loadState(in, stamp);
    in.padding();
    if (!in.atEnd()) in.corrupt("bytes are left over after the last field");
    // Each setting by the rule its setter keeps, so that the world never reports a value its
    // setter would refuse (world_settings.h).
    checkSettings(call, "the snapshot's ", state.settings);
    // 1/h of the last step: 0 before the first step, else within the time step's limits.
    if (state.previousInvDt != 0.0f && !(state.previousInvDt >= 1.0f / kMaxTimeStep &&
                                         state.previousInvDt <= 1.0f / kMinTimeStep)) {
        in.corrupt("the last step's 1/dt is " + formatFloat(state.previousInvDt));
    }
    checkLinks(in, state, contactState.broadPhase, contactState.contactsMade);

    // Checked: take it. Nothing below can fail (but for running out of memory).
    w.id = stamp;
    w.settings = state.settings;
    w.previousInvDt = state.previousInvDt;
    // Copied into the world's storage, which keeps its capacity, rather than moved: the steps
    // of a rollback (restore, step, restore, ...) find every buffer as warm as before.
    w.bodies = state.bodies;
    w.shapes = state.shapes;
    w.joints = state.joints;
    w.contacts = state.contacts;
    // Not in the snapshot: they follow from the shapes, checked above.
    w.contacts.forEach([&](std::int32_t, Contact& c) {
        c.radiusA = collisionRadius(w.shapes[c.shapeA]);
        c.radiusB = collisionRadius(w.shapes[c.shapeB]);
    });
    w.mouseJoints = state.mouseJoints;
    w.letGoEvents = state.letGoEvents;
    w.edgeEvents = state.edgeEvents;
    w.discarded = state.discarded;
    w.hitEvents = state.hitEvents;
    w.moveEvents = state.moveEvents;
    w.stats = state.stats;
    w.hitEventShapeCount = 0;
    w.shapes.forEach([&](std::int32_t, const Shape& s) { w.hitEventShapeCount += s.hitEvents; });
    w.contactManager.adoptState(contactState);
    // What a step sizes by the pools, sized now for the snapshot's pools.
    w.reserveEventBuffers();
    w.stepper.reserveStepBuffers(SolverStorage{w.bodies, w.shapes, w.joints, w.contacts,
                                               w.contactManager.census(), w.mouseJoints,
                                               w.islandRevision});
    w.islandRevision.bump();
}

}  // namespace pivot
