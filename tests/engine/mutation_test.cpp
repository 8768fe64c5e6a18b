// Changing a world between steps keeps it consistent: body types, shape densities and joint
// solvers changed while things touch and hang, and bodies, shapes and joints destroyed while
// iterating the lists the API hands out.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

void steps(World& world, int n) {
    for (int i = 0; i < n; ++i) world.step(kDt);
}

BodyId groundWithFloor(World& world) {
    BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(20.0f, 0.5f));
    return ground;
}

BodyId box(World& world, BodyType type, Vec2 position, float half = 0.5f) {
    BodyDef def;
    def.type = type;
    def.position = position;
    BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Polygon::box(half, half));
    return body;
}

bool touching(const World& world, BodyId a, BodyId b) {
    for (const ContactData& c : world.contacts()) {
        BodyId x = world.shapeBody(c.shapeA), y = world.shapeBody(c.shapeB);
        if ((x == a && y == b) || (x == b && y == a)) return true;
    }
    return false;
}

bool allFinite(const World& world) {
    for (BodyId id : world.bodyIds()) {
        if (!isFinite(world.bodyPosition(id)) || !isFinite(world.bodyLinearVelocity(id)) ||
            !std::isfinite(world.bodyAngle(id)) || !std::isfinite(world.bodyAngularVelocity(id)))
            return false;
    }
    return true;
}

}  // namespace

TEST(SetBodyType, AStaticBodyMadeDynamicGetsItsMassFallsAndCollides) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    // Static, overlapping the floor's box: a static-static pair is never a contact.
    BodyId body = box(world, BodyType::Static, {0.0f, 1.2f});
    steps(world, 5);
    EXPECT_FALSE(touching(world, ground, body));
    EXPECT_EQ(world.bodyMass(body), 0.0f);

    world.setBodyType(body, BodyType::Dynamic);
    EXPECT_EQ(world.bodyType(body), BodyType::Dynamic);
    EXPECT_FLOAT_EQ(world.bodyMass(body), 1.0f);  // 1 m^2 at density 1
    EXPECT_GT(world.bodyRotationalInertia(body), 0.0f);
    EXPECT_TRUE(world.isBodyAwake(body));
    steps(world, 120);
    EXPECT_TRUE(touching(world, ground, body));
    EXPECT_NEAR(world.bodyPosition(body).y, 1.0f, 0.05f);  // resting on the floor
}

TEST(SetBodyType, ABodyMadeStaticStopsAndItsStaticContactsGo) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    BodyId body = box(world, BodyType::Dynamic, {0.0f, 1.0f});
    world.setBodySleepAllowed(body, false);
    steps(world, 60);
    ASSERT_TRUE(touching(world, ground, body));
    world.setBodyLinearVelocity(body, {3.0f, 1.0f});
    world.applyForceToCenter(body, {100.0f, 0.0f});

    world.setBodyType(body, BodyType::Static);
    EXPECT_EQ(world.bodyLinearVelocity(body), Vec2{});
    EXPECT_EQ(world.bodyAngularVelocity(body), 0.0f);
    EXPECT_EQ(world.bodyMass(body), 0.0f);
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
    Vec2 where = world.bodyPosition(body);

    world.step(kDt);
    EXPECT_FALSE(touching(world, ground, body));
    EXPECT_EQ(world.contactEndEvents().size(), 1u);
    EXPECT_EQ(world.lastStepStats().contactCount, 0);
    steps(world, 60);
    EXPECT_EQ(world.bodyPosition(body), where);

    // And back: the pair is found again and the box settles on the floor.
    world.setBodyType(body, BodyType::Dynamic);
    steps(world, 60);
    EXPECT_TRUE(touching(world, ground, body));
}

TEST(SetBodyType, AKinematicBodyKeepsTheVelocityOfItsOriginAndIgnoresGravity) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 10.0f};
    def.angularVelocity = 2.0f;
    BodyId body = world.createBody(def);
    // Off-centre, so the centre of mass is not the origin.
    world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.5f, {1.0f, 0.0f}, 0.0f));
    world.setBodyLinearVelocity(body, {1.0f, 0.0f});
    Vec2 originVelocity = world.bodyLinearVelocity(body) +
                          cross(world.bodyAngularVelocity(body),
                                world.bodyPosition(body) - world.bodyWorldCenter(body));

    world.setBodyType(body, BodyType::Kinematic);
    EXPECT_EQ(world.bodyMass(body), 0.0f);
    EXPECT_EQ(world.bodyWorldCenter(body), world.bodyPosition(body));
    EXPECT_NEAR(world.bodyLinearVelocity(body).x, originVelocity.x, 1e-6f);
    EXPECT_NEAR(world.bodyLinearVelocity(body).y, originVelocity.y, 1e-6f);
    EXPECT_EQ(world.bodyAngularVelocity(body), 2.0f);
    Vec2 velocity = world.bodyLinearVelocity(body);
    steps(world, 60);
    EXPECT_EQ(world.bodyLinearVelocity(body), velocity);  // no gravity on a kinematic body
    EXPECT_NEAR(world.bodyPosition(body).x, velocity.x, 1e-3f);
}

TEST(SetBodyType, KinematicAgainstStaticContactsAreDropped) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    BodyId body = box(world, BodyType::Dynamic, {0.0f, 1.0f});
    steps(world, 30);
    ASSERT_TRUE(touching(world, ground, body));
    world.setBodyType(body, BodyType::Kinematic);
    world.step(kDt);
    EXPECT_FALSE(touching(world, ground, body));
    EXPECT_EQ(world.lastStepStats().contactCount, 0);
}

TEST(SetBodyType, ADynamicBodyNeedsDensityInEveryShape) {
    World world{oneSubstepDef()};
    BodyId body = world.createBody(BodyDef{});  // static
    ShapeDef massless;
    massless.density = 0.0f;
    ShapeId shape = world.createShape(body, massless, Circle{});
    world.createShape(body, ShapeDef{}, Polygon::box(1.0f, 1.0f));
    std::uint64_t before = world.stateHash();
    try {
        world.setBodyType(body, BodyType::Dynamic);
        ADD_FAILURE() << "made a body with a zero-density shape dynamic";
    } catch (const Error& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("setBodyType"), std::string::npos) << message;
        EXPECT_NE(message.find("density 0"), std::string::npos) << message;
    }
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_EQ(world.bodyType(body), BodyType::Static);

    world.setShapeDensity(shape, 2.0f);
    world.setBodyType(body, BodyType::Dynamic);
    EXPECT_FLOAT_EQ(world.bodyMass(body), 4.0f + 2.0f * kPi * 0.25f);
    // Nor can a dynamic body's shape lose its density.
    before = world.stateHash();
    EXPECT_THROW(world.setShapeDensity(shape, 0.0f), Error);
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_THROW(world.setBodyType(body, static_cast<BodyType>(3)), Error);
    EXPECT_EQ(world.stateHash(), before);

    // A dynamic body without shapes is a unit point mass, as from createBody.
    BodyId bare = world.createBody(BodyDef{});
    world.setBodyType(bare, BodyType::Dynamic);
    EXPECT_EQ(world.bodyMass(bare), 1.0f);
    steps(world, 10);
    EXPECT_LT(world.bodyLinearVelocity(bare).y, 0.0f);
}

TEST(SetBodyType, WakesWhatRestsOnTheBody) {
    World world{oneSubstepDef()};
    groundWithFloor(world);
    BodyId platform = box(world, BodyType::Dynamic, {0.0f, 1.0f});
    BodyId top = box(world, BodyType::Dynamic, {0.0f, 2.0f});
    steps(world, 240);
    ASSERT_FALSE(world.isBodyAwake(top));
    ASSERT_FALSE(world.isBodyAwake(platform));
    world.setBodyType(platform, BodyType::Static);
    EXPECT_TRUE(world.isBodyAwake(top));
    steps(world, 60);
    EXPECT_TRUE(touching(world, platform, top));
    EXPECT_EQ(world.lastStepStats().contactCount, 1);  // platform-ground went
    EXPECT_NEAR(world.bodyPosition(top).y, 2.0f, 0.05f);
}

TEST(SetBodyType, JointsAndMouseJointsStayValid) {
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId bob = box(world, BodyType::Dynamic, {2.0f, 10.0f}, 0.25f);
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, bob, {0.0f, 10.0f}));
    MouseJointDef hand;
    hand.body = bob;
    hand.target = {2.0f, 10.0f};
    MouseJointId mouse = world.createMouseJoint(hand);
    steps(world, 30);

    world.setBodyType(bob, BodyType::Static);  // a joint between two static bodies
    steps(world, 30);
    world.setBodyType(bob, BodyType::Kinematic);
    world.setBodyAngularVelocity(bob, 1.0f);
    world.setMouseTarget(mouse, {0.0f, 0.0f});
    steps(world, 30);
    EXPECT_TRUE(world.isValid(pin));
    EXPECT_TRUE(world.isValid(mouse));
    EXPECT_TRUE(allFinite(world));
    EXPECT_TRUE(std::isfinite(world.jointReactionForce(pin).x));

    world.setBodyType(bob, BodyType::Dynamic);
    world.destroyMouseJoint(mouse);
    steps(world, 120);
    EXPECT_TRUE(allFinite(world));
    EXPECT_LT(world.jointSeparation(pin), 0.01f);
}

TEST(SetShapeDensity, RecomputesTheMassTheJointHolds) {
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId bob = box(world, BodyType::Dynamic, {0.0f, 5.0f}, 0.5f);
    world.setBodySleepAllowed(bob, false);
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, bob, {0.0f, 6.0f}));
    ShapeId shape = world.bodyShapes(bob)[0];
    steps(world, 60);
    float force = world.jointReactionForce(pin).y;
    EXPECT_NEAR(force, 10.0f, 0.01f);

    world.setShapeDensity(shape, 3.0f);
    EXPECT_EQ(world.shapeDensity(shape), 3.0f);
    EXPECT_FLOAT_EQ(world.bodyMass(bob), 3.0f);
    steps(world, 60);
    EXPECT_NEAR(world.jointReactionForce(pin).y, 30.0f, 0.05f);
    EXPECT_LT(world.jointSeparation(pin), kLinearSlop);

    // A second shape off-centre moves the centre of mass; the body keeps hanging.
    ShapeId extra = world.createShape(bob, ShapeDef{}, Circle{{0.5f, 0.0f}, 0.25f});
    world.setShapeDensity(extra, kMaxDensity);
    EXPECT_GT(world.bodyLocalCenter(bob).x, 0.4f);
    steps(world, 240);
    EXPECT_TRUE(allFinite(world));
    EXPECT_LT(world.jointSeparation(pin), 0.01f);
}

TEST(SetShapeDensity, OnAStaticBodyIsKeptForLater) {
    World world{oneSubstepDef()};
    BodyId body = world.createBody(BodyDef{});
    ShapeId shape = world.createShape(body, ShapeDef{}, Polygon::box(1.0f, 0.5f));
    world.setShapeDensity(shape, 0.0f);
    EXPECT_EQ(world.bodyMass(body), 0.0f);
    world.setShapeDensity(shape, 5.0f);
    EXPECT_EQ(world.bodyMass(body), 0.0f);
    world.setBodyType(body, BodyType::Dynamic);
    EXPECT_FLOAT_EQ(world.bodyMass(body), 10.0f);
}

// Types, densities and solvers changed between steps, run twice: the same bits.
TEST(Mutation, ChangesBetweenStepsRepeatBitForBit) {
    auto run = [] {
        World world{oneSubstepDef()};
        BodyId ground = groundWithFloor(world);
        std::vector<BodyId> links;
        std::vector<JointId> joints;
        BodyId previous = ground;
        for (int i = 0; i < 8; ++i) {
            BodyId link = box(world, BodyType::Dynamic, {0.5f + float(i), 8.0f}, 0.45f);
            joints.push_back(
                world.createJoint(RevoluteJointDef::atWorldAnchor(previous, link, {float(i), 8})));
            links.push_back(link);
            previous = link;
        }
        for (int i = 0; i < 6; ++i) box(world, BodyType::Dynamic, {-5.0f, 1.0f + 1.1f * i});
        for (int s = 0; s < 600; ++s) {
            if (s % 50 == 10) {
                for (std::size_t j = 0; j < joints.size(); ++j) {
                    world.setJointPositionSolver(
                        joints[j],
                        static_cast<PositionSolver>((s / 50 + j) % kPositionSolverCount));
                }
            }
            if (s % 120 == 60) world.setBodyType(links[3], BodyType::Static);
            if (s % 120 == 90) world.setBodyType(links[3], BodyType::Kinematic);
            if (s % 120 == 119) world.setBodyType(links[3], BodyType::Dynamic);
            if (s % 70 == 35) {
                ShapeId shape = world.bodyShapes(links[5])[0];
                world.setShapeDensity(shape, s % 140 == 35 ? 4.0f : 1.0f);
            }
            world.step(kDt);
        }
        EXPECT_TRUE(allFinite(world));
        // Held together (a link is 0.9 m long) with all six strategies taking turns.
        for (JointId j : joints) {
            EXPECT_LT(world.jointSeparation(j), 0.1f)
                << positionSolverName(world.jointPositionSolver(j));
        }
        return world.stateHash();
    };
    EXPECT_EQ(run(), run());
}

TEST(DestroyWhileIterating, EveryBodyFromBodyIds) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    BodyId previous = ground;
    for (int i = 0; i < 10; ++i) {
        BodyId b = box(world, BodyType::Dynamic, {float(i), 1.0f + 0.5f * i}, 0.4f);
        world.createJoint(RevoluteJointDef::atWorldAnchor(previous, b, {float(i), 1.0f}));
        previous = b;
    }
    steps(world, 30);
    for (BodyId id : world.bodyIds()) world.destroyBody(id);
    EXPECT_EQ(world.bodyCount(), 0);
    EXPECT_EQ(world.shapeCount(), 0);
    EXPECT_EQ(world.jointCount(), 0);
    EXPECT_TRUE(world.contacts().empty());
    steps(world, 2);
    EXPECT_EQ(world.lastStepStats().contactCount, 0);
}

TEST(DestroyWhileIterating, BodiesFoundInContacts) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    for (int i = 0; i < 12; ++i) box(world, BodyType::Dynamic, {0.1f * (i % 3), 1.0f + i}, 0.5f);
    steps(world, 180);
    std::vector<ContactData> contacts = world.contacts();
    ASSERT_GT(contacts.size(), 5u);
    int destroyed = 0;
    for (const ContactData& c : contacts) {
        // An earlier iteration may have destroyed this contact's bodies: the copy's ids go
        // stale, and isValid says so.
        for (ShapeId s : {c.shapeA, c.shapeB}) {
            if (!world.isValid(s)) continue;
            BodyId b = world.shapeBody(s);
            if (b == ground) continue;
            world.destroyBody(b);
            ++destroyed;
        }
    }
    EXPECT_EQ(world.bodyCount(), 13 - destroyed);
    steps(world, 60);
    EXPECT_TRUE(allFinite(world));
}

TEST(DestroyWhileIterating, JointsAndShapesFromEvents) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    BodyId previous = ground;
    for (int i = 0; i < 6; ++i) {
        BodyId b = box(world, BodyType::Dynamic, {float(i) + 0.5f, 3.0f}, 0.45f);
        world.createJoint(RevoluteJointDef::atWorldAnchor(previous, b, {float(i), 3.0f}));
        previous = b;
    }
    for (JointId j : world.jointIds()) {
        if (j.index % 2 == 0) world.destroyJoint(j);
    }
    EXPECT_EQ(world.jointCount(), 3);
    for (JointId j : world.jointIds()) EXPECT_TRUE(world.isValid(j));

    // The first touches of the ground: destroy the shapes they name, while iterating the
    // events, which are a copy that the destruction appends to.
    int ended = 0;
    for (int s = 0; s < 240 && ended == 0; ++s) {
        world.step(kDt);
        for (const ContactEvent& e : world.contactBeginEvents()) {
            ShapeId mine = world.shapeBody(e.shapeA) == ground ? e.shapeB : e.shapeA;
            if (!world.isValid(mine)) continue;
            world.destroyShape(mine);
            ++ended;
        }
    }
    EXPECT_GT(ended, 0);
    EXPECT_EQ(static_cast<int>(world.contactEndEvents().size()), ended);
    for (const ContactEvent& e : world.contactEndEvents()) {
        EXPECT_FALSE(world.isValid(e.shapeA) && world.isValid(e.shapeB));
    }
    steps(world, 60);
    EXPECT_TRUE(allFinite(world));
}

TEST(Destroy, ABodyWakesWhatRestedOnItAndTakesItsJointsAndShapes) {
    World world{oneSubstepDef()};
    BodyId ground = groundWithFloor(world);
    BodyId platform = box(world, BodyType::Dynamic, {0.0f, 1.0f});
    world.createShape(platform, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.2f});
    BodyId top = box(world, BodyType::Dynamic, {0.0f, 2.0f});
    BodyId hanging = box(world, BodyType::Dynamic, {5.0f, 1.0f}, 0.2f);
    world.createJoint(RevoluteJointDef::atWorldAnchor(platform, hanging, {5.0f, 1.0f}));
    MouseJointDef hand;
    hand.body = platform;
    MouseJointId mouse = world.createMouseJoint(hand);
    world.destroyMouseJoint(mouse);
    mouse = world.createMouseJoint(hand);
    world.destroyMouseJoint(mouse);
    steps(world, 300);
    ASSERT_FALSE(world.isBodyAwake(top));
    int shapes = world.shapeCount();

    world.destroyBody(platform);
    EXPECT_TRUE(world.isBodyAwake(top));
    EXPECT_TRUE(world.isBodyAwake(hanging));
    EXPECT_EQ(world.shapeCount(), shapes - 2);
    EXPECT_EQ(world.jointCount(), 0);
    steps(world, 60);
    EXPECT_TRUE(touching(world, ground, top));
}
