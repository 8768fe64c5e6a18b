// Bad input is rejected with a message that names the problem, and the world is unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A small world with a body, a shape and a joint, stepped once so velocities, impulses and
// forces are non-trivial.
struct Fixture {
    World world{oneSubstepDef()};
    BodyId ground, body, other;
    ShapeId shape;
    JointId joint;

    Fixture() {
        ground = world.createBody(BodyDef{});
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {1.0f, 0.0f};
        body = world.createBody(def);
        shape = world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.25f));
        def.position = {2.0f, 0.0f};
        other = world.createBody(def);
        world.createShape(other, ShapeDef{}, Circle{{0, 0}, 0.3f});
        joint = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, body, {0.5f, 0.0f}));
        world.step(1.0f / 60.0f);
        world.applyForceToCenter(body, {1.0f, 2.0f});
    }
};

struct Snapshot {
    std::uint64_t hash;
    int bodies, shapes, joints;
    bool operator==(const Snapshot& o) const {
        return hash == o.hash && bodies == o.bodies && shapes == o.shapes && joints == o.joints;
    }
};

Snapshot snapshot(const World& w) {
    return {w.stateHash(), w.bodyCount(), w.shapeCount(), w.jointCount()};
}

// Runs `call`, which must throw pivot::Error whose message contains every one of `words`,
// and checks the world is exactly as before.
template <typename Call>
void expectRejected(World& world, Call&& call, const std::vector<std::string>& words) {
    Snapshot before = snapshot(world);
    try {
        call();
        ADD_FAILURE() << "accepted input that should be rejected";
    } catch (const Error& e) {
        std::string message = e.what();
        for (const std::string& w : words) {
            EXPECT_NE(message.find(w), std::string::npos)
                << "message \"" << message << "\" does not mention \"" << w << "\"";
        }
    }
    EXPECT_TRUE(snapshot(world) == before) << "a rejected call changed the world";
}

BodyDef dynamicDef() {
    BodyDef def;
    def.type = BodyType::Dynamic;
    return def;
}

}  // namespace

TEST(Validation, NonFiniteBodyDefFields) {
    Fixture f;
    auto with = [](auto mutate) {
        BodyDef def = dynamicDef();
        mutate(def);
        return def;
    };
    expectRejected(f.world,
                   [&] { f.world.createBody(with([](BodyDef& d) { d.position.x = kNaN; })); },
                   {"createBody", "def.position", "nan"});
    expectRejected(f.world, [&] { f.world.createBody(with([](BodyDef& d) { d.angle = kInf; })); },
                   {"def.angle", "inf"});
    expectRejected(
        f.world, [&] { f.world.createBody(with([](BodyDef& d) { d.linearVelocity.y = -kInf; })); },
        {"def.linearVelocity", "-inf"});
    expectRejected(f.world,
                   [&] { f.world.createBody(with([](BodyDef& d) { d.angularVelocity = kNaN; })); },
                   {"def.angularVelocity"});
    expectRejected(f.world,
                   [&] { f.world.createBody(with([](BodyDef& d) { d.linearDamping = -1.0f; })); },
                   {"def.linearDamping", ">= 0", "-1"});
    expectRejected(f.world,
                   [&] { f.world.createBody(with([](BodyDef& d) { d.gravityScale = kNaN; })); },
                   {"def.gravityScale"});
    expectRejected(
        f.world,
        [&] { f.world.createBody(with([](BodyDef& d) { d.type = static_cast<BodyType>(7); })); },
        {"def.type", "7"});
    expectRejected(f.world,
                   [&] {
                       BodyDef d;  // static
                       d.linearVelocity = {1.0f, 0.0f};
                       f.world.createBody(d);
                   },
                   {"static", "def.linearVelocity"});
}

TEST(Validation, NonFiniteArgumentsToBodyCalls) {
    Fixture f;
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyTransform(f.body, {kNaN, 0}, 0);
                   },
                   {"position", "nan"});
    expectRejected(f.world, [&] { f.world.setBodyTransform(f.body, {0, 0}, kInf); }, {"angle"});
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyLinearVelocity(f.body, {0, kInf});
                   },
                   {"velocity"});
    expectRejected(f.world, [&] { f.world.setBodyAngularVelocity(f.body, kNaN); }, {"omega"});
    expectRejected(f.world, [&] { f.world.applyForce(f.body, {kNaN, 0}, {0, 0}); }, {"force"});
    expectRejected(f.world, [&] { f.world.applyForce(f.body, {1, 0}, {kInf, 0}); }, {"worldPoint"});
    expectRejected(f.world, [&] { f.world.applyTorque(f.body, kNaN); }, {"torque"});
    expectRejected(f.world,
                   [&] {
                       f.world.applyLinearImpulse(f.body, {kNaN, 0}, {0, 0});
                   },
                   {"impulse"});
    expectRejected(f.world, [&] { f.world.applyAngularImpulse(f.body, kInf); }, {"impulse"});
    expectRejected(f.world, [&] { f.world.setGravity({0, kNaN}); }, {"gravity"});
    expectRejected(f.world, [&] { f.world.setBodyLinearVelocity(f.ground, {1, 0}); }, {"static"});
}

TEST(Validation, DegeneratePolygons) {
    Fixture f;
    ShapeDef def;
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Polygon::fromPoints({{0, 0}, {1, 0}}));
                   },
                   {"createShape", "polygon.count", "[3, 8]", "2"});
    expectRejected(
        f.world,
        [&] {
            f.world.createShape(f.body, def, Polygon::fromPoints({{0, 0}, {1, 1}, {2, 2}}));
        },
        {"collinear"});
    expectRejected(
        f.world,
        [&] {
            f.world.createShape(f.body, def, Polygon::fromPoints({{0, 0}, {1, 0}, {2, 0}, {1, 1}}));
        },
        {"collinear"});
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(
                           f.body, def,
                           Polygon::fromPoints({{0, 0}, {2, 0}, {1, 0.5f}, {2, 2}, {0, 2}}));
                   },
                   {"not convex"});
    expectRejected(
        f.world,
        [&] {
            f.world.createShape(f.body, def, Polygon::fromPoints({{0, 0}, {1, 0}, {1, 0}, {0, 1}}));
        },
        {"edge from vertices[1] to vertices[2]", "is 0 m long", "kLinearSlop", "repeated vertex"});
    // A box too small for the slop: the message names the rule it breaks and the limit, not a
    // repeated vertex (it has none).
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Polygon::box(1e-3f, 1e-3f)); },
                   {"World::createShape", "edge from vertices[0] to vertices[1]", "0.002 m long",
                    "at least kLinearSlop (0.005 m)"});
    // Vertices numbered as given, also when a clockwise polygon is stored reversed.
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(
                           f.body, def,
                           Polygon::fromPoints({{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0.003f, 0}}));
                   },
                   {"edge from vertices[0] to vertices[4]", "0.003 m long"});
    expectRejected(
        f.world,
        [&] {
            f.world.createShape(f.body, def, Polygon::fromPoints({{0, 0}, {kNaN, 0}, {0, 1}}));
        },
        {"polygon.vertices[1]", "nan"});
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Polygon::box(0.0f, 1.0f)); },
                   {"Polygon::box", "halfWidth", "> 0"});
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Polygon::box(1.0f, -1.0f)); },
                   {"halfHeight", "-1"});
    expectRejected(f.world, [&] { Polygon::box(1.0f, 1.0f, {kNaN, 0.0f}, 0.0f); }, {"center"});
    Polygon tooMany = Polygon::box(1, 1);
    tooMany.count = kMaxPolygonVertices + 1;
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, tooMany); },
                   {"polygon.count", "9"});
    EXPECT_THROW(
        Polygon::fromPoints(
            {{0, 0}, {1, 0}, {2, 1}, {2, 2}, {1, 3}, {0, 3}, {-1, 2}, {-1, 1}, {-0.5f, 0.2f}}),
        Error);
}

TEST(Validation, CircleAndShapeDefFields) {
    Fixture f;
    ShapeDef def;
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Circle{{0, 0}, 0.0f});
                   },
                   {"circle.radius", ">= kLinearSlop", "0.005", "got 0"});
    // Smaller than the slop: the lightest such circle's inverse mass would overflow.
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Circle{{0, 0}, 1e-20f});
                   },
                   {"circle.radius", "1e-20"});
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Circle{{0, 0}, 2e5f});
                   },
                   {"circle.radius", "kMaxCoordinate", "2e+05"});
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Circle{{0, 0}, kNaN});
                   },
                   {"circle.radius", "nan"});
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, def, Circle{{kInf, 0}, 1.0f});
                   },
                   {"circle.center"});
    ShapeDef bad = def;
    bad.friction = -0.1f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, bad, Circle{}); }, {"def.friction"});
    bad = def;
    bad.friction = 1e20f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, bad, Circle{}); },
                   {"def.friction", "kMaxFriction", "1e+20"});
    bad = def;
    bad.restitution = 1.5f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, bad, Circle{}); },
                   {"def.restitution", "1.5"});
    bad = def;
    bad.restitution = kNaN;
    expectRejected(f.world, [&] { f.world.createShape(f.body, bad, Circle{}); },
                   {"def.restitution", "nan"});
}

TEST(Validation, DensityOutsideItsRange) {
    Fixture f;
    ShapeDef def;
    // The range applies on every body type: the shape keeps its density if its body changes
    // type later.
    for (BodyId body : {f.ground, f.body}) {
        def.density = 1e-30f;
        expectRejected(f.world, [&] { f.world.createShape(body, def, Circle{}); },
                       {"def.density", "kMinDensity", "1e-30"});
        def.density = std::numeric_limits<float>::denorm_min();
        expectRejected(f.world, [&] { f.world.createShape(body, def, Circle{}); }, {"def.density"});
        def.density = 2e6f;
        expectRejected(f.world, [&] { f.world.createShape(body, def, Circle{}); },
                       {"def.density", "kMaxDensity", "2e+06"});
        def.density = kInf;
        expectRejected(f.world, [&] { f.world.createShape(body, def, Circle{}); },
                       {"def.density", "inf"});
    }
    def.density = kMinDensity;
    EXPECT_NO_THROW(f.world.createShape(f.body, def, Circle{}));
    def.density = kMaxDensity;
    EXPECT_NO_THROW(f.world.createShape(f.body, def, Circle{}));
    for (int i = 0; i < 10; ++i) f.world.step(1.0f / 60.0f);
    EXPECT_TRUE(std::isfinite(f.world.bodyPosition(f.body).x));
}

TEST(Validation, NumbersBeyondTheInputLimits) {
    Fixture f;
    const float huge = 1e20f;
    const float tooFar = 2.0f * kMaxCoordinate;
    const float tooBig = 2.0f * kMaxMagnitude;
    auto dynamicWith = [](auto mutate) {
        BodyDef def = dynamicDef();
        mutate(def);
        return def;
    };
    expectRejected(
        f.world,
        [&] {
            f.world.createBody(dynamicWith([&](BodyDef& d) { d.position = {tooFar, 0}; }));
        },
        {"createBody", "def.position", "kMaxCoordinate", "2e+05"});
    expectRejected(f.world,
                   [&] { f.world.createBody(dynamicWith([&](BodyDef& d) { d.angle = tooBig; })); },
                   {"def.angle", "kMaxMagnitude", "2e+10"});
    expectRejected(
        f.world,
        [&] {
            f.world.createBody(dynamicWith([&](BodyDef& d) { d.linearVelocity = {0, -huge}; }));
        },
        {"def.linearVelocity", "-1e+20"});
    expectRejected(
        f.world,
        [&] { f.world.createBody(dynamicWith([&](BodyDef& d) { d.angularVelocity = huge; })); },
        {"def.angularVelocity"});
    expectRejected(
        f.world,
        [&] { f.world.createBody(dynamicWith([&](BodyDef& d) { d.angularDamping = huge; })); },
        {"def.angularDamping"});
    expectRejected(
        f.world,
        [&] { f.world.createBody(dynamicWith([&](BodyDef& d) { d.gravityScale = -huge; })); },
        {"def.gravityScale"});

    expectRejected(f.world,
                   [&] {
                       f.world.setBodyTransform(f.body, {0, tooFar}, 0);
                   },
                   {"setBodyTransform", "position"});
    expectRejected(f.world, [&] { f.world.setBodyTransform(f.body, {0, 0}, huge); }, {"angle"});
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyLinearVelocity(f.body, {huge, 0});
                   },
                   {"velocity"});
    expectRejected(f.world, [&] { f.world.setBodyAngularVelocity(f.body, -huge); }, {"omega"});
    expectRejected(f.world, [&] { f.world.applyForce(f.body, {huge, 0}, {0, 0}); }, {"force"});
    expectRejected(f.world,
                   [&] {
                       f.world.applyForce(f.body, {1, 0}, {tooFar, 0});
                   },
                   {"worldPoint"});
    expectRejected(f.world, [&] { f.world.applyForceToCenter(f.body, {0, huge}); }, {"force"});
    expectRejected(f.world, [&] { f.world.applyTorque(f.body, huge); }, {"torque"});
    expectRejected(f.world,
                   [&] {
                       f.world.applyLinearImpulse(f.body, {huge, 0}, {0, 0});
                   },
                   {"impulse"});
    expectRejected(f.world,
                   [&] {
                       f.world.applyLinearImpulse(f.body, {1, 0}, {0, -tooFar});
                   },
                   {"worldPoint"});
    expectRejected(f.world, [&] { f.world.applyAngularImpulse(f.body, huge); }, {"impulse"});
    expectRejected(f.world, [&] { f.world.bodyWorldPoint(f.body, {tooFar, 0}); }, {"localPoint"});
    expectRejected(f.world, [&] { f.world.bodyLocalPoint(f.body, {tooFar, 0}); }, {"worldPoint"});
    expectRejected(f.world, [&] { f.world.setGravity({0, -huge}); }, {"gravity"});

    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, ShapeDef{}, Circle{{tooFar, 0}});
                   },
                   {"circle.center", "kMaxCoordinate"});
    Polygon far = Polygon::box(1, 1);
    far.vertices[2].x = tooFar;
    expectRejected(f.world, [&] { f.world.createShape(f.body, ShapeDef{}, far); },
                   {"polygon.vertices[2]", "kMaxCoordinate"});
    expectRejected(f.world, [&] { Polygon::box(tooFar, 1); }, {"halfWidth", "kMaxCoordinate"});
    expectRejected(f.world, [&] { Polygon::box(1, 1, {0, tooFar}, 0); }, {"center"});
    expectRejected(f.world, [&] { Polygon::box(1, 1, {0, 0}, huge); }, {"angle"});

    RevoluteJointDef def = RevoluteJointDef::atWorldAnchor(f.body, f.other, {1.5f, 0});
    RevoluteJointDef bad = def;
    bad.worldAnchor = Vec2{tooFar, 0};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.worldAnchor"});
    bad = def;
    bad.worldAnchor.reset();
    bad.localAnchorA = {0, -tooFar};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.localAnchorA"});
    bad = def;
    bad.referenceAngle = huge;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.referenceAngle"});
    bad = def;
    bad.limit = {true, -huge, 0.0f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.limit.lower"});
    bad = def;
    bad.motor = {true, huge, 1.0f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.motor.speed"});
    bad = def;
    bad.motor = {true, 1.0f, huge};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.motor.maxTorque"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointLimit(f.joint, {true, 0.0f, huge});
                   },
                   {"limit.upper"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointMotor(f.joint, {true, -huge, 1.0f});
                   },
                   {"motor.speed"});

    MouseJointDef mouse;
    mouse.body = f.body;
    mouse.target = {1, 0};
    MouseJointDef badMouse = mouse;
    badMouse.target = {tooFar, 0};
    expectRejected(f.world, [&] { f.world.createMouseJoint(badMouse); }, {"def.target"});
    badMouse = mouse;
    badMouse.maxForce = huge;
    expectRejected(f.world, [&] { f.world.createMouseJoint(badMouse); }, {"def.maxForce"});
    badMouse = mouse;
    badMouse.hertz = huge;
    expectRejected(f.world, [&] { f.world.createMouseJoint(badMouse); }, {"def.hertz"});
    badMouse = mouse;
    badMouse.dampingRatio = huge;
    expectRejected(f.world, [&] { f.world.createMouseJoint(badMouse); }, {"def.dampingRatio"});
    MouseJointId hand = f.world.createMouseJoint(mouse);
    expectRejected(f.world, [&] { f.world.setMouseTarget(hand, {0, tooFar}); }, {"target"});

    expectRejected(f.world, [&] { f.world.step(2.0f); }, {"dt", "kMaxTimeStep", "got 2"});
    WorldDef worldDef = oneSubstepDef();
    worldDef.gravity = {huge, 0};
    EXPECT_THROW(World{worldDef}, Error);
    worldDef = oneSubstepDef();
    worldDef.restitutionThreshold = huge;
    EXPECT_THROW(World{worldDef}, Error);

    // Right at the limits is accepted.
    BodyDef edge = dynamicDef();
    edge.position = {kMaxCoordinate, -kMaxCoordinate};
    edge.angularVelocity = kMaxAngularSpeed;
    edge.linearVelocity = {-kMaxSpeed, kMaxSpeed};
    edge.gravityScale = -kMaxGravityScale;
    EXPECT_NO_THROW(f.world.createBody(edge));
    EXPECT_NO_THROW(f.world.step(kMaxTimeStep));
}

TEST(Validation, ComputeMassChecksItsInput) {
    Polygon tooMany = Polygon::box(1, 1);
    tooMany.count = kMaxPolygonVertices + 1;
    EXPECT_THROW(computeMass(tooMany, 1.0f), Error);
    Polygon negative = Polygon::box(1, 1);
    negative.count = -1;
    EXPECT_THROW(computeMass(negative, 1.0f), Error);
    EXPECT_THROW(computeMass(Polygon::fromPoints({{0, 0}, {1, 1}, {2, 2}}), 1.0f), Error);
    EXPECT_THROW(computeMass(Polygon::box(1, 1), kNaN), Error);
    EXPECT_THROW(computeMass(Polygon::box(1, 1), -1.0f), Error);
    EXPECT_THROW(computeMass(Circle{{0, 0}, 0.0f}, 1.0f), Error);
    EXPECT_THROW(computeMass(Circle{{kNaN, 0}, 1.0f}, 1.0f), Error);
    try {
        computeMass(tooMany, 1.0f);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("computeMass: polygon.count"), std::string::npos)
            << e.what();
    }
    EXPECT_FLOAT_EQ(computeMass(Polygon::box(1, 2), 3.0f).mass, 24.0f);
}

TEST(Validation, ZeroOrNegativeDensityOnADynamicBody) {
    Fixture f;
    ShapeDef def;
    def.density = 0.0f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Circle{}); },
                   {"def.density", "> 0", "dynamic"});
    def.density = -2.0f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Circle{}); },
                   {"def.density", "-2"});
    def.density = kNaN;
    expectRejected(f.world, [&] { f.world.createShape(f.body, def, Circle{}); },
                   {"def.density", "nan"});
    // Zero density on a static body is fine.
    def.density = 0.0f;
    EXPECT_NO_THROW(f.world.createShape(f.ground, def, Circle{}));
}

TEST(Validation, JointBetweenABodyAndItself) {
    Fixture f;
    expectRejected(f.world,
                   [&] {
                       f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.body, f.body, {0, 0}));
                   },
                   {"createJoint", "same body"});
}

TEST(Validation, JointDefFields) {
    Fixture f;
    RevoluteJointDef def = RevoluteJointDef::atWorldAnchor(f.body, f.other, {1.5f, 0});
    RevoluteJointDef bad = def;
    bad.worldAnchor = Vec2{kNaN, 0};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.worldAnchor", "nan"});
    bad = def;
    bad.worldAnchor.reset();
    bad.localAnchorB = {0, kInf};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.localAnchorB"});
    bad = def;
    bad.referenceAngle = kNaN;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.referenceAngle"});
    bad = def;
    bad.biasFactor = 1.5f;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.biasFactor", "[0, 1]", "1.5"});
    bad = def;
    bad.positionSolver = static_cast<PositionSolver>(17);
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.positionSolver", "17"});
    const auto firstInvalid = static_cast<PositionSolver>(kPositionSolverCount);
    expectRejected(f.world, [&] { f.world.setJointPositionSolver(f.joint, firstInvalid); },
                   {"solver", std::to_string(kPositionSolverCount)});
    bad = def;
    bad.softness.hertz = 0.0f;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.softness.hertz", "> 0"});
    bad = def;
    bad.softness.hertz = kNaN;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.softness.hertz", "nan"});
    bad = def;
    bad.softness.dampingRatio = -1.0f;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.softness.dampingRatio"});
    bad = def;
    bad.softness.compliance = -1e-3f;
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.softness.compliance"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointSoftness(f.joint, {kInf, 1.0f});
                   },
                   {"softness.hertz", "inf"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointSoftness(f.joint, {10.0f, 2e10f});
                   },
                   {"softness.dampingRatio"});
    expectRejected(f.world, [&] { f.world.setJointBiasFactor(f.joint, -0.1f); }, {"biasFactor"});
    bad = def;
    bad.limit = {true, 0.5f, -0.5f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); },
                   {"def.limit.lower", "<=", "def.limit.upper", "0.5", "-0.5"});
    bad = def;
    bad.limit = {true, kNaN, 1.0f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.limit.lower", "nan"});
    bad = def;
    bad.motor = {true, kInf, 1.0f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.motor.speed", "inf"});
    bad = def;
    bad.motor = {true, 1.0f, -3.0f};
    expectRejected(f.world, [&] { f.world.createJoint(bad); }, {"def.motor.maxTorque", ">= 0"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointLimit(f.joint, {true, 1.0f, 0.0f});
                   },
                   {"setJointLimit", "limit.lower"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointMotor(f.joint, {true, 0.0f, kNaN});
                   },
                   {"setJointMotor", "motor.maxTorque"});
}

TEST(Validation, StaleIds) {
    Fixture f;
    BodyDef def = dynamicDef();
    BodyId doomed = f.world.createBody(def);
    ShapeId doomedShape = f.world.createShape(doomed, ShapeDef{}, Circle{});
    JointId doomedJoint =
        f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.ground, doomed, {0, 0}));
    f.world.destroyBody(doomed);
    // Destroying a body took its shape and joint with it.
    EXPECT_FALSE(f.world.isValid(doomedShape));
    EXPECT_FALSE(f.world.isValid(doomedJoint));
    // The slot is reused by the next body, yet the old id stays stale.
    BodyId reused = f.world.createBody(def);
    EXPECT_EQ(reused.index, doomed.index);
    EXPECT_FALSE(f.world.isValid(doomed));

    expectRejected(f.world, [&] { f.world.bodyPosition(doomed); },
                   {"bodyPosition", "stale", "destroyed"});
    expectRejected(f.world, [&] { f.world.destroyBody(doomed); }, {"destroyBody", "stale"});
    expectRejected(f.world, [&] { f.world.createShape(doomed, ShapeDef{}, Circle{}); }, {"stale"});
    expectRejected(f.world, [&] { f.world.destroyShape(doomedShape); }, {"shape", "stale"});
    expectRejected(f.world, [&] { f.world.jointSeparation(doomedJoint); }, {"joint", "stale"});
    expectRejected(
        f.world,
        [&] {
            f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.ground, doomed, {0, 0}));
        },
        {"def.bodyB", "stale"});
}

TEST(Validation, UnknownNullAndForeignIds) {
    Fixture f;
    Fixture elsewhere;
    BodyId made_up = f.body;
    made_up.index = 1000;
    expectRejected(f.world, [&] { f.world.bodyAngle(made_up); }, {"index 1000", "never issued"});
    expectRejected(f.world, [&] { f.world.bodyAngle(BodyId{}); }, {"null"});
    expectRejected(f.world, [&] { f.world.destroyJoint(JointId{}); }, {"joint", "null"});
    expectRejected(f.world, [&] { f.world.bodyAngle(elsewhere.body); }, {"another world"});
    expectRejected(f.world, [&] { f.world.destroyBody(elsewhere.body); }, {"another world"});
    expectRejected(f.world, [&] { f.world.destroyShape(elsewhere.shape); }, {"another world"});
    expectRejected(
        f.world,
        [&] {
            f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.ground, elsewhere.body, {0, 0}));
        },
        {"def.bodyB", "another world"});
    expectRejected(f.world, [&] { f.world.destroyJoint(elsewhere.joint); },
                   {"destroyJoint", "another world"});
    expectRejected(f.world, [&] { f.world.setJointMotor(elsewhere.joint, JointMotor{}); },
                   {"another world"});
    MouseJointDef mouse;
    mouse.body = elsewhere.body;
    MouseJointId foreignHand = elsewhere.world.createMouseJoint(mouse);
    expectRejected(f.world,
                   [&] {
                       f.world.setMouseTarget(foreignHand, {0, 0});
                   },
                   {"mouse joint", "another world"});
    expectRejected(f.world, [&] { f.world.destroyMouseJoint(MouseJointId{}); },
                   {"mouse joint", "null"});
    mouse.body = elsewhere.body;
    expectRejected(f.world, [&] { f.world.createMouseJoint(mouse); },
                   {"def.body", "another world"});
    EXPECT_FALSE(f.world.isValid(elsewhere.body));
    EXPECT_FALSE(f.world.isValid(elsewhere.shape));
    EXPECT_FALSE(f.world.isValid(elsewhere.joint));
    EXPECT_FALSE(f.world.isValid(foreignHand));
    EXPECT_FALSE(f.world.isValid(BodyId{}));
    EXPECT_FALSE(f.world.isValid(MouseJointId{}));
}

// Every call that takes an id refuses a stale one, with the world unchanged. Listing them all
// here keeps a new call from slipping through without its check.
TEST(Validation, EveryCallChecksItsIds) {
    Fixture f;
    BodyId body = f.world.createBody(dynamicDef());
    ShapeId shape = f.world.createShape(body, ShapeDef{}, Circle{});
    JointId joint = f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.ground, body, {0, 0}));
    MouseJointDef mouseDef;
    mouseDef.body = body;
    MouseJointId mouse = f.world.createMouseJoint(mouseDef);
    f.world.destroyBody(body);
    EXPECT_FALSE(f.world.isValid(mouse));
    f.world.step(1.0f / 60.0f);

    std::vector<std::function<void()>> bodyCalls = {
        [&] { f.world.destroyBody(body); },
        [&] { f.world.bodyShapes(body); },
        [&] { f.world.bodyJoints(body); },
        [&] { f.world.bodyContacts(body); },
        [&] { f.world.bodyLinearDamping(body); },
        [&] { f.world.setBodyLinearDamping(body, 1.0f); },
        [&] { f.world.bodyAngularDamping(body); },
        [&] { f.world.setBodyAngularDamping(body, 1.0f); },
        [&] { f.world.bodyGravityScale(body); },
        [&] { f.world.setBodyGravityScale(body, 1.0f); },
        [&] { f.world.setBodyFixedRotation(body, true); },
        [&] { f.world.isBodySleepAllowed(body); },
        [&] { f.world.createShape(body, ShapeDef{}, Circle{}); },
        [&] {
            f.world.createShape(body, ShapeDef{}, Segment{{0, 0}, {1, 0}});
        },
        [&] {
            f.world.createShape(body, ShapeDef{}, ChainSegment{{2, 0}, {{1, 0}, {0, 0}}, {-1, 0}});
        },
        [&] {
            f.world.createChain(body, ShapeDef{}, Chain{{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, false});
        },
        [&] { f.world.bodyType(body); },
        [&] { f.world.setBodyType(body, BodyType::Static); },
        [&] { f.world.bodyPosition(body); },
        [&] { f.world.bodyAngle(body); },
        [&] { f.world.bodyTransform(body); },
        [&] { f.world.bodyWorldCenter(body); },
        [&] { f.world.bodyLocalCenter(body); },
        [&] { f.world.bodyLinearVelocity(body); },
        [&] { f.world.bodyAngularVelocity(body); },
        [&] { f.world.bodyMass(body); },
        [&] { f.world.bodyRotationalInertia(body); },
        [&] {
            f.world.bodyWorldPoint(body, {0, 0});
        },
        [&] {
            f.world.bodyLocalPoint(body, {0, 0});
        },
        [&] { f.world.isBodyAwake(body); },
        [&] { f.world.setBodyAwake(body, true); },
        [&] { f.world.setBodySleepAllowed(body, true); },
        [&] {
            f.world.setBodyTransform(body, {0, 0}, 0);
        },
        [&] {
            f.world.setBodyLinearVelocity(body, {0, 0});
        },
        [&] { f.world.setBodyAngularVelocity(body, 0); },
        [&] {
            f.world.applyForce(body, {0, 0}, {0, 0});
        },
        [&] {
            f.world.applyForceToCenter(body, {0, 0});
        },
        [&] { f.world.applyTorque(body, 0); },
        [&] {
            f.world.applyLinearImpulse(body, {0, 0}, {0, 0});
        },
        [&] { f.world.applyAngularImpulse(body, 0); },
        [&] { f.world.createShape(body, ShapeDef{}, Circle{}); },
        [&] { f.world.createShape(body, ShapeDef{}, Polygon::box(1, 1)); },
        [&] {
            f.world.createJoint(RevoluteJointDef::atWorldAnchor(body, f.ground, {0, 0}));
        },
        [&] { f.world.createMouseJoint(mouseDef); },
        [&] { f.world.bodyFixedRotation(body); },
        [&] { f.world.bodyUserData(body); },
        [&] { f.world.setBodyUserData(body, 1); },
    };
    for (const auto& call : bodyCalls) expectRejected(f.world, call, {"body", "stale"});
    std::vector<std::function<void()>> shapeCalls = {
        [&] { f.world.destroyShape(shape); },
        [&] { f.world.shapeBody(shape); },
        [&] { f.world.shapeFilter(shape); },
        [&] { f.world.shapeType(shape); },
        [&] { f.world.shapeCircle(shape); },
        [&] { f.world.shapePolygon(shape); },
        [&] { f.world.shapeSegment(shape); },
        [&] { f.world.shapeChainSegment(shape); },
        [&] { f.world.setShapeFilter(shape, Filter{}); },
        [&] { f.world.shapeDensity(shape); },
        [&] { f.world.shapeFriction(shape); },
        [&] { f.world.setShapeFriction(shape, 0.5f); },
        [&] { f.world.shapeRestitution(shape); },
        [&] { f.world.setShapeRestitution(shape, 0.5f); },
        [&] { f.world.setShapeDensity(shape, 1.0f); },
        [&] { f.world.shapeUserData(shape); },
        [&] { f.world.setShapeUserData(shape, 1); },
        [&] { f.world.shapeHitEventsEnabled(shape); },
        [&] { f.world.setShapeHitEventsEnabled(shape, true); },
        [&] { f.world.shapePreSolveEnabled(shape); },
        [&] { f.world.setShapePreSolveEnabled(shape, true); },
    };
    for (const auto& call : shapeCalls) expectRejected(f.world, call, {"shape", "stale"});
    std::vector<std::function<void()>> jointCalls = {
        [&] { f.world.destroyJoint(joint); },
        [&] { f.world.jointBodyA(joint); },
        [&] { f.world.jointBodyB(joint); },
        [&] { f.world.jointAnchorA(joint); },
        [&] { f.world.jointAnchorB(joint); },
        [&] { f.world.jointSeparation(joint); },
        [&] { f.world.jointAngle(joint); },
        [&] { f.world.jointSpeed(joint); },
        [&] { f.world.jointReactionForce(joint); },
        [&] { f.world.jointReactionTorque(joint); },
        [&] { f.world.jointMotorTorque(joint); },
        [&] { f.world.jointLimit(joint); },
        [&] { f.world.setJointLimit(joint, JointLimit{}); },
        [&] { f.world.jointMotor(joint); },
        [&] { f.world.setJointMotor(joint, JointMotor{}); },
        [&] { f.world.jointPositionSolver(joint); },
        [&] { f.world.setJointPositionSolver(joint, PositionSolver::FullNGS); },
        [&] { f.world.jointBiasFactor(joint); },
        [&] { f.world.setJointBiasFactor(joint, std::nullopt); },
        [&] { f.world.isJointLetGo(joint); },
        [&] { f.world.rearmJoint(joint); },
        [&] { f.world.jointLetGoSeparation(joint); },
        [&] { f.world.setJointLetGoSeparation(joint, 1.0f); },
        [&] { f.world.jointUserData(joint); },
        [&] { f.world.setJointUserData(joint, 1); },
        [&] { f.world.jointBreakForce(joint); },
        [&] { f.world.jointLocalAnchorA(joint); },
        [&] { f.world.jointLocalAnchorB(joint); },
        [&] { f.world.jointReferenceAngle(joint); },
        [&] { f.world.jointCollideConnected(joint); },
        [&] { f.world.setJointCollideConnected(joint, true); },
        [&] { f.world.setJointBreakForce(joint, 1.0f); },
        [&] { f.world.jointBreakTorque(joint); },
        [&] { f.world.setJointBreakTorque(joint, 1.0f); },
    };
    for (const auto& call : jointCalls) expectRejected(f.world, call, {"joint", "stale"});
    std::vector<std::function<void()>> mouseCalls = {
        [&] { f.world.destroyMouseJoint(mouse); },
        [&] {
            f.world.setMouseTarget(mouse, {0, 0});
        },
        [&] { f.world.mouseTarget(mouse); },
        [&] { f.world.mouseJointBody(mouse); },
        [&] { f.world.mouseJointMaxForce(mouse); },
        [&] { f.world.setMouseJointMaxForce(mouse, 1.0f); },
        [&] { f.world.mouseJointHertz(mouse); },
        [&] { f.world.mouseJointDampingRatio(mouse); },
        [&] { f.world.setMouseJointSpring(mouse, 1.0f, 1.0f); },
    };
    for (const auto& call : mouseCalls) expectRejected(f.world, call, {"mouse joint", "stale"});
}

TEST(Validation, StepArguments) {
    Fixture f;
    expectRejected(f.world, [&] { f.world.step(0.0f); },
                   {"step", "dt", ">= kMinTimeStep (1e-05 s)"});
    // The shortest steps used to be accepted and made 1/dt infinite (docs/reliability.md).
    expectRejected(f.world, [&] { f.world.step(1e-40f); }, {"dt", "kMinTimeStep", "got 1e-40"});
    expectRejected(f.world, [&] { f.world.step(1e-30f); }, {"dt", "kMinTimeStep"});
    expectRejected(f.world, [&] { f.world.step(0.99f * kMinTimeStep); }, {"dt", "kMinTimeStep"});
    expectRejected(f.world, [&] { f.world.step(-1.0f / 60.0f); }, {"dt"});
    expectRejected(f.world, [&] { f.world.step(kNaN); }, {"dt", "nan"});
    expectRejected(f.world, [&] { f.world.step(kInf); }, {"dt", "inf"});
    expectRejected(f.world, [&] { f.world.step(1.0f / 60.0f, -1, 3); },
                   {"velocityIterations", "-1"});
    expectRejected(f.world, [&] { f.world.step(1.0f / 60.0f, 8, -3); },
                   {"positionIterations", "-3"});
    expectRejected(f.world, [&] { f.world.step(1.0f / 60.0f, 8, kMaxIterations + 1); },
                   {"positionIterations"});
    EXPECT_NO_THROW(f.world.step(1.0f / 60.0f, 0, 0));
    EXPECT_NO_THROW(f.world.step(kMinTimeStep));
}

TEST(Validation, WorldDef) {
    WorldDef def = oneSubstepDef();
    def.gravity.y = kNaN;
    EXPECT_THROW(World{def}, Error);
    def = oneSubstepDef();
    def.defaultPositionSolver = static_cast<PositionSolver>(kPositionSolverCount);
    EXPECT_THROW(World{def}, Error);
    def = oneSubstepDef();
    def.contactCorrection = static_cast<ContactCorrection>(3);
    EXPECT_THROW(World{def}, Error);
    def = oneSubstepDef();
    def.broadPhaseBoxes = static_cast<BroadPhaseBoxes>(2);
    try {
        World refused{def};
        ADD_FAILURE() << "an out-of-range BroadPhaseBoxes was accepted";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("def.broadPhaseBoxes"), std::string::npos);
    }
    def.broadPhaseBoxes = BroadPhaseBoxes::Compact;
    EXPECT_EQ(World{def}.broadPhaseBoxes(), BroadPhaseBoxes::Compact);
    for (float bad : {0.0f, -1.0f, kNaN, kInf}) {
        def = oneSubstepDef();
        def.contactHertz = bad;
        EXPECT_THROW(World{def}, Error) << bad;
        def = oneSubstepDef();
        def.contactPushSpeed = bad;
        EXPECT_THROW(World{def}, Error) << bad;
    }
    def = oneSubstepDef();
    def.contactDampingRatio = -1.0f;
    EXPECT_THROW(World{def}, Error);
    def = oneSubstepDef();
    def.contactBiasFactor = 1.5f;
    EXPECT_THROW(World{def}, Error);
    def = oneSubstepDef();
    def.restitutionThreshold = -1.0f;
    EXPECT_THROW(World{def}, Error);
    Fixture f;
    expectRejected(f.world,
                   [&] { f.world.setContactCorrection(static_cast<ContactCorrection>(9)); },
                   {"setContactCorrection", "9"});
}

TEST(Validation, ShapeCallsCheckTheirIds) {
    Fixture f;
    ShapeId doomed = f.world.createShape(f.other, ShapeDef{}, Circle{{0.5f, 0}, 0.1f});
    f.world.destroyShape(doomed);
    expectRejected(f.world, [&] { f.world.setShapeFilter(doomed, Filter{}); },
                   {"setShapeFilter", "stale"});
    expectRejected(f.world, [&] { f.world.shapeFilter(ShapeId{}); }, {"null"});
    expectRejected(f.world, [&] { f.world.isBodyAwake(BodyId{}); }, {"isBodyAwake", "null"});
}

TEST(Lifetime, DestroyingAJointUnlinksOnlyThatJoint) {
    Fixture f;
    JointId second =
        f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.body, f.other, {1.5f, 0}));
    JointId third =
        f.world.createJoint(RevoluteJointDef::atWorldAnchor(f.ground, f.other, {2.5f, 0}));
    f.world.destroyJoint(second);
    EXPECT_TRUE(f.world.isValid(f.joint));
    EXPECT_TRUE(f.world.isValid(third));
    EXPECT_EQ(f.world.jointCount(), 2);
    f.world.destroyBody(f.other);
    EXPECT_FALSE(f.world.isValid(third));
    EXPECT_TRUE(f.world.isValid(f.joint));
    EXPECT_EQ(f.world.jointCount(), 1);
    EXPECT_EQ(f.world.bodyCount(), 2);
    for (int i = 0; i < 10; ++i) f.world.step(1.0f / 60.0f);
    EXPECT_LT(f.world.jointSeparation(f.joint), kLinearSlop);
}

// The limits that keep a step's products inside float range (docs/reliability.md, "Input
// limits"): each refused just past its limit, with the limit named, and accepted at it.
TEST(Validation, TheLimitsThatKeepAStepInRange) {
    Fixture f;
    const float past = 1.0001f;
    BodyDef def = dynamicDef();
    def.linearVelocity = {0.0f, past * kMaxSpeed};
    expectRejected(f.world, [&] { f.world.createBody(def); }, {"def.linearVelocity", "kMaxSpeed"});
    def = dynamicDef();
    def.angularVelocity = -past * kMaxAngularSpeed;
    expectRejected(f.world, [&] { f.world.createBody(def); },
                   {"def.angularVelocity", "kMaxAngularSpeed"});
    def = dynamicDef();
    def.gravityScale = past * kMaxGravityScale;
    expectRejected(f.world, [&] { f.world.createBody(def); },
                   {"def.gravityScale", "kMaxGravityScale"});
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyLinearVelocity(f.body, {past * kMaxSpeed, 0});
                   },
                   {"velocity", "kMaxSpeed"});
    expectRejected(f.world,
                   [&] { f.world.setBodyAngularVelocity(f.body, past * kMaxAngularSpeed); },
                   {"omega", "kMaxAngularSpeed"});
    expectRejected(f.world,
                   [&] {
                       f.world.setGravity({0, -past * kMaxGravity});
                   },
                   {"gravity", "kMaxGravity"});
    WorldDef worldDef = oneSubstepDef();
    worldDef.gravity = {past * kMaxGravity, 0};
    EXPECT_THROW(World{worldDef}, Error);
    ShapeDef shape;
    shape.friction = past * kMaxFriction;
    expectRejected(f.world, [&] { f.world.createShape(f.body, shape, Circle{}); },
                   {"def.friction", "kMaxFriction"});
    expectRejected(f.world,
                   [&] {
                       f.world.setJointMotor(f.joint, {true, past * kMaxAngularSpeed, 1.0f});
                   },
                   {"motor.speed", "kMaxAngularSpeed"});

    // Denormals are refused wherever a float is taken; zero is fine.
    const float denormal = std::numeric_limits<float>::denorm_min();
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyLinearVelocity(f.body, {denormal, 0});
                   },
                   {"velocity", "denormal"});
    expectRejected(f.world,
                   [&] {
                       f.world.setBodyTransform(f.body, {0, 1e-39f}, 0);
                   },
                   {"position", "denormal"});
    expectRejected(f.world, [&] { f.world.applyTorque(f.body, -denormal); },
                   {"torque", "denormal"});
    expectRejected(f.world,
                   [&] {
                       f.world.createShape(f.body, ShapeDef{},
                                           Polygon::fromPoints({{0, 0}, {1, denormal}, {0, 1}}));
                   },
                   {"polygon.vertices[1]", "denormal"});

    // At the limits.
    EXPECT_NO_THROW(f.world.setBodyLinearVelocity(f.body, {kMaxSpeed, -kMaxSpeed}));
    EXPECT_NO_THROW(f.world.setBodyAngularVelocity(f.body, -kMaxAngularSpeed));
    EXPECT_NO_THROW(f.world.setGravity({kMaxGravity, -kMaxGravity}));
    shape.friction = kMaxFriction;
    EXPECT_NO_THROW(f.world.createShape(f.body, shape, Circle{}));
}
