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
    {"pendulum",          {0x57fd490d01ac1575ull, 0xd937d128c0d4b304ull, 0x01b4650bb1925c7cull, 0xc8865e3e8328601full}},
    {"pendulum_limit",    {0xe56024245e6d4dceull, 0xf1ab654dc3178075ull, 0x64c97eecf2bdb15dull, 0x789e97942b76ad09ull}},
    {"double_pendulum",   {0xa1c47aa0a29d985cull, 0xc5543026f8b4ea2dull, 0xf2a03fbf2110a985ull, 0xcd3a59362e6ad17aull}},
    {"motor_wheel",       {0x0c12c68706e1a1a0ull, 0x044886035a9a7917ull, 0xc4e21969940115edull, 0xaa87746e6c873d09ull}},
    {"bridge",            {0x7bf4c017088e9377ull, 0x8bc4cfbfae6a08baull, 0xd3fa9d84c2757dbbull, 0x64832e65faad5f1aull}},
    {"chain",             {0xcfad34c6d55bc32cull, 0x5a5eab2e93461ee4ull, 0xf25af09cd30b63ebull, 0x58ad46daee7980cfull}},
    {"bridge_heavy",      {0x058f1465e55a7614ull, 0x09449e46cfe8552full, 0x02a737f8e2dcf5d7ull, 0xf71bd80a87a0f4d2ull}},
    {"pyramid",           {0xbdfb5177959c641eull, 0x0a780d02edb50ff7ull, 0x456fd8bdaf7bff34ull, 0x599978abf181465dull}},
    {"tumbler",           {0x9f40fe88e0e12e8eull, 0xcc296421e30877aaull, 0xfdd66a9449d5c103ull, 0x59154062cd50931full}},
    {"pendulum_drag",     {0x5071406d522bb773ull, 0x63e4c52924e7e9e7ull, 0x692776be68f97648ull, 0x773df0080e6b3860ull}},
    {"chain_drag",        {0xd0c77d3fd87130f8ull, 0x89506a4fbab3689bull, 0xbd33aff2b7123d30ull, 0xac65cc958dde117aull}},
    {"ragdoll",           {0xb62008db4ecb98bdull, 0x8063d5ad329e026eull, 0xa46b6e7223014479ull, 0x5579dbc24cb1a22full}},
    {"ragdoll_motorized", {0xb77521b4d0ed21a7ull, 0x977a020e7844547eull, 0x832667cbc590ebabull, 0x1948867333fbf552ull}},
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
