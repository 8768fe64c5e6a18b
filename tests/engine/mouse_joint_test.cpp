// The mouse joint: a soft spring pulling a body point to a target.
#include <gtest/gtest.h>

#include <cmath>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

BodyId ball(World& world, Vec2 p) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = p;
    BodyId b = world.createBody(def);
    world.createShape(b, ShapeDef{}, Circle{{0, 0}, 0.5f});
    return b;
}
}  // namespace

TEST(MouseJoint, HoldsABodyAtTheTargetAgainstGravityLikeASpring) {
    World world{oneSubstepDef()};
    BodyId b = ball(world, {0, 5});
    MouseJointDef def;
    def.body = b;
    def.target = {0, 5};
    def.maxForce = 1000.0f * world.bodyMass(b);
    MouseJointId mouse = world.createMouseJoint(def);
    for (int i = 0; i < 180; ++i) world.step(kDt);
    // A spring of 5 Hz sags by g / w^2 under gravity: 10 / (2 pi 5)^2 = 1 cm.
    float sag = 5.0f - world.bodyPosition(b).y;
    EXPECT_NEAR(sag, 10.0f / std::pow(2.0f * kPi * 5.0f, 2.0f), 2e-3f);
    // Moving the target drags the body after it.
    world.setMouseTarget(mouse, {3, 6});
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(b).x, 3.0f, 0.02f);
    EXPECT_NEAR(world.bodyPosition(b).y, 6.0f, 0.02f);
    EXPECT_EQ(world.mouseTarget(mouse), (Vec2{3, 6}));
}

TEST(MouseJoint, ItsForceIsCapped) {
    World world{oneSubstepDef()};
    BodyId b = ball(world, {0, 5});
    MouseJointDef def;
    def.body = b;
    def.target = {0, 5};
    def.maxForce = 0.5f * world.bodyMass(b) * 10.0f;  // half the weight
    world.createMouseJoint(def);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    // Net downward acceleration at least g/2: after 1 s it has fallen about 2.5 m or more.
    EXPECT_LT(world.bodyPosition(b).y, 5.0f - 2.0f);
}

TEST(MouseJoint, DestroyingItOrItsBodyReleases) {
    World world{oneSubstepDef()};
    BodyId b = ball(world, {0, 5});
    MouseJointDef def;
    def.body = b;
    def.target = {0, 5};
    MouseJointId mouse = world.createMouseJoint(def);
    world.step(kDt);
    world.destroyMouseJoint(mouse);
    EXPECT_FALSE(world.isValid(mouse));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(b).y, 4.0f);

    MouseJointId again = world.createMouseJoint(def);
    world.destroyBody(b);
    EXPECT_FALSE(world.isValid(again));
    world.step(kDt);  // nothing dangles
}

TEST(MouseJoint, BadDefsAreRejected) {
    World world{oneSubstepDef()};
    BodyId b = ball(world, {0, 5});
    BodyId ground = world.createBody(BodyDef{});
    std::uint64_t before = world.stateHash();
    MouseJointDef def;
    def.body = b;
    def.target = {0, 5};
    auto rejects = [&](MouseJointDef d, const char* word) {
        try {
            world.createMouseJoint(d);
            ADD_FAILURE() << "accepted " << word;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
    };
    MouseJointDef d = def;
    d.body = ground;
    rejects(d, "dynamic");
    d = def;
    d.target.x = std::nanf("");
    rejects(d, "def.target");
    d = def;
    d.maxForce = 0.0f;
    rejects(d, "def.maxForce");
    d = def;
    d.hertz = -1.0f;
    rejects(d, "def.hertz");
    d = def;
    d.dampingRatio = -0.5f;
    rejects(d, "def.dampingRatio");
    d = def;
    d.body = BodyId{};
    rejects(d, "null");
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_THROW(world.setMouseTarget(MouseJointId{}, {0, 0}), Error);
}
