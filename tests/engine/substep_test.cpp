// WorldDef::substepCount: a step solved as n substeps of dt / n.
#include <gtest/gtest.h>

#include "pivot/pivot.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"
#include "scoped_switch.h"
#include "solver/island_solver.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {

BodyId fallingBall(World& world) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 10.0f};
    const BodyId body = world.createBody(def);
    ShapeDef shape;
    shape.density = 1.0f;
    world.createShape(body, shape, Circle{{0.0f, 0.0f}, 0.5f});
    return body;
}

// The largest joint separation of `scene` over a run with the given substeps.
double maxSeparation(const char* name, PositionSolver solver, int substeps, int steps) {
    SceneOptions options;
    options.solver = solver;
    options.substepCount = substeps;
    Scene scene = buildScene(*findScene(name), options);
    RunSettings settings;
    settings.steps = steps;
    return runScene(scene, settings).maxSeparation;
}

}  // namespace

TEST(Substeps, CountIsValidated) {
    for (int bad : {0, -1, kMaxSubsteps + 1}) {
        WorldDef def = oneSubstepDef();
        def.substepCount = bad;
        EXPECT_THROW(World{def}, Error) << bad;
    }
    World world{oneSubstepDef()};
    fallingBall(world);
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(world.setSubstepCount(0), Error);
    EXPECT_THROW(world.setSubstepCount(kMaxSubsteps + 1), Error);
    EXPECT_EQ(world.substepCount(), 1);
    EXPECT_EQ(world.stateHash(), before);

    // Each substep must still be at least kMinTimeStep long.
    world.setSubstepCount(4);
    EXPECT_THROW(world.step(2.0f * kMinTimeStep), Error);
    world.setSubstepCount(1);
    EXPECT_EQ(world.stateHash(), before);
    world.setSubstepCount(2);
    EXPECT_NO_THROW(world.step(2.0f * kMinTimeStep));
    EXPECT_EQ(world.substepCount(), 2);
}

TEST(Substeps, AFreeFallIsIntegratedInEachSubstep) {
    // Semi-implicit Euler per substep: after n substeps of h from rest, v = -g n h and the drop
    // is g h^2 (1 + 2 + ... + n). One substep of dt drops g dt^2; four drop 10/16 of that.
    for (int n : {1, 4}) {
        WorldDef def = oneSubstepDef();
        def.substepCount = n;
        World world(def);
        const BodyId ball = fallingBall(world);
        const float dt = 1.0f / 60.0f;
        world.step(dt);
        const float h = dt / static_cast<float>(n);
        EXPECT_NEAR(world.bodyLinearVelocity(ball).y, -10.0f * dt, 1e-5f) << n;
        const float drop = 10.0f * h * h * static_cast<float>(n * (n + 1) / 2);
        EXPECT_NEAR(10.0f - world.bodyPosition(ball).y, drop, 1e-5f) << n;
    }
}

TEST(Substeps, HoldAHeavyChainBetterThanOneStep) {
    // ball_chain: a ball of 600 links' mass on 40 links. Substeps shorten the step each
    // constraint is linearised over: the measured separations drop by orders of magnitude.
    for (PositionSolver solver : {PositionSolver::Baumgarte, PositionSolver::FullNGS}) {
        const double one = maxSeparation("ball_chain", solver, 1, 300);
        const double eight = maxSeparation("ball_chain", solver, 8, 300);
        EXPECT_GT(one, 1.0) << positionSolverName(solver);
        EXPECT_LT(eight, 0.1) << positionSolverName(solver);
    }
}

TEST(Substeps, TheNumberOfWorkersChangesNothing) {
    for (const char* name : {"bridge", "pyramid", "ragdoll", "pendulum_drag", "pulley_gear"}) {
        std::uint64_t hashes[2];
        for (int workers = 1; workers <= 2; ++workers) {
            SceneOptions options;
            options.workerCount = workers;
            options.substepCount = 4;
            Scene scene = buildScene(*findScene(name), options);
            RunSettings settings;
            settings.steps = 200;
            runScene(scene, settings);
            hashes[workers - 1] = scene.world->stateHash();
        }
        EXPECT_EQ(hashes[0], hashes[1]) << name;
    }
}

TEST(Substeps, ChangingTheCountBetweenStepsKeepsTheSceneTogether) {
    SceneOptions options;
    Scene scene = buildScene(*findScene("bridge"), options);
    for (int i = 0; i < 240; ++i) {
        if (i % 60 == 0) scene.world->setSubstepCount(1 + (i / 60) % 3 * 3);  // 1, 4, 7, 1
        scene.world->step(1.0f / 60.0f);
        ASSERT_FALSE(isBlownUp(scene)) << i;
        ASSERT_LT(sampleSeparation(scene).max, 0.05) << i;
    }
}

namespace {

using JointRemeasuring = ScopedSwitch<&setJointRemeasuring>;

}  // namespace

TEST(Substeps, JointsKeptAcrossSubstepsStepToTheSameBitsAsRebuilt) {
    // Scenes with limits and motors (pendulum_limit, motor_wheel, ragdoll_motorized), a mouse
    // joint (pendulum_drag), let-go joints (platformer), every joint type (weld_beam, car,
    // elevator, pulley_gear, distance_pendulum) and a coloured island (bridge_heavy is not
    // one: chain_drag's hundred links are not either; the team tests cover colours).
    const char* names[] = {"pendulum_limit", "motor_wheel", "bridge",           "ragdoll_motorized",
                           "pendulum_drag",  "platformer",  "weld_beam",        "car",
                           "elevator",       "pulley_gear", "distance_pendulum"};
    for (const char* name : names) {
        for (int s = 0; s < kPositionSolverCount; ++s) {
            for (int workers = 1; workers <= 2; ++workers) {
                SceneOptions options;
                options.solver = static_cast<PositionSolver>(s);
                options.substepCount = 4;
                options.workerCount = workers;
                Scene kept = buildScene(*findScene(name), options);
                Scene rebuilt = buildScene(*findScene(name), options);
                for (int i = 0; i < 200; ++i) {
                    if (kept.beforeStep) kept.beforeStep(kept, i);
                    if (rebuilt.beforeStep) rebuilt.beforeStep(rebuilt, i);
                    {
                        JointRemeasuring on(true);
                        kept.world->step(1.0f / options.hz);
                    }
                    {
                        JointRemeasuring off(false);
                        rebuilt.world->step(1.0f / options.hz);
                    }
                    ASSERT_EQ(kept.world->stateHash(), rebuilt.world->stateHash())
                        << name << " " << positionSolverName(options.solver) << ", workers "
                        << workers << ", step " << i;
                }
            }
        }
    }
}
