// Revolute joint basics common to every solver: anchors, reference angle, warm starting,
// reaction force.
#include <gtest/gtest.h>

#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

struct HangingBox {
    World world{oneSubstepDef()};
    BodyId ground, box;
    JointId joint;

    explicit HangingBox(const WorldDef& def = oneSubstepDef()) : world(def) {
        ground = world.createBody(BodyDef{});
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {0, 4};
        box = world.createBody(bd);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
        joint = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, box, {0, 4.5f}));
    }
};
}  // namespace

TEST(RevoluteJoint, WorldAnchorBecomesLocalAnchorsAndReferenceAngle) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.position = {1, 2};
    bd.angle = 0.3f;
    BodyId a = world.createBody(bd);
    bd.type = BodyType::Dynamic;
    bd.position = {4, 2};
    bd.angle = -0.2f;
    BodyId b = world.createBody(bd);
    JointId j = world.createJoint(RevoluteJointDef::atWorldAnchor(a, b, {3, 3}));
    Vec2 pA = world.jointAnchorA(j), pB = world.jointAnchorB(j);
    EXPECT_NEAR(pA.x, 3.0f, 1e-6f);
    EXPECT_NEAR(pA.y, 3.0f, 1e-6f);
    EXPECT_NEAR(pB.x, 3.0f, 1e-6f);
    EXPECT_NEAR(pB.y, 3.0f, 1e-6f);
    EXPECT_EQ(world.jointBodyA(j), a);
    EXPECT_EQ(world.jointBodyB(j), b);
}

TEST(RevoluteJoint, LocalAnchorsGiveTheSameJointAsTheWorldAnchor) {
    auto run = [](bool useLocal) {
        World world{oneSubstepDef()};
        BodyId ground = world.createBody(BodyDef{});
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {2, 0};
        BodyId body = world.createBody(bd);
        world.createShape(body, ShapeDef{}, Polygon::box(1, 0.25f));
        RevoluteJointDef jd;
        if (useLocal) {
            jd.bodyA = ground;
            jd.bodyB = body;
            jd.localAnchorA = {1, 0};
            jd.localAnchorB = {-1, 0};
        } else {
            jd = RevoluteJointDef::atWorldAnchor(ground, body, {1, 0});
        }
        world.createJoint(jd);
        for (int i = 0; i < 120; ++i) world.step(kDt);
        return world.stateHash();
    };
    EXPECT_EQ(run(true), run(false));
}

TEST(RevoluteJoint, ReactionForceHoldsTheWeightAndSurvivesAChangeOfTimeStep) {
    HangingBox rig;
    rig.world.setBodySleepAllowed(rig.box, false);
    for (int i = 0; i < 120; ++i) rig.world.step(kDt);
    float weight = rig.world.bodyMass(rig.box) * 10.0f;
    EXPECT_NEAR(rig.world.jointReactionForce(rig.joint).y, weight, 1e-3f * weight);
    // Warm-start impulses are scaled by the ratio of time steps, so the force they stand for
    // carries over when dt halves and the box stays put.
    rig.world.step(kDt / 2);
    EXPECT_NEAR(rig.world.jointReactionForce(rig.joint).y, weight, 1e-3f * weight);
    EXPECT_LT(length(rig.world.bodyLinearVelocity(rig.box)), 1e-3f);
}

TEST(RevoluteJoint, ASleepingJointReportsTheForceItHeld) {
    HangingBox rig;
    for (int i = 0; i < 120; ++i) rig.world.step(kDt);
    ASSERT_FALSE(rig.world.isBodyAwake(rig.box));
    float weight = rig.world.bodyMass(rig.box) * 10.0f;
    rig.world.step(kDt / 2);  // the sleeping joint is not solved at the new dt
    EXPECT_NEAR(rig.world.jointReactionForce(rig.joint).y, weight, 1e-3f * weight);
}

TEST(RevoluteJoint, WarmStartingCanBeSwitchedOff) {
    // A single pin is solved exactly by one 2x2 solve, warm start or not; a chain couples its
    // joints, so Gauss-Seidel does not converge in 8 sweeps and the warm start shows.
    auto chain = [](bool warmStarting) {
        WorldDef def = oneSubstepDef();
        def.warmStarting = warmStarting;
        World world(def);
        BodyId previous = world.createBody(BodyDef{});
        JointId last;
        for (int i = 0; i < 10; ++i) {
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.position = {0.5f + float(i), 10};
            BodyId link = world.createBody(bd);
            world.createShape(link, ShapeDef{}, Polygon::box(0.6f, 0.125f));
            last =
                world.createJoint(RevoluteJointDef::atWorldAnchor(previous, link, {float(i), 10}));
            previous = link;
        }
        for (int i = 0; i < 120; ++i) world.step(kDt);
        EXPECT_LT(world.jointSeparation(last), 0.05f);
        return world.stateHash();
    };
    EXPECT_NE(chain(false), chain(true));
}

TEST(RevoluteJoint, DestroyingAJointFreesTheBody) {
    HangingBox rig;
    rig.world.destroyJoint(rig.joint);
    EXPECT_FALSE(rig.world.isValid(rig.joint));
    for (int i = 0; i < 30; ++i) rig.world.step(kDt);
    EXPECT_LT(rig.world.bodyPosition(rig.box).y, 3.0f);  // falls
}
