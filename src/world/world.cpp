// The World facade, part one: lifetime, stepping and world-wide settings.
// Every public call checks its input completely before it changes anything, and a failed
// check throws pivot::Error.
#include <atomic>
#include <cmath>
#include <exception>
#include <string>

#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

// Ids 1 to 2^32 - 1, each once per process (0 marks a null handle): a repeated id would let a
// handle kept from a destroyed world name an object of a new one, so the counter never wraps.
std::uint32_t newWorldId(const char* call) {
    static std::atomic<std::uint64_t> counter{0};
    const std::uint64_t id = ++counter;
    if (id > 0xFFFFFFFFull) {
        fail(call,
             "this process has used 2^32 - 1 world ids, every id a handle can carry "
             "(each world takes one, and one more for each snapshot of another world it "
             "restores)");
    }
    return static_cast<std::uint32_t>(id);
}

World::Impl::Impl(const WorldDef& def)
    : id(newWorldId("World::World")),
      settings(WorldSettings::of(def)),
      pool(def.workerCount, TaskSystem{def.enqueueTask, def.finishTask}),
      adaptWorkerCount(def.adaptWorkerCount),
      workerChooser(def.workerCount),
      contactManager(bodies, shapes, joints, contacts, islandRevision, pool, access, id),
      stepper(pool) {
    contactManager.broadPhase().setBoxes(def.broadPhaseBoxes);
}

std::int32_t World::Impl::bodyIndex(const char* call, BodyId id) const {
    requireRead(call);
    return checkHandle(call, "body", id, bodies, this->id);
}
std::int32_t World::Impl::shapeIndex(const char* call, ShapeId id) const {
    requireRead(call);
    return checkHandle(call, "shape", id, shapes, this->id);
}
std::int32_t World::Impl::jointIndex(const char* call, JointId id) const {
    requireRead(call);
    return checkHandle(call, "joint", id, joints, this->id);
}
std::int32_t World::Impl::mouseJointIndex(const char* call, MouseJointId id) const {
    requireRead(call);
    return checkHandle(call, "mouse joint", id, mouseJoints, this->id);
}

void World::Impl::wakeAll() {
    bodies.forEach([this](std::int32_t, Body& b) { wakeUp(b, islandRevision); });
}

World::World(const WorldDef& def) {
    const char* call = "World::World";
    checkSettings(call, "def.", WorldSettings::of(def));
    checkBroadPhaseBoxes(call, "def.broadPhaseBoxes", def.broadPhaseBoxes);
    if (def.workerCount < 1 || def.workerCount > 64) {
        fail(call,
             "def.workerCount must be in [1, 64] (got " + std::to_string(def.workerCount) + ")");
    }
    if (static_cast<bool>(def.enqueueTask) != static_cast<bool>(def.finishTask)) {
        fail(call, std::string("def.enqueueTask and def.finishTask must be set together (got ") +
                       (def.enqueueTask ? "enqueueTask" : "finishTask") + " alone)");
    }
    // bool fields need no check: any value is meaningful.
    impl_ = std::make_unique<Impl>(def);
}

World::~World() = default;

void World::step(float dt) {
    step(dt, impl_->settings.velocityIterations, impl_->settings.positionIterations);
}

void World::step(float dt, int velocityIterations, int positionIterations) {
    const char* call = "World::step";
    impl_->requireStructureChange(call);
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
    // Checked before the message is built: a step allocates nothing when all is well.
    if (velocityIterations < 0 || velocityIterations > kMaxIterations) {
        checkIterations(call, "velocityIterations", velocityIterations);
    }
    if (positionIterations < 0 || positionIterations > kMaxIterations) {
        checkIterations(call, "positionIterations", positionIterations);
    }
    const int substeps = impl_->settings.substepCount;
    if (dt / static_cast<float>(substeps) < kMinTimeStep) {
        fail(call, "dt / substepCount must be >= kMinTimeStep (" + formatFloat(kMinTimeStep) +
                       " s) (got dt " + formatFloat(dt) + " s in " + std::to_string(substeps) +
                       " substeps)");
    }
    {
        // Until the step returns, the world refuses changes from anywhere, and reads from
        // anywhere but the step's callbacks (world_access.h).
        const WorldAccess::StepScope stepping(impl_->access);
        impl_->step(dt, velocityIterations, positionIterations);
    }
    // A callback's exception, held while the step finished (World::setPreSolveCallback), or
    // the task system's (WorldDef::enqueueTask): the callback's first when both threw.
    std::exception_ptr callbackError = impl_->contactManager.takeCallbackError();
    std::exception_ptr taskError = impl_->pool.takeTaskError();
    if (callbackError) std::rethrow_exception(callbackError);
    if (taskError) std::rethrow_exception(taskError);
}

const StepStats& World::lastStepStats() const {
    impl_->requireRead("World::lastStepStats");
    return impl_->stats;
}

std::vector<WorldEdgeEvent> World::worldEdgeEvents() const {
    impl_->requireRead("World::worldEdgeEvents");
    return impl_->edgeEvents;
}

std::vector<BodyId> World::discardedBodies() const {
    impl_->requireRead("World::discardedBodies");
    return impl_->discarded;
}

int World::substepCount() const {
    return impl_->settings.substepCount;
}

void World::setSubstepCount(int count) {
    impl_->requireChange("World::setSubstepCount");
    checkSubstepCount("World::setSubstepCount", "count", count);
    impl_->settings.substepCount = count;
}

int World::velocityIterations() const {
    return impl_->settings.velocityIterations;
}

int World::positionIterations() const {
    return impl_->settings.positionIterations;
}

void World::setIterations(int velocityIterations, int positionIterations) {
    const char* call = "World::setIterations";
    impl_->requireChange(call);
    checkIterations(call, "velocityIterations", velocityIterations);
    checkIterations(call, "positionIterations", positionIterations);
    impl_->settings.velocityIterations = velocityIterations;
    impl_->settings.positionIterations = positionIterations;
}

Vec2 World::gravity() const {
    return impl_->settings.gravity;
}

void World::setGravity(Vec2 gravity) {
    impl_->requireChange("World::setGravity");
    checkGravity("World::setGravity", "gravity", gravity);
    impl_->settings.gravity = gravity;
    impl_->wakeAll();
}

PositionSolver World::defaultPositionSolver() const {
    return impl_->settings.defaultPositionSolver;
}

BroadPhaseBoxes World::broadPhaseBoxes() const {
    return impl_->contactManager.broadPhase().boxes();
}

ContactCorrection World::contactCorrection() const {
    return impl_->settings.contactCorrection;
}

void World::setContactCorrection(ContactCorrection correction) {
    impl_->requireChange("World::setContactCorrection");
    checkContactCorrection("World::setContactCorrection", "correction", correction);
    impl_->settings.contactCorrection = correction;
}

void World::setSleepEnabled(bool enabled) {
    impl_->requireChange("World::setSleepEnabled");
    impl_->settings.enableSleep = enabled;
    if (!enabled) impl_->wakeAll();
}

bool World::isSleepEnabled() const {
    return impl_->settings.enableSleep;
}

void World::setContinuousEnabled(bool enabled) {
    impl_->requireChange("World::setContinuousEnabled");
    impl_->settings.enableContinuous = enabled;
}

bool World::isContinuousEnabled() const {
    return impl_->settings.enableContinuous;
}

void World::setContinuousCollision(ContinuousCollision policy) {
    const char* call = "World::setContinuousCollision";
    impl_->requireChange(call);
    checkContinuousCollision(call, "policy", policy);
    impl_->settings.continuousCollision = policy;
}

ContinuousCollision World::continuousCollision() const {
    return impl_->settings.continuousCollision;
}

float World::hitEventThreshold() const {
    return impl_->settings.hitEventThreshold;
}

void World::setHitEventThreshold(float speed) {
    const char* call = "World::setHitEventThreshold";
    impl_->requireChange(call);
    checkHitEventThreshold(call, "speed", speed);
    impl_->settings.hitEventThreshold = speed;
}

}  // namespace pivot
