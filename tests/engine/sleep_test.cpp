// Sleeping: islands at rest sleep; new contacts, joint changes and API calls wake them; sleep
// can be switched off for the world and for a body.
#include <gtest/gtest.h>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct RestingBox {
    World world{oneSubstepDef()};
    BodyId ground, box;

    explicit RestingBox(const WorldDef& def = oneSubstepDef()) : world(def) {
        ground = world.createBody(BodyDef{});
        ShapeDef slab;
        slab.density = 0.0f;
        world.createShape(ground, slab, Polygon::box(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
        box = addBox({0.0f, 0.515f});
    }

    BodyId addBox(Vec2 p) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = p;
        BodyId b = world.createBody(def);
        world.createShape(b, ShapeDef{}, Polygon::box(0.5f, 0.5f));
        return b;
    }

    void run(int steps) {
        for (int i = 0; i < steps; ++i) world.step(kDt);
    }
};

}  // namespace

TEST(Sleep, ARestingIslandSleepsAfterHalfASecondAndCostsNothing) {
    RestingBox rig;
    rig.run(20);
    EXPECT_TRUE(rig.world.isBodyAwake(rig.box));
    rig.run(60);
    EXPECT_FALSE(rig.world.isBodyAwake(rig.box));
    EXPECT_EQ(rig.world.bodyLinearVelocity(rig.box), (Vec2{0, 0}));
    rig.world.step(kDt);
    EXPECT_EQ(rig.world.lastStepStats().islandCount, 0);
}

TEST(Sleep, CanBeSwitchedOffForTheWorldAndForABody) {
    WorldDef def = oneSubstepDef();
    def.enableSleep = false;
    RestingBox noSleep(def);
    noSleep.run(120);
    EXPECT_TRUE(noSleep.world.isBodyAwake(noSleep.box));

    RestingBox rig;
    rig.world.setBodySleepAllowed(rig.box, false);
    rig.run(120);
    EXPECT_TRUE(rig.world.isBodyAwake(rig.box));
    rig.world.setBodySleepAllowed(rig.box, true);
    rig.run(60);
    EXPECT_FALSE(rig.world.isBodyAwake(rig.box));
    // Switching sleep off for the world wakes everything.
    rig.world.setSleepEnabled(false);
    EXPECT_TRUE(rig.world.isBodyAwake(rig.box));
}

TEST(Sleep, ANewContactWakesASleepingBody) {
    RestingBox rig;
    rig.run(120);
    ASSERT_FALSE(rig.world.isBodyAwake(rig.box));
    BodyId falling = rig.addBox({0.2f, 4.0f});
    bool woke = false;
    for (int i = 0; i < 60 && !woke; ++i) {
        rig.world.step(kDt);
        woke = rig.world.isBodyAwake(rig.box);
    }
    EXPECT_TRUE(woke);
    EXPECT_GT(rig.world.bodyPosition(falling).y, 1.0f);  // landed on the box, not through it
}

TEST(Sleep, ApiCallsThatMoveOrPushWake) {
    auto asleep = [] {
        auto rig = std::make_unique<RestingBox>();
        rig->run(120);
        EXPECT_FALSE(rig->world.isBodyAwake(rig->box));
        return rig;
    };
    auto rig = asleep();
    rig->world.applyForceToCenter(rig->box, {10, 0});
    EXPECT_TRUE(rig->world.isBodyAwake(rig->box));
    rig = asleep();
    rig->world.applyLinearImpulse(rig->box, {0, 1}, rig->world.bodyWorldCenter(rig->box));
    EXPECT_TRUE(rig->world.isBodyAwake(rig->box));
    rig = asleep();
    rig->world.setBodyLinearVelocity(rig->box, {1, 0});
    EXPECT_TRUE(rig->world.isBodyAwake(rig->box));
    rig = asleep();
    rig->world.setBodyTransform(rig->box, {1, 0.515f}, 0);
    EXPECT_TRUE(rig->world.isBodyAwake(rig->box));
    rig = asleep();
    rig->world.setGravity({0, -9});
    EXPECT_TRUE(rig->world.isBodyAwake(rig->box));
}

TEST(Sleep, JointChangesWake) {
    RestingBox rig;
    BodyId other = rig.addBox({3.0f, 0.515f});
    rig.run(120);
    ASSERT_FALSE(rig.world.isBodyAwake(rig.box));
    JointId joint =
        rig.world.createJoint(RevoluteJointDef::atWorldAnchor(rig.box, other, {1.5f, 0.5f}));
    EXPECT_TRUE(rig.world.isBodyAwake(rig.box));
    EXPECT_TRUE(rig.world.isBodyAwake(other));
    rig.run(120);
    ASSERT_FALSE(rig.world.isBodyAwake(rig.box));
    rig.world.setJointPositionSolver(joint, PositionSolver::Baumgarte);
    EXPECT_TRUE(rig.world.isBodyAwake(rig.box));
    rig.run(120);
    ASSERT_FALSE(rig.world.isBodyAwake(other));
    rig.world.destroyJoint(joint);
    EXPECT_TRUE(rig.world.isBodyAwake(other));
}

TEST(Sleep, ABodyCreatedAsleepStaysPutUntilWoken) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0, 10};
    def.isAwake = false;
    BodyId body = world.createBody(def);
    // Its shapes do not wake it (as in Box2D), so a scene can be built asleep.
    world.createShape(body, ShapeDef{}, Circle{});
    EXPECT_FALSE(world.isBodyAwake(body));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_EQ(world.bodyPosition(body).y, 10.0f);
    world.setBodyAwake(body, true);
    world.step(kDt);
    EXPECT_LT(world.bodyPosition(body).y, 10.0f);
}

TEST(Sleep, ABodyCreatedAsleepWakesWhenSomethingAwakeTouchesIt) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0, 0};
    def.isAwake = false;
    BodyId sleeper = world.createBody(def);
    world.createShape(sleeper, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    def.isAwake = true;
    def.position = {0, 3};
    BodyId faller = world.createBody(def);
    world.createShape(faller, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    int steps = 0;
    while (!world.isBodyAwake(sleeper) && steps < 120) {
        world.step(kDt);
        ++steps;
    }
    EXPECT_TRUE(world.isBodyAwake(sleeper));
    // Woken as the falling box reached it (about 0.6 s), not before.
    EXPECT_GT(steps, 30);
    EXPECT_LT(steps, 60);
}
