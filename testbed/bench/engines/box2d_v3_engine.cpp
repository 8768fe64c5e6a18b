// Box2D v3 behind bench::Builder, compiled only when CMake is given its source tree
// (PIVOT_BOX2D_V3_SOURCE). This file sees only v3's headers: its box2d/box2d.h has the same
// name as Box2D 2.4.1's. It steps as v3's benchmark app does: 1/60 s, 4 substeps, its tasks
// served by a pool of threads (task_pool.h) when given more than one.
#include <box2d/box2d.h>

#include <string>

#include "bench/engines/engine.h"
#include "bench/engines/task_pool.h"

namespace pivot::bench {

namespace {

b2Vec2 v(Vec2 p) {
    return {p.x, p.y};
}

void* enqueueTask(b2TaskCallback* task, int items, int minRange, void* context, void* pool) {
    return static_cast<TaskPool*>(pool)->enqueue(task, items, minRange, context);
}

void finishTask(void* task, void* pool) {
    static_cast<TaskPool*>(pool)->finish(task);
}

class Box2dV3Engine final : public Engine {
public:
    explicit Box2dV3Engine(const WorldSettings& settings)
        : pool_(std::make_unique<TaskPool>(settings.threads)) {
        b2WorldDef def = b2DefaultWorldDef();
        def.enableSleep = settings.sleep;
        def.enableContinuous = settings.continuous;
        def.workerCount = settings.threads;
        if (settings.threads > 1) {
            def.enqueueTask = enqueueTask;
            def.finishTask = finishTask;
            def.userTaskContext = pool_.get();
        }
        world_ = b2CreateWorld(&def);
    }

    ~Box2dV3Engine() override { b2DestroyWorld(world_); }

    void step() override { b2World_Step(world_, kTimeStep, 4); }

    int contactCount() const override { return b2World_GetCounters(world_).contactCount; }

    void setGravity(Vec2 gravity) override { b2World_SetGravity(world_, v(gravity)); }

    int body(const BodySpec& spec) override {
        b2BodyDef def = b2DefaultBodyDef();
        def.type = spec.motion == Motion::Static      ? b2_staticBody
                   : spec.motion == Motion::Kinematic ? b2_kinematicBody
                                                      : b2_dynamicBody;
        def.position = v(spec.position);
        def.linearVelocity = v(spec.velocity);
        def.linearDamping = spec.linearDamping;
        def.isAwake = spec.awake;
        def.enableSleep = spec.allowSleep;
        bodies_.push_back(b2CreateBody(world_, &def));
        return static_cast<int>(bodies_.size()) - 1;
    }

    void destroyBody(int body) override { b2DestroyBody(id(body)); }

    void circle(int body, Vec2 center, float radius, const Material& material) override {
        const b2ShapeDef def = shapeDef(material);
        const b2Circle circle{v(center), radius};
        b2CreateCircleShape(id(body), &def, &circle);
    }

    void box(int body, float hx, float hy, Vec2 center, float angle,
             const Material& material) override {
        const b2ShapeDef def = shapeDef(material);
        const b2Polygon polygon = b2MakeOffsetBox(hx, hy, v(center), b2MakeRot(angle));
        b2CreatePolygonShape(id(body), &def, &polygon);
    }

    void roundedBox(int body, float hx, float hy, float radius, const Material& material) override {
        const b2ShapeDef def = shapeDef(material);
        const b2Polygon polygon = b2MakeRoundedBox(hx, hy, radius);
        b2CreatePolygonShape(id(body), &def, &polygon);
    }

    void polygon(int body, const std::vector<Vec2>& points, float radius,
                 const Material& material) override {
        std::vector<b2Vec2> vertices;
        for (Vec2 p : points) vertices.push_back(v(p));
        const b2Hull hull = b2ComputeHull(vertices.data(), static_cast<int>(vertices.size()));
        const b2ShapeDef def = shapeDef(material);
        const b2Polygon polygon = b2MakePolygon(&hull, radius);
        b2CreatePolygonShape(id(body), &def, &polygon);
    }

    void capsule(int body, Vec2 center1, Vec2 center2, float radius,
                 const Material& material) override {
        const b2ShapeDef def = shapeDef(material);
        const b2Capsule capsule{v(center1), v(center2), radius};
        b2CreateCapsuleShape(id(body), &def, &capsule);
    }

    void segment(int body, Vec2 point1, Vec2 point2, const Material& material) override {
        const b2ShapeDef def = shapeDef(material);
        const b2Segment segment{v(point1), v(point2)};
        b2CreateSegmentShape(id(body), &def, &segment);
    }

    void loop(int body, const std::vector<Vec2>& points, const Material& material) override {
        std::vector<b2Vec2> vertices;
        for (Vec2 p : points) vertices.push_back(v(p));
        b2SurfaceMaterial surface = b2DefaultSurfaceMaterial();
        surface.friction = material.friction;
        surface.restitution = material.restitution;
        b2ChainDef def = b2DefaultChainDef();
        def.points = vertices.data();
        def.count = static_cast<int>(vertices.size());
        def.isLoop = true;
        def.materials = &surface;
        def.materialCount = 1;
        def.filter = chainFilter(material);
        b2CreateChain(id(body), &def);
    }

    int pin(const PinSpec& spec) override {
        b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
        def.bodyIdA = id(spec.bodyA);
        def.bodyIdB = id(spec.bodyB);
        def.localAnchorA = b2Body_GetLocalPoint(def.bodyIdA, v(spec.pivot));
        def.localAnchorB = b2Body_GetLocalPoint(def.bodyIdB, v(spec.pivot));
        def.referenceAngle = spec.referenceAngle;
        def.enableLimit = spec.limit;
        def.lowerAngle = spec.lower;
        def.upperAngle = spec.upper;
        def.enableMotor = spec.motor;
        def.motorSpeed = spec.motorSpeed;
        def.maxMotorTorque = spec.maxMotorTorque;
        joints_.push_back(b2CreateRevoluteJoint(world_, &def));
        return static_cast<int>(joints_.size()) - 1;
    }

    float pinAngle(int joint) override {
        return b2RevoluteJoint_GetAngle(joints_[static_cast<std::size_t>(joint)]);
    }

    float restGap() const override { return 0.0f; }  // no skin: boxes rest touching

private:
    b2BodyId id(int body) const { return bodies_[static_cast<std::size_t>(body)]; }

    static b2ShapeDef shapeDef(const Material& material) {
        b2ShapeDef def = b2DefaultShapeDef();
        def.density = material.density;
        def.material.friction = material.friction;
        def.material.restitution = material.restitution;
        def.filter.categoryBits = material.category;
        def.filter.maskBits = material.mask;
        def.filter.groupIndex = material.group;
        return def;
    }

    static b2Filter chainFilter(const Material& material) {
        b2Filter filter = b2DefaultFilter();
        filter.categoryBits = material.category;
        filter.maskBits = material.mask;
        filter.groupIndex = material.group;
        return filter;
    }

    std::unique_ptr<TaskPool> pool_;  // outlives the world, which it serves
    b2WorldId world_{};
    std::vector<b2BodyId> bodies_;
    std::vector<b2JointId> joints_;
};

}  // namespace

std::vector<EngineKind> box2dV3Engines() {
    EngineKind kind;
    kind.name = "box2d_v3";
    const b2Version version = b2GetVersion();
    kind.about = "Box2D v3 (" + std::to_string(version.major) + "." +
                 std::to_string(version.minor) + "." + std::to_string(version.revision) +
                 ", from source), 4 substeps, its tasks on a thread pool";
    kind.maxThreads = 64;
    kind.make = [](const WorldSettings& settings) -> std::unique_ptr<Engine> {
        return std::make_unique<Box2dV3Engine>(settings);
    };
    return {kind};
}

}  // namespace pivot::bench
