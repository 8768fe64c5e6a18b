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
    {"pendulum",          {0x2040f6baa00668b9ull, 0x2193d1a807e6be38ull, 0x1caf586220254fddull, 0x94bf3aaa700495edull}},
    {"pendulum_limit",    {0x05fa28fb27c55d41ull, 0x288978f595bfac07ull, 0x88303b2765f2277cull, 0xfce30887301919c7ull}},
    {"double_pendulum",   {0xc7a945c71ff24d7dull, 0x4995f37375cb1693ull, 0x93d394e853fdf214ull, 0xcd615945343b693aull}},
    {"motor_wheel",       {0x1d67c7fc20bb70f1ull, 0xeb823a26a97c8650ull, 0x0cdcc90c371e7990ull, 0x73ff8049b78bbbb0ull}},
    {"bridge",            {0x97bf2ae7b08c1cadull, 0x89a8a4e68903bcedull, 0xdd68bfecb36c8a93ull, 0x8aaa7165904503aaull}},
    {"chain",             {0x17ea2bf47e0f1d4full, 0xb655bb79f0987b10ull, 0x00eda8d2219273d1ull, 0x620ba2010ae55e25ull}},
    {"bridge_heavy",      {0x0d2b14031f561f87ull, 0x71285261fb570dfaull, 0x44c382897d551a72ull, 0xbeb77af53029ca2eull}},
    {"pyramid",           {0xde2c2c6d53d9307eull, 0x24cae4749c9ab7abull, 0x5211471ef2a7f4a4ull, 0xf5235d6889ad3a11ull}},
    {"tumbler",           {0x45597282958c24f5ull, 0xf295b9dcc45f08e1ull, 0x79c32be6bf83881dull, 0x10c1881fbd7d5c4dull}},
    {"pendulum_drag",     {0x49dd7553d9b41225ull, 0x23a0b020406c96dbull, 0xc771a03b7d5b483dull, 0xa5de5faaa2110a7full}},
    {"chain_drag",        {0x1ecf144b4f38a7b7ull, 0x0bd4dc60f01fe1bfull, 0xe688e74634292e76ull, 0x013e16b1ad23b329ull}},
    {"ragdoll",           {0x5c006f5356012424ull, 0xb6da37c761729c14ull, 0xc03da196824b2093ull, 0xec90875ba860ad6full}},
    {"ragdoll_motorized", {0x6d879974e7f2ff8eull, 0xae292680241c8f83ull, 0x5b0e0444e0e3c5f4ull, 0x92f0ec6d588fc2c6ull}},
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
