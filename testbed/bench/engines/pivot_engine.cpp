// pivot2d behind bench::Builder, in each of the bench's set-ups.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "bench/engines/engine.h"
#include "bench/engines/task_pool.h"
#include "pivot/pivot.h"
#include "scenes/parts.h"

namespace pivot::bench {

namespace {

struct PivotSetup {
    const char* name;
    const char* about;
    PositionSolver solver;
    ContactCorrection contacts;
    int substeps;
    int velocityIterations;
    int positionIterations;
    // Each set-up's continuous collision is that of the engine it is like for like with.
    ContinuousCollision continuous;
};

constexpr PivotSetup kSetups[] = {
    {"full_ngs",
     "pivot2d, FullNGS joints, NGS contacts, 8/3, Box2D 2.4.1's continuous collision (the "
     "defaults)",
     PositionSolver::FullNGS, ContactCorrection::NGS, 1, 8, 3, ContinuousCollision::Substeps},
    {"baumgarte",
     "pivot2d, Baumgarte joints, NGS contacts, 8/3, Box2D 2.4.1's continuous collision",
     PositionSolver::Baumgarte, ContactCorrection::NGS, 1, 8, 3, ContinuousCollision::Substeps},
    {"soft_step",
     "pivot2d, soft-step joints, soft contacts, 4 substeps of 1/1, Box2D v3's continuous "
     "collision (fast bodies)",
     PositionSolver::SoftStep, ContactCorrection::Soft, 4, 1, 1, ContinuousCollision::FastBodies},
};

class PivotEngine final : public Engine {
public:
    PivotEngine(const PivotSetup& setup, const WorldSettings& settings)
        : setup_(setup), positionIterations_(setup.positionIterations) {
        WorldDef def;
        def.enableSleep = settings.sleep;
        def.enableContinuous = settings.continuous;
        def.continuousCollision = settings.continuousCollision.value_or(setup.continuous);
        def.defaultPositionSolver = setup.solver;
        def.contactCorrection = setup.contacts;
        def.substepCount = setup.substeps;
        def.workerCount = settings.threads;
        def.adaptWorkerCount = settings.adaptWorkers;
        if (settings.predictiveBoxes) def.broadPhaseBoxes = BroadPhaseBoxes::Predictive;
        if (settings.sharedTasks && settings.threads > 1) {
            tasks_ = std::make_unique<TaskPool>(settings.threads);
            pending_.assign(static_cast<std::size_t>(settings.threads - 1),
                            StepTask(nullptr, nullptr, 0));
            def.enqueueTask = [this](StepTask task) { return enqueue(task); };
            def.finishTask = [this](void* handle) { tasks_->finish(handle); };
        }
        world_ = std::make_unique<World>(def);
        if (settings.positionIterations && setup.substeps == 1) {
            positionIterations_ = *settings.positionIterations;
        }
    }

    void step() override {
        world_->step(kTimeStep, setup_.velocityIterations, positionIterations_);
    }

    int contactCount() const override { return world_->lastStepStats().contactCount; }

    void setGravity(Vec2 gravity) override { world_->setGravity(gravity); }

    int body(const BodySpec& spec) override {
        BodyDef def;
        def.type = spec.motion == Motion::Static      ? BodyType::Static
                   : spec.motion == Motion::Kinematic ? BodyType::Kinematic
                                                      : BodyType::Dynamic;
        def.position = spec.position;
        def.linearVelocity = spec.velocity;
        def.linearDamping = spec.linearDamping;
        def.isAwake = spec.awake;
        def.allowSleep = spec.allowSleep;
        bodies_.push_back(world_->createBody(def));
        return static_cast<int>(bodies_.size()) - 1;
    }

    void destroyBody(int body) override { world_->destroyBody(id(body)); }

    void circle(int body, Vec2 center, float radius, const Material& material) override {
        world_->createShape(id(body), shapeDef(material), Circle{center, radius});
    }

    void box(int body, float hx, float hy, Vec2 center, float angle,
             const Material& material) override {
        world_->createShape(id(body), shapeDef(material), Polygon::box(hx, hy, center, angle));
    }

    void roundedBox(int body, float hx, float hy, float radius, const Material& material) override {
        world_->createShape(id(body), shapeDef(material),
                            Polygon::roundedBox(hx + radius, hy + radius, radius));
    }

    void polygon(int body, const std::vector<Vec2>& points, float radius,
                 const Material& material) override {
        Polygon polygon = Polygon::convexHull(points.data(), static_cast<int>(points.size()));
        polygon.radius = radius;
        world_->createShape(id(body), shapeDef(material), polygon);
    }

    void capsule(int body, Vec2 center1, Vec2 center2, float radius,
                 const Material& material) override {
        world_->createShape(id(body), shapeDef(material), Capsule{center1, center2, radius});
    }

    void segment(int body, Vec2 point1, Vec2 point2, const Material& material) override {
        world_->createShape(id(body), shapeDef(material), Segment{point1, point2});
    }

    void loop(int body, const std::vector<Vec2>& points, const Material& material) override {
        Chain chain;
        chain.points = points;
        chain.loop = true;
        world_->createChain(id(body), shapeDef(material), chain);
    }

    int pin(const PinSpec& spec) override {
        RevoluteJointDef def;
        def.bodyA = id(spec.bodyA);
        def.bodyB = id(spec.bodyB);
        def.localAnchorA = world_->bodyLocalPoint(def.bodyA, spec.pivot);
        def.localAnchorB = world_->bodyLocalPoint(def.bodyB, spec.pivot);
        def.referenceAngle = spec.referenceAngle;
        def.limit = {spec.limit, spec.lower, spec.upper};
        def.motor = {spec.motor, spec.motorSpeed, spec.maxMotorTorque};
        joints_.push_back(world_->createJoint(def));
        return static_cast<int>(joints_.size()) - 1;
    }

    float pinAngle(int joint) override {
        return world_->jointAngle(joints_[static_cast<std::size_t>(joint)]);
    }

    float restGap() const override { return scenes::kRestGap; }

private:
    BodyId id(int body) const { return bodies_[static_cast<std::size_t>(body)]; }

    static ShapeDef shapeDef(const Material& material) {
        ShapeDef def;
        def.density = material.density;
        def.friction = material.friction;
        def.restitution = material.restitution;
        def.filter = {material.category, material.mask, material.group};
        return def;
    }

    // A world task waits in a slot of its own until finished. A job's tasks are all finished
    // before the next job hands out any, so a ring as long as a job's tasks never overwrites
    // one still waiting.
    void* enqueue(StepTask task) {
        StepTask& slot = pending_[nextSlot_++ % pending_.size()];
        slot = task;
        return tasks_->enqueue(
            [](int, int, std::uint32_t, void* context) { (*static_cast<StepTask*>(context))(); }, 1,
            1, &slot);
    }

    PivotSetup setup_;
    int positionIterations_;           // the set-up's, or --position-iterations
    std::unique_ptr<TaskPool> tasks_;  // outlives the world, which it serves
    std::vector<StepTask> pending_;
    std::size_t nextSlot_ = 0;
    std::unique_ptr<World> world_;
    std::vector<BodyId> bodies_;
    std::vector<JointId> joints_;
};

}  // namespace

std::vector<EngineKind> pivotEngines() {
    std::vector<EngineKind> kinds;
    for (const PivotSetup& setup : kSetups) {
        EngineKind kind;
        kind.name = setup.name;
        kind.about = setup.about;
        kind.maxThreads = 64;
        kind.isPivot = true;
        kind.make = [&setup](const WorldSettings& settings) -> std::unique_ptr<Engine> {
            return std::make_unique<PivotEngine>(setup, settings);
        };
        kinds.push_back(std::move(kind));
    }
    return kinds;
}

}  // namespace pivot::bench
