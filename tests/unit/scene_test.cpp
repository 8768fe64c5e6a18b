// The seed note's three systems, run through the shared scene library.
#include <gtest/gtest.h>

#include "scenes/metrics.h"
#include "scenes/scene.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {
Scene build(const char* name, PositionSolver solver) {
    SceneOptions options;
    options.solver = solver;
    return buildScene(*findScene(name), options);
}
}  // namespace

TEST(Scenes, ListTheSeedNotesSystems) {
    ASSERT_NE(findScene("pendulum"), nullptr);
    ASSERT_NE(findScene("bridge"), nullptr);
    ASSERT_NE(findScene("chain"), nullptr);
    EXPECT_EQ(findScene("nope"), nullptr);
    EXPECT_EQ(build("bridge", PositionSolver::FullNGS).joints.size(), 31u);
    EXPECT_EQ(build("chain", PositionSolver::FullNGS).joints.size(), 30u);
}

TEST(Scenes, PendulumStartsAt100RadPerSecondAndTheClampEngages) {
    Scene scene = build("pendulum", PositionSolver::FullNGS);
    World& world = *scene.world;
    BodyId ball = scene.bodies[0];
    EXPECT_EQ(world.bodyAngularVelocity(ball), 100.0f);
    EXPECT_NEAR(length(world.bodyLinearVelocity(ball)), 500.0f, 1e-3f);
    EXPECT_NEAR(world.jointSeparation(scene.joints[0]), 0.0f, 1e-6f);
    world.step(1.0f / 60.0f);
    EXPECT_EQ(world.lastStepStats().translationClamps, 1);
    EXPECT_EQ(world.lastStepStats().rotationClamps, 1);
    // The clamp scales the velocity itself: 2 m per step at 60 Hz is 120 m/s.
    EXPECT_NEAR(length(world.bodyLinearVelocity(ball)), kMaxTranslation * 60.0f, 1e-3f);
}

TEST(Scenes, FullNgsKeepsThePendulumOnItsStick) {
    Scene scene = build("pendulum", PositionSolver::FullNGS);
    World& world = *scene.world;
    const Vec2 pivot = world.jointAnchorA(scene.joints[0]);
    RunSettings settings;
    settings.steps = 1;
    RunMetrics first = runScene(scene, settings);
    // The first step, at the clamp, may leave a sub-millimetre error; after it, never the slop.
    EXPECT_LT(first.maxSeparation, 1e-3);
    float worst = 0.0f;
    for (int i = 0; i < 599; ++i) {
        world.step(1.0f / 60.0f);
        worst = std::max(worst, world.jointSeparation(scene.joints[0]));
        float radius = distance(world.bodyWorldCenter(scene.bodies[0]), pivot);
        ASSERT_NEAR(radius, 5.0f, kLinearSlop) << "step " << i;
    }
    EXPECT_LT(worst, kLinearSlop);
    EXPECT_FALSE(isBlownUp(scene));
}

TEST(Scenes, FullNgsKeepsTheChainTogether) {
    Scene scene = build("chain", PositionSolver::FullNGS);
    RunSettings settings;
    RunMetrics m = runScene(scene, settings);
    EXPECT_FALSE(m.blewUp);
    EXPECT_EQ(m.steps, 600);
    EXPECT_LT(m.maxSeparation, 0.1);            // never 10 cm apart while falling and whipping
    EXPECT_LT(m.finalSeparation, kLinearSlop);  // and back within slop at the end
    // A free chain only loses energy to the solver; it never gains.
    EXPECT_LT(m.energyEnd, m.energyStart);
}

TEST(Scenes, FullNgsKeepsTheBridgeUp) {
    Scene scene = build("bridge", PositionSolver::FullNGS);
    RunMetrics m = runScene(scene, RunSettings{});
    EXPECT_FALSE(m.blewUp);
    EXPECT_LT(m.maxSeparation, 0.1);
    // The middle plank sags but hangs near the deck's height (5 m): no collapse.
    Vec2 middle = scene.world->bodyWorldCenter(scene.bodies[15]);
    EXPECT_GT(middle.y, 2.0f);
    EXPECT_LT(middle.y, 5.0f);
}

class EverySceneAndSolver : public testing::TestWithParam<std::tuple<const char*, PositionSolver>> {
};

TEST_P(EverySceneAndSolver, RunsAndReportsFiniteMetrics) {
    Scene scene = build(std::get<0>(GetParam()), std::get<1>(GetParam()));
    RunSettings settings;
    settings.steps = 120;
    RunMetrics m = runScene(scene, settings);
    EXPECT_GT(m.steps, 0);
    EXPECT_TRUE(std::isfinite(m.rmsSeparation) || m.blewUp);
    EXPECT_GE(m.maxSeparation, m.rmsSeparation);
    EXPECT_GT(m.microsecondsPerStep, 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, EverySceneAndSolver,
    testing::Combine(testing::Values("pendulum", "bridge", "chain"),
                     testing::Values(PositionSolver::Baumgarte, PositionSolver::PseudoVelocity,
                                     PositionSolver::ModifiedNGS, PositionSolver::FullNGS)),
    [](const auto& info) {
        return std::string(std::get<0>(info.param)) + "_" +
               positionSolverName(std::get<1>(info.param));
    });
