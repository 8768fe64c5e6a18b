// Box2D 2.4.1 behind bench::Builder. It has neither capsules nor rounded polygons, so it stands
// in for them: a capsule becomes the polygon of its two end caps, each cap drawn with four
// points (an 8-gon, Box2D 2.4.1's most), and a rounded polygon becomes its sharp outline grown
// by the rounding (a rounded box: the box of its whole extent; a rounded hull: the hull as is).
// Its polygons' skin (b2_polygonRadius) is pivot2d's, so stacks rest alike.
#include <box2d/box2d.h>

#include <cmath>

#include "bench/engines/engine.h"
#include "scenes/parts.h"

namespace pivot::bench {

namespace {

b2Vec2 v(Vec2 p) {
    return {p.x, p.y};
}

class Box2dEngine final : public Engine {
public:
    explicit Box2dEngine(const WorldSettings& settings)
        : world_(std::make_unique<b2World>(b2Vec2(0.0f, -10.0f))) {
        world_->SetAllowSleeping(settings.sleep);
        world_->SetContinuousPhysics(settings.continuous);
    }

    void step() override { world_->Step(kTimeStep, 8, 3); }

    int contactCount() const override { return world_->GetContactCount(); }

    void setGravity(Vec2 gravity) override { world_->SetGravity(v(gravity)); }

    int body(const BodySpec& spec) override {
        b2BodyDef def;
        def.type = spec.motion == Motion::Static      ? b2_staticBody
                   : spec.motion == Motion::Kinematic ? b2_kinematicBody
                                                      : b2_dynamicBody;
        def.position = v(spec.position);
        def.linearVelocity = v(spec.velocity);
        def.linearDamping = spec.linearDamping;
        def.awake = spec.awake;
        def.allowSleep = spec.allowSleep;
        bodies_.push_back(world_->CreateBody(&def));
        return static_cast<int>(bodies_.size()) - 1;
    }

    void destroyBody(int body) override {
        world_->DestroyBody(bodies_[static_cast<std::size_t>(body)]);
        bodies_[static_cast<std::size_t>(body)] = nullptr;
    }

    void circle(int body, Vec2 center, float radius, const Material& material) override {
        b2CircleShape shape;
        shape.m_p = v(center);
        shape.m_radius = radius;
        attach(body, shape, material);
    }

    void box(int body, float hx, float hy, Vec2 center, float angle,
             const Material& material) override {
        b2PolygonShape shape;
        shape.SetAsBox(hx, hy, v(center), angle);
        attach(body, shape, material);
    }

    void roundedBox(int body, float hx, float hy, float radius, const Material& material) override {
        box(body, hx + radius, hy + radius, {}, 0.0f, material);
    }

    void polygon(int body, const std::vector<Vec2>& points, float,
                 const Material& material) override {
        std::vector<b2Vec2> vertices;
        for (Vec2 p : points) vertices.push_back(v(p));
        b2PolygonShape shape;
        shape.Set(vertices.data(), static_cast<int32>(vertices.size()));
        attach(body, shape, material);
    }

    void capsule(int body, Vec2 center1, Vec2 center2, float radius,
                 const Material& material) override {
        const Vec2 axis = center2 - center1;
        const float base = std::atan2(axis.y, axis.x);
        b2Vec2 vertices[8];
        for (int i = 0; i < 4; ++i) {  // each cap from -90 to +90 degrees about its end
            const float a = base - 0.5f * kPi + kPi * static_cast<float>(i) / 3.0f;
            vertices[i] = v(center2 + radius * Vec2{std::cos(a), std::sin(a)});
            vertices[i + 4] = v(center1 - radius * Vec2{std::cos(a), std::sin(a)});
        }
        b2PolygonShape shape;
        shape.Set(vertices, 8);
        attach(body, shape, material);
    }

    void segment(int body, Vec2 point1, Vec2 point2, const Material& material) override {
        b2EdgeShape shape;
        shape.SetTwoSided(v(point1), v(point2));
        attach(body, shape, material);
    }

    void loop(int body, const std::vector<Vec2>& points, const Material& material) override {
        std::vector<b2Vec2> vertices;
        for (Vec2 p : points) vertices.push_back(v(p));
        b2ChainShape shape;
        shape.CreateLoop(vertices.data(), static_cast<int32>(vertices.size()));
        attach(body, shape, material);
    }

    int pin(const PinSpec& spec) override {
        b2RevoluteJointDef def;
        def.Initialize(bodies_[static_cast<std::size_t>(spec.bodyA)],
                       bodies_[static_cast<std::size_t>(spec.bodyB)], v(spec.pivot));
        def.referenceAngle = spec.referenceAngle;
        def.enableLimit = spec.limit;
        def.lowerAngle = spec.lower;
        def.upperAngle = spec.upper;
        def.enableMotor = spec.motor;
        def.motorSpeed = spec.motorSpeed;
        def.maxMotorTorque = spec.maxMotorTorque;
        joints_.push_back(static_cast<b2RevoluteJoint*>(world_->CreateJoint(&def)));
        return static_cast<int>(joints_.size()) - 1;
    }

    float pinAngle(int joint) override {
        return joints_[static_cast<std::size_t>(joint)]->GetJointAngle();
    }

    float restGap() const override { return scenes::kRestGap; }

private:
    void attach(int body, const b2Shape& shape, const Material& material) {
        b2FixtureDef def;
        def.shape = &shape;
        def.density = material.density;
        def.friction = material.friction;
        def.restitution = material.restitution;
        def.filter.categoryBits = material.category;
        def.filter.maskBits = material.mask;
        def.filter.groupIndex = material.group;
        bodies_[static_cast<std::size_t>(body)]->CreateFixture(&def);
    }

    std::unique_ptr<b2World> world_;
    std::vector<b2Body*> bodies_;
    std::vector<b2RevoluteJoint*> joints_;  // a destroyed body's joints dangle: never read again
};

}  // namespace

EngineKind box2dEngine() {
    EngineKind kind;
    kind.name = "box2d_2.4.1";
    kind.about = "Box2D 2.4.1 (Debian's libbox2d), 8/3, one thread";
    kind.maxThreads = 1;
    kind.make = [](const WorldSettings& settings) -> std::unique_ptr<Engine> {
        return std::make_unique<Box2dEngine>(settings);
    };
    return kind;
}

}  // namespace pivot::bench
