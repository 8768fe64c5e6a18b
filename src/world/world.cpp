// The World facade, part one: lifetime, stepping, world-wide settings and the state hash.
// Every public call checks its input completely before it changes anything, and a failed
// check throws pivot::Error.
#include <atomic>
#include <cmath>
#include <string>

#include "core/state_hash.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

namespace {
// Ids 1 to 2^32 - 1, each once per process (0 marks a null handle): a repeated id would let a
// handle kept from a destroyed world name an object of a new one, so the counter never wraps.
std::uint32_t nextWorldId() {
    static std::atomic<std::uint64_t> counter{0};
    const std::uint64_t id = ++counter;
    if (id > 0xFFFFFFFFull) {
        fail("World::World", "this process has made 2^32 - 1 worlds, every id a handle can carry");
    }
    return static_cast<std::uint32_t>(id);
}
}  // namespace

World::Impl::Impl(const WorldDef& def)
    : id(nextWorldId()),
      gravity(def.gravity),
      defaultPositionSolver(def.defaultPositionSolver),
      warmStarting(def.warmStarting),
      contactCorrection(def.contactCorrection),
      contactBiasFactor(def.contactBiasFactor),
      restitutionThreshold(def.restitutionThreshold),
      enableSleep(def.enableSleep),
      jointLetGoSeparation(def.jointLetGoSeparation),
      pool(def.workerCount),
      workspaces(static_cast<std::size_t>(def.workerCount)) {}

std::int32_t World::Impl::bodyIndex(const char* call, BodyId id) const {
    return checkHandle(call, "body", id, bodies, this->id);
}
std::int32_t World::Impl::shapeIndex(const char* call, ShapeId id) const {
    return checkHandle(call, "shape", id, shapes, this->id);
}
std::int32_t World::Impl::jointIndex(const char* call, JointId id) const {
    return checkHandle(call, "joint", id, joints, this->id);
}
std::int32_t World::Impl::mouseJointIndex(const char* call, MouseJointId id) const {
    return checkHandle(call, "mouse joint", id, mouseJoints, this->id);
}

void World::Impl::wakeAll() {
    bodies.forEach([](std::int32_t, Body& b) { wakeUp(b); });
}

World::World(const WorldDef& def) {
    const char* call = "World::World";
    requireWithin(call, "def.gravity", def.gravity, kMaxGravity, "kMaxGravity");
    checkSolver(call, "def.defaultPositionSolver", def.defaultPositionSolver);
    checkContactCorrection(call, "def.contactCorrection", def.contactCorrection);
    requireInRange(call, "def.contactBiasFactor", def.contactBiasFactor, 0.0f, 1.0f);
    requireNonNegative(call, "def.restitutionThreshold", def.restitutionThreshold);
    requireNonNegative(call, "def.jointLetGoSeparation", def.jointLetGoSeparation);
    if (def.workerCount < 1 || def.workerCount > 64) {
        fail(call,
             "def.workerCount must be in [1, 64] (got " + std::to_string(def.workerCount) + ")");
    }
    // bool fields need no check: any value is meaningful.
    impl_ = std::make_unique<Impl>(def);
}

World::~World() = default;

void World::step(float dt, int velocityIterations, int positionIterations) {
    const char* call = "World::step";
    // Not requireFinite: a denormal dt is one more step too short, and is told so.
    if (!std::isfinite(dt)) fail(call, "dt must be finite (got " + formatFloat(dt) + ")");
    if (dt < kMinTimeStep) {
        fail(call, "dt must be >= kMinTimeStep (" + formatFloat(kMinTimeStep) +
                       " s); skip the step or carry the time over (got " + formatFloat(dt) + ")");
    }
    if (dt > kMaxTimeStep) {
        fail(call, "dt must be <= kMaxTimeStep (" + formatFloat(kMaxTimeStep) + " s) (got " +
                       formatFloat(dt) + ")");
    }
    auto checkIterations = [&](const char* field, int value) {
        if (value < 0 || value > kMaxIterations) {
            fail(call, std::string(field) + " must be in [0, " + std::to_string(kMaxIterations) +
                           "] (got " + std::to_string(value) + ")");
        }
    };
    checkIterations("velocityIterations", velocityIterations);
    checkIterations("positionIterations", positionIterations);
    impl_->step(dt, velocityIterations, positionIterations);
}

const StepStats& World::lastStepStats() const {
    return impl_->stats;
}

std::vector<WorldEdgeEvent> World::worldEdgeEvents() const {
    return impl_->edgeEvents;
}

std::vector<BodyId> World::discardedBodies() const {
    return impl_->discarded;
}

Vec2 World::gravity() const {
    return impl_->gravity;
}

void World::setGravity(Vec2 gravity) {
    requireWithin("World::setGravity", "gravity", gravity, kMaxGravity, "kMaxGravity");
    impl_->gravity = gravity;
    impl_->wakeAll();
}

PositionSolver World::defaultPositionSolver() const {
    return impl_->defaultPositionSolver;
}

ContactCorrection World::contactCorrection() const {
    return impl_->contactCorrection;
}

void World::setContactCorrection(ContactCorrection correction) {
    checkContactCorrection("World::setContactCorrection", "correction", correction);
    impl_->contactCorrection = correction;
}

void World::setSleepEnabled(bool enabled) {
    impl_->enableSleep = enabled;
    if (!enabled) impl_->wakeAll();
}

bool World::isSleepEnabled() const {
    return impl_->enableSleep;
}

// Everything a public call can change goes in, so that "the hash is unchanged" means "the world
// is unchanged": settings, every field of every object (derived ones too, such as the inverse
// mass, so that a forgotten recomputation shows), the list links, the broad phase's boxes, the
// contacts with their manifolds, and what the last step reported. Only scratch buffers that
// every step rebuilds are left out.
std::uint64_t World::stateHash() const {
    const Impl& w = *impl_;
    StateHasher h;
    h.add(w.gravity);
    h.add(static_cast<std::int32_t>(w.defaultPositionSolver));
    h.add(w.warmStarting);
    h.add(static_cast<std::int32_t>(w.contactCorrection));
    h.add(w.contactBiasFactor);
    h.add(w.restitutionThreshold);
    h.add(w.enableSleep);
    h.add(w.jointLetGoSeparation);
    h.add(w.previousInvDt);
    h.add(w.newShapes);

    h.add(w.bodies.size());
    w.bodies.forEach([&](std::int32_t index, const Body& b) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.bodies.generation(index)));
        h.add(static_cast<std::int32_t>(b.type));
        h.add(b.xf);
        h.add(b.localCenter);
        h.add(b.center);
        h.add(b.angle);
        h.add(b.linearVelocity);
        h.add(b.angularVelocity);
        h.add(b.force);
        h.add(b.torque);
        h.add(b.mass);
        h.add(b.invMass);
        h.add(b.inertia);
        h.add(b.invInertia);
        h.add(b.linearDamping);
        h.add(b.angularDamping);
        h.add(b.gravityScale);
        h.add(b.fixedRotation);
        h.add(b.userData);
        h.add(b.shapeList);
        h.add(b.jointList);
        h.add(b.contactList);
        h.add(b.mouseList);
        h.add(b.shapeCount);
        h.add(b.awake);
        h.add(b.allowSleep);
        h.add(b.sleepTime);
    });
    h.add(w.shapes.size());
    w.shapes.forEach([&](std::int32_t index, const Shape& s) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.shapes.generation(index)));
        h.add(s.body);
        h.add(static_cast<std::int32_t>(s.type));
        if (s.type == ShapeType::Circle) {
            h.add(s.circle.center);
            h.add(s.circle.radius);
        } else {
            h.add(s.polygon.count);
            for (int i = 0; i < s.polygon.count; ++i) h.add(s.polygon.vertices[i]);
        }
        h.add(s.density);
        h.add(s.friction);
        h.add(s.restitution);
        h.add(static_cast<std::int32_t>(s.filter.categoryBits | (s.filter.maskBits << 16)));
        h.add(static_cast<std::int32_t>(s.filter.groupIndex));
        h.add(s.userData);
        h.add(s.prev);
        h.add(s.next);
        const AABB& box = w.broadPhase.fatBox(s.proxyId);
        h.add(box.lower);
        h.add(box.upper);
    });
    h.add(w.joints.size());
    w.joints.forEach([&](std::int32_t index, const RevoluteJoint& j) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.joints.generation(index)));
        for (const BodyEdge& e : j.edges) {
            h.add(e.body);
            h.add(e.prevKey);
            h.add(e.nextKey);
        }
        h.add(j.localAnchorA);
        h.add(j.localAnchorB);
        h.add(j.referenceAngle);
        h.add(static_cast<std::int32_t>(j.solver));
        h.add(j.hasBiasOverride);
        h.add(j.biasOverride);
        h.add(j.collideConnected);
        h.add(j.userData);
        h.add(j.enableLimit);
        h.add(j.lowerAngle);
        h.add(j.upperAngle);
        h.add(j.enableMotor);
        h.add(j.motorSpeed);
        h.add(j.maxMotorTorque);
        h.add(j.impulse);
        h.add(j.motorImpulse);
        h.add(j.lowerImpulse);
        h.add(j.upperImpulse);
        h.add(j.impulseInvDt);
        h.add(j.letGo);
        h.add(static_cast<std::int32_t>(j.letGoReason));
        h.add(j.letGoAt);
        h.add(j.hasLetGoOverride);
        h.add(j.letGoOverride);
    });
    h.add(w.mouseJoints.size());
    w.mouseJoints.forEach([&](std::int32_t index, const MouseJoint& m) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.mouseJoints.generation(index)));
        h.add(m.body);
        h.add(m.next);
        h.add(m.localAnchor);
        h.add(m.target);
        h.add(m.maxForce);
        h.add(m.hertz);
        h.add(m.dampingRatio);
        h.add(m.impulse);
    });
    h.add(w.contacts.size());
    w.contacts.forEach([&](std::int32_t index, const Contact& c) {
        h.add(index);
        for (const BodyEdge& e : c.edges) {
            h.add(e.body);
            h.add(e.prevKey);
            h.add(e.nextKey);
        }
        h.add(c.shapeA);
        h.add(c.shapeB);
        h.add(c.friction);
        h.add(c.restitution);
        h.add(c.touching);
        h.add(c.needsFiltering);
        const Manifold& m = c.manifold;
        h.add(static_cast<std::int32_t>(m.type));
        h.add(m.localNormal);
        h.add(m.localPoint);
        h.add(m.pointCount);
        for (int i = 0; i < m.pointCount; ++i) {
            h.add(m.points[i].localPoint);
            h.add(m.points[i].normalImpulse);
            h.add(m.points[i].tangentImpulse);
            h.add(static_cast<std::int32_t>(m.points[i].id));
        }
    });
    for (const std::vector<ContactEvent>* events : {&w.beginEvents, &w.endEvents}) {
        h.add(static_cast<std::int32_t>(events->size()));
        for (const ContactEvent& e : *events) {
            h.add(e.shapeA.index);
            h.add(static_cast<std::int32_t>(e.shapeA.generation));
            h.add(e.shapeB.index);
            h.add(static_cast<std::int32_t>(e.shapeB.generation));
        }
    }
    h.add(static_cast<std::int32_t>(w.letGoEvents.size()));
    for (const JointLetGoEvent& e : w.letGoEvents) {
        h.add(e.joint.index);
        h.add(static_cast<std::int32_t>(e.joint.generation));
        h.add(static_cast<std::int32_t>(e.reason));
        h.add(e.separation);
    }
    h.add(static_cast<std::int32_t>(w.discarded.size()));
    for (BodyId b : w.discarded) {
        h.add(b.index);
        h.add(static_cast<std::int32_t>(b.generation));
    }
    h.add(static_cast<std::int32_t>(w.edgeEvents.size()));
    for (const WorldEdgeEvent& e : w.edgeEvents) {
        h.add(e.body.index);
        h.add(static_cast<std::int32_t>(e.body.generation));
        h.add(e.reached);
    }
    const StepStats& s = w.stats;
    for (int value :
         {s.islandCount, s.bodyCount, s.jointCount, s.translationClamps, s.rotationClamps,
          s.positionIterations, s.contactCount, s.touchingCount, s.sleepingBodyCount,
          s.letGoJointCount, s.discardedBodyCount, s.edgeBodyCount}) {
        h.add(static_cast<std::int32_t>(value));
    }
    return h.value();
}

}  // namespace pivot
