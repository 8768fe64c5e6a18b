// Bad input is rejected with a message that names the problem, and the world is unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pivot/pivot.h"

using namespace pivot;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A small world with a body, a shape and a joint, stepped once so velocities, impulses and
// forces are non-trivial.
struct Fixture {
    World world;
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
        {"repeated vertices"});
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
                   {"circle.radius", "> 0", "0"});
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
    bad.restitution = 1.5f;
    expectRejected(f.world, [&] { f.world.createShape(f.body, bad, Circle{}); },
                   {"def.restitution", "1.5"});
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
    expectRejected(f.world,
                   [&] { f.world.setJointPositionSolver(f.joint, static_cast<PositionSolver>(4)); },
                   {"solver", "4"});
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
    EXPECT_FALSE(f.world.isValid(elsewhere.body));
    EXPECT_FALSE(f.world.isValid(BodyId{}));
}

TEST(Validation, StepArguments) {
    Fixture f;
    expectRejected(f.world, [&] { f.world.step(0.0f); }, {"step", "dt", "> 0"});
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
}

TEST(Validation, WorldDef) {
    WorldDef def;
    def.gravity.y = kNaN;
    EXPECT_THROW(World{def}, Error);
    def = WorldDef{};
    def.defaultPositionSolver = static_cast<PositionSolver>(5);
    EXPECT_THROW(World{def}, Error);
    def = WorldDef{};
    def.contactCorrection = static_cast<ContactCorrection>(2);
    EXPECT_THROW(World{def}, Error);
    def = WorldDef{};
    def.contactBiasFactor = 1.5f;
    EXPECT_THROW(World{def}, Error);
    def = WorldDef{};
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
