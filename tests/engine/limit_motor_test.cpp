// The revolute joint's angle limit, under every position solver, and its motor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenes/scene.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {

constexpr float kDt = 1.0f / 60.0f;

std::string solverName(const testing::TestParamInfo<PositionSolver>& info) {
    return positionSolverName(info.param);
}

Scene limitedPendulum(PositionSolver solver) {
    SceneOptions options;
    options.solver = solver;
    return buildScene(*findScene("pendulum_limit"), options);
}

}  // namespace

class LimitUnderEverySolver : public testing::TestWithParam<PositionSolver> {};

TEST_P(LimitUnderEverySolver, TheSwingStopsAtTheLimitAndTurnsBack) {
    Scene scene = limitedPendulum(GetParam());
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    const float lower = world.jointLimit(joint).lower;
    int crossed = -1;
    int reversed = -1;
    for (int i = 0; i < 120 && reversed < 0; ++i) {
        world.step(kDt);
        if (crossed < 0 && world.jointAngle(joint) < lower) crossed = i;
        if (crossed >= 0 && world.jointSpeed(joint) > 0.0f) reversed = i;
    }
    ASSERT_GE(crossed, 0) << "the pendulum never reached its limit";
    // Whatever the solver, the limit turns the swing around within a quarter second.
    EXPECT_GE(reversed, 0);
    EXPECT_LE(reversed - crossed, 15);
}

INSTANTIATE_TEST_SUITE_P(PositionSolvers, LimitUnderEverySolver,
                         testing::Values(PositionSolver::Baumgarte, PositionSolver::PseudoVelocity,
                                         PositionSolver::ModifiedNGS, PositionSolver::FullNGS),
                         solverName);

class LimitHeldWithoutMomentum : public testing::TestWithParam<PositionSolver> {};

TEST_P(LimitHeldWithoutMomentum, OvershootStaysWithinOneCorrectionAndTheBallRestsOnTheLimit) {
    // The strategies that correct positions without adding momentum: the limit is overshot by
    // at most one step's worth (kMaxAngularCorrection caps a correction) and the pendulum ends
    // resting against it, within the angular slop.
    Scene scene = limitedPendulum(GetParam());
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    JointLimit limit = world.jointLimit(joint);
    float worst = 0.0f;
    for (int i = 0; i < 600; ++i) {
        world.step(kDt);
        float a = world.jointAngle(joint);
        worst = std::max({worst, limit.lower - a, a - limit.upper});
    }
    EXPECT_LT(worst, kMaxAngularCorrection);
    EXPECT_NEAR(world.jointAngle(joint), limit.lower, 2.0f * kAngularSlop);
    EXPECT_LT(world.jointSeparation(joint), kLinearSlop);
}

INSTANTIATE_TEST_SUITE_P(PositionSolvers, LimitHeldWithoutMomentum,
                         testing::Values(PositionSolver::PseudoVelocity,
                                         PositionSolver::ModifiedNGS, PositionSolver::FullNGS),
                         solverName);

TEST(Limit, EqualLimitsHoldTheAngle) {
    // lower == upper: the joint becomes a weld of its two bodies' angles. A 2 m plank pinned at
    // one end and held level against gravity.
    for (int s = 0; s < kPositionSolverCount; ++s) {
        auto solver = static_cast<PositionSolver>(s);
        World world{oneSubstepDef()};
        BodyId ground = world.createBody(BodyDef{});
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {1.0f, 5.0f};
        BodyId plank = world.createBody(def);
        world.createShape(plank, ShapeDef{}, Polygon::box(1.0f, 0.1f));
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(ground, plank, {0.0f, 5.0f});
        jd.positionSolver = solver;
        jd.limit = {true, 0.0f, 0.0f};
        JointId joint = world.createJoint(jd);
        float worst = 0.0f;
        for (int i = 0; i < 300; ++i) {
            world.step(kDt);
            worst = std::max(worst, std::fabs(world.jointAngle(joint)));
        }
        EXPECT_LT(worst, 0.1f) << positionSolverName(solver);
    }
}

TEST(Limit, SettingTheLimitWakesAndTakesEffect) {
    Scene scene = limitedPendulum(PositionSolver::FullNGS);
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    // It bounces on the limit, less each time, and comes to rest and sleeps after about 13 s
    // (as does Box2D 2.4.1's joint on the same scene, step for step).
    for (int i = 0; i < 900; ++i) world.step(kDt);
    ASSERT_NEAR(world.jointAngle(joint), -kPi / 3.0f, 2.0f * kAngularSlop);
    ASSERT_FALSE(world.isBodyAwake(scene.bodies[0]));
    world.setJointLimit(joint, {true, -kPi / 2.5f, kPi / 3.0f});
    EXPECT_TRUE(world.isBodyAwake(scene.bodies[0]));
    for (int i = 0; i < 300; ++i) world.step(kDt);
    EXPECT_NEAR(world.jointAngle(joint), -kPi / 2.5f, 2.0f * kAngularSlop);
    world.setJointLimit(joint, {false, 0.0f, 0.0f});
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_LT(world.jointAngle(joint), -kPi / 2.5f - 0.1f);  // free to hang lower
}

TEST(Motor, DrivesTheWheelAtItsSpeedAgainstGravity) {
    SceneOptions options;
    Scene scene = buildScene(*findScene("motor_wheel"), options);
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    float sum = 0.0f;
    const int steps = 600;
    for (int i = 0; i < steps; ++i) {
        world.step(kDt);
        if (i >= steps / 2) sum += world.jointSpeed(joint);
        // The motor never exceeds its torque.
        ASSERT_LE(std::fabs(world.jointMotorTorque(joint)), 30.0f * 1.0001f);
    }
    // Over whole turns gravity's work cancels: the average speed is the motor's.
    EXPECT_NEAR(sum / (steps / 2), 2.0f, 0.1f);
}

TEST(Motor, TooWeakAMotorStallsAtItsMaximumTorque) {
    SceneOptions options;
    Scene scene = buildScene(*findScene("motor_wheel"), options);
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    world.setJointMotor(joint, {true, 2.0f, 5.0f});  // gravity needs up to ~18 N m
    EXPECT_EQ(world.jointMotor(joint).maxTorque, 5.0f);
    bool saturated = false;
    for (int i = 0; i < 300; ++i) {
        world.step(kDt);
        saturated = saturated || std::fabs(world.jointMotorTorque(joint)) >= 5.0f * 0.9999f;
    }
    EXPECT_TRUE(saturated);
    // It cannot lift the weight over the top: the wheel rocks instead of turning.
    EXPECT_LT(std::fabs(world.bodyAngle(scene.bodies[0])), kPi);
}

TEST(Motor, ReactionTorqueIsTheMotorsWhenNoLimitActs) {
    SceneOptions options;
    Scene scene = buildScene(*findScene("motor_wheel"), options);
    World& world = *scene.world;
    JointId joint = scene.joints[0];
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_EQ(world.jointReactionTorque(joint), world.jointMotorTorque(joint));
    EXPECT_NE(world.jointMotorTorque(joint), 0.0f);
}
