// The World facade, part one: lifetime, stepping, world-wide settings and the state hash.
// Every public call checks its input completely before it changes anything, and a failed
// check throws pivot::Error.
#include <atomic>
#include <string>

#include "state_hash.h"
#include "world_checks.h"
#include "world_impl.h"

namespace pivot {

namespace {
std::uint32_t nextWorldId() {
    static std::atomic<std::uint32_t> counter{0};
    std::uint32_t id = ++counter;
    if (id == 0) id = ++counter;  // 0 marks a null handle
    return id;
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
    requireFinite(call, "def.gravity", def.gravity);
    checkSolver(call, "def.defaultPositionSolver", def.defaultPositionSolver);
    checkContactCorrection(call, "def.contactCorrection", def.contactCorrection);
    requireInRange(call, "def.contactBiasFactor", def.contactBiasFactor, 0.0f, 1.0f);
    requireNonNegative(call, "def.restitutionThreshold", def.restitutionThreshold);
    if (def.workerCount < 1 || def.workerCount > 64) {
        fail(call,
             "def.workerCount must be in [1, 64] (got " + std::to_string(def.workerCount) + ")");
    }
    impl_ = std::make_unique<Impl>(def);
}

World::~World() = default;

void World::step(float dt, int velocityIterations, int positionIterations) {
    const char* call = "World::step";
    requireFinite(call, "dt", dt);
    if (dt <= 0.0f) fail(call, "dt must be > 0 (got " + formatFloat(dt) + ")");
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

Vec2 World::gravity() const {
    return impl_->gravity;
}

void World::setGravity(Vec2 gravity) {
    requireFinite("World::setGravity", "gravity", gravity);
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

std::uint64_t World::stateHash() const {
    StateHasher h;
    impl_->bodies.forEach([&](std::int32_t index, const Body& b) {
        h.add(index);
        h.add(static_cast<std::int32_t>(b.type));
        h.add(b.center);
        h.add(b.angle);
        h.add(b.linearVelocity);
        h.add(b.angularVelocity);
        h.add(b.force);
        h.add(b.torque);
        h.add(b.mass);
        h.add(b.inertia);
        h.add(b.localCenter);
        h.add(b.shapeCount);
        h.add(static_cast<std::int32_t>(b.awake));
        h.add(b.sleepTime);
    });
    impl_->shapes.forEach([&](std::int32_t index, const Shape& s) {
        h.add(index);
        h.add(s.body);
        h.add(s.density);
        h.add(static_cast<std::int32_t>(s.filter.categoryBits | (s.filter.maskBits << 16)));
        h.add(static_cast<std::int32_t>(s.filter.groupIndex));
    });
    impl_->joints.forEach([&](std::int32_t index, const RevoluteJoint& j) {
        h.add(index);
        h.add(static_cast<std::int32_t>(j.solver));
        h.add(j.biasFactor());
        h.add(j.impulse);
        h.add(j.motorImpulse);
        h.add(j.lowerImpulse);
        h.add(j.upperImpulse);
        h.add(j.bodyA());
        h.add(j.bodyB());
    });
    impl_->mouseJoints.forEach([&](std::int32_t index, const MouseJoint& m) {
        h.add(index);
        h.add(m.body);
        h.add(m.target);
        h.add(m.impulse);
    });
    impl_->contacts.forEach([&](std::int32_t index, const Contact& c) {
        h.add(index);
        h.add(c.shapeA);
        h.add(c.shapeB);
        h.add(c.manifold.pointCount);
        for (int i = 0; i < c.manifold.pointCount; ++i) {
            h.add(c.manifold.points[i].localPoint);
            h.add(c.manifold.points[i].normalImpulse);
            h.add(c.manifold.points[i].tangentImpulse);
        }
    });
    return h.value();
}

}  // namespace pivot
