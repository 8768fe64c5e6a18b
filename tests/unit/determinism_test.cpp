// Same inputs, same binary: bit-identical results.
#include <gtest/gtest.h>

#include "scenes/metrics.h"
#include "scenes/scene.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {
std::uint64_t hashAfter(const SceneInfo& info, PositionSolver solver, int steps) {
    SceneOptions options;
    options.solver = solver;
    Scene scene = buildScene(info, options);
    for (int i = 0; i < steps; ++i) scene.world->step(1.0f / 60.0f);
    return scene.world->stateHash();
}
}  // namespace

TEST(Determinism, EverySceneAndSolverRepeatsBitForBit) {
    for (const SceneInfo& info : allScenes()) {
        for (int s = 0; s < kPositionSolverCount; ++s) {
            auto solver = static_cast<PositionSolver>(s);
            EXPECT_EQ(hashAfter(info, solver, 300), hashAfter(info, solver, 300))
                << info.name << " " << positionSolverName(solver);
        }
    }
}

TEST(Determinism, TheHashSeesEveryStep) {
    const SceneInfo& chain = *findScene("chain");
    EXPECT_NE(hashAfter(chain, PositionSolver::FullNGS, 10),
              hashAfter(chain, PositionSolver::FullNGS, 11));
    EXPECT_NE(hashAfter(chain, PositionSolver::FullNGS, 10),
              hashAfter(chain, PositionSolver::Baumgarte, 10));
}

TEST(Determinism, WorldsDoNotShareState) {
    // Two worlds stepped in interleaved order give the same result as one alone.
    const SceneInfo& bridge = *findScene("bridge");
    SceneOptions options;
    Scene a = buildScene(bridge, options);
    Scene b = buildScene(bridge, options);
    for (int i = 0; i < 100; ++i) {
        a.world->step(1.0f / 60.0f);
        b.world->step(1.0f / 60.0f);
    }
    EXPECT_EQ(a.world->stateHash(), b.world->stateHash());
    EXPECT_EQ(a.world->stateHash(), hashAfter(bridge, PositionSolver::FullNGS, 100));
}

TEST(Determinism, TheNumberOfWorkersChangesNothing) {
    // Islands, contact updates and broad-phase queries are shared among the workers, and every
    // result is merged in a fixed order: the state is bit-identical for any worker count.
    for (const SceneInfo& info : allScenes()) {
        std::uint64_t hashes[2];
        for (int workers = 1; workers <= 2; ++workers) {
            SceneOptions options;
            options.workerCount = workers;
            Scene scene = buildScene(info, options);
            RunSettings settings;
            settings.steps = 300;
            runScene(scene, settings);
            hashes[workers - 1] = scene.world->stateHash();
        }
        EXPECT_EQ(hashes[0], hashes[1]) << info.name;
    }
}
