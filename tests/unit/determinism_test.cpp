// Same inputs, same binary: bit-identical results.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>

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

namespace {

// A scene run as the testbed runs it (scripted events included) for `steps` steps at 60 Hz.
std::uint64_t hashOfRun(const SceneInfo& info, PositionSolver solver, int steps) {
    SceneOptions options;
    options.solver = solver;
    Scene scene = buildScene(info, options);
    for (int i = 0; i < steps; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, i);
        scene.world->step(1.0f / options.hz);
    }
    return scene.world->stateHash();
}

struct RecordedHashes {
    const char* scene;
    std::uint64_t hash[kPositionSolverCount];  // in PositionSolver order
};

// World::stateHash of every scene with every position solver after 600 steps, so that any
// change to the numerics (or to what the hash covers) is seen here and made on purpose. After
// an intended change, regenerate the table with
//   PIVOT_PRINT_HASHES=1 ./build/tests/pivot-tests --gtest_filter=Determinism.RecordedHashes
// which prints it in this form, and paste it over this one. Recorded with GCC 12 on x86-64
// (Release and the Debug sanitizer build agree); other compilers and CPUs may differ
// (docs/reliability.md).
// clang-format off
const RecordedHashes kRecorded[] = {
    // scene               baumgarte             pseudo_velocity       modified_ngs          full_ngs
    {"pendulum",          {0x83b30e6889034ab5ull, 0xd2111d8e40385484ull, 0x25ac08b15bfcc48cull, 0x82927eeab6de712full}},
    {"pendulum_limit",    {0x74d08a8f4beca25eull, 0x1f1bf7f8eef10fe5ull, 0x026dc6a9d53acffdull, 0x28b89379497326b9ull}},
    {"double_pendulum",   {0x16d88708eef00c0cull, 0xa199e1e4e99c18ddull, 0x65a4516435a227a5ull, 0x6b908c1417c47ddaull}},
    {"motor_wheel",       {0x3edfd3d374ca88d0ull, 0xe32acc649f0ae6e7ull, 0x991564c85f89bc6dull, 0xdfbd3568b6c32779ull}},
    {"bridge",            {0x272d1b91024d20d7ull, 0x3bde71a77bb2d47aull, 0x91136a05125df05bull, 0x704c328b76100c9aull}},
    {"chain",             {0xe4e453049dc9509cull, 0x7b7d0e65d28cff44ull, 0x76f5c3e551f3b7cbull, 0x06930357cb67703full}},
    {"bridge_heavy",      {0x0d25904fe7c80344ull, 0x7dc48342e81894bfull, 0x5a4ba3009c95e357ull, 0x9b1ae70e97fcdd72ull}},
    {"pyramid",           {0x3a2531760911a72eull, 0xdf4e95cb2a94a447ull, 0x4a2e1127edab2884ull, 0x1086769f4525686dull}},
    {"tumbler",           {0x5c5da9008bb6cc1eull, 0xffe239bfe21f2f8aull, 0xbd92bac9acceb4e3ull, 0xe51142ee05f1518full}},
    {"pendulum_drag",     {0x126f6c0db4766c0bull, 0x1a01a89fa0b073ecull, 0xec1edb6576afd77bull, 0xc56583d92e80e520ull}},
    {"chain_drag",        {0x3186b8faeff0749aull, 0xccb78794a7c3d797ull, 0xabbe4b21fd28576eull, 0x052259d3bc1a9ac9ull}},
    {"ragdoll",           {0x1361eb263e980e5dull, 0x1db58f6a0ca2b8ceull, 0xf6decdf4c325ac79ull, 0xa24f1d49333d571full}},
    {"ragdoll_motorized", {0x17304d446d3a4a07ull, 0x75847cd49752a13eull, 0xde45d0867c1231cbull, 0x45bcdfd966bfc0b2ull}},
};
// clang-format on

}  // namespace

TEST(Determinism, RecordedHashes) {
    const bool print = std::getenv("PIVOT_PRINT_HASHES") != nullptr;
    EXPECT_EQ(std::size(kRecorded), allScenes().size()) << "a scene without recorded hashes";
    for (std::size_t n = 0; n < allScenes().size(); ++n) {
        const SceneInfo& info = allScenes()[n];
        std::uint64_t hashes[kPositionSolverCount];
        for (int s = 0; s < kPositionSolverCount; ++s) {
            hashes[s] = hashOfRun(info, static_cast<PositionSolver>(s), 600);
        }
        if (print) {
            std::printf(
                "    {\"%s\",%*s{0x%016llxull, 0x%016llxull, 0x%016llxull, 0x%016llxull}},\n",
                info.name, static_cast<int>(18 - std::strlen(info.name)), "",
                static_cast<unsigned long long>(hashes[0]),
                static_cast<unsigned long long>(hashes[1]),
                static_cast<unsigned long long>(hashes[2]),
                static_cast<unsigned long long>(hashes[3]));
        }
        if (n >= std::size(kRecorded)) continue;
        EXPECT_STREQ(kRecorded[n].scene, info.name);
        for (int s = 0; s < kPositionSolverCount; ++s) {
            EXPECT_EQ(hashes[s], kRecorded[n].hash[s])
                << info.name << " " << positionSolverName(static_cast<PositionSolver>(s))
                << ": the numerics changed (see the comment above kRecorded)";
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
