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

// World::stateHash of every scene with every position solver after 600 steps, under the
// default broad-phase boxes (Compact; Predictive's numerics are pinned by the Box2D 2.4.1
// bit-for-bit reference tests), so that any change to the numerics (or to what the hash
// covers) is seen here and made on purpose. After an intended change, regenerate the table with
//   PIVOT_PRINT_HASHES=1 ./build/tests/engine/pivot-engine-tests
//   --gtest_filter=Determinism.RecordedHashes
// which prints it in this form, and paste it over this one. Recorded with GCC 12 on x86-64
// (Release and the Debug sanitizer build agree); other compilers and CPUs may differ
// (docs/reliability.md).
// clang-format off
const RecordedHashes kRecorded[] = {
    // scene               baumgarte             pseudo_velocity       modified_ngs          full_ngs
    {"pendulum",          {0xa71c3d73618574a0ull, 0xc8c59a98e7403572ull, 0x4dba72eed24aea9dull, 0x51d23b10d22cae82ull, 0x6ffe6d2b9433c6adull, 0x707662640287e47full}},
    {"pendulum_limit",    {0x1ea96ffe35f8a1cdull, 0xc09f97de20210578ull, 0xafe1b700e7e3e81eull, 0xee410034e6682ad4ull, 0xb48d9f8e9ba057dcull, 0x357016bf291646adull}},
    {"double_pendulum",   {0xb608fe513cc0ba65ull, 0x7b05384262bbda2eull, 0xcb76b62b3c1331aaull, 0xe9373e586a7fb872ull, 0x9becd71bc06d595dull, 0x623f8a65b65e6bc1ull}},
    {"motor_wheel",       {0x154e877e536ac667ull, 0x303ecead06ff51f8ull, 0x1a12dc0fa537bdb3ull, 0x2469067858353ecfull, 0x420afa6b9e00ecafull, 0x66068451abe76f9dull}},
    {"bridge",            {0x0e2a2fc769292212ull, 0xf9d718da6c235c35ull, 0x45e98f7ca9fa4ebdull, 0xf36db183b20b42e1ull, 0x1738dfebdd418933ull, 0x0e8e53099449df11ull}},
    {"chain",             {0x20bb306026f265eaull, 0x60c8dcf692f653feull, 0xe14181ca0a87c397ull, 0x83d5470692e1d75cull, 0x6de50159351cc81full, 0xff0eea1fc3eddb87ull}},
    {"bridge_heavy",      {0x2f9016c97dee60f5ull, 0xb6c121457f19f7ceull, 0x6bea93915f09331cull, 0xe4aec9fdfd3b6cddull, 0x39d4c4472b7de134ull, 0x95fc6491ad516713ull}},
    {"pyramid",           {0x0f2dbc98a774e567ull, 0xafd528a56302d9e6ull, 0xcb18b3a967760285ull, 0x366f9bd10e7325b4ull, 0x3e1a3d6f2ab6022bull, 0x8a4270ba456fa5aaull}},
    {"tumbler",           {0x2493f426ccd620c0ull, 0x0bb4b27e29948a43ull, 0x80d9858d86c134f3ull, 0x8163523af41602abull, 0x98c73584864ceb1eull, 0x92ca206b84043806ull}},
    {"pendulum_drag",     {0x6fb397c6c470d6baull, 0xeeb48c876846d4f3ull, 0x89efbc76d5a45d01ull, 0xe5f608417a181c35ull, 0xfa9cafce7b5551eeull, 0xdf2f6b7bc42611a8ull}},
    {"chain_drag",        {0x695d91066f6edeb0ull, 0x971ee675fa75ecbfull, 0xdf87cb8b126ab809ull, 0x97a898f26b5900f8ull, 0xa78844fcb007d362ull, 0xb0b6c17a5476762bull}},
    {"ragdoll",           {0x53814b175ce33f7bull, 0xbd405847fdee682cull, 0xde586528c5a49939ull, 0x07224e1da2302777ull, 0x66c83fbaacc3e749ull, 0x31a1f0983d14cfbcull}},
    {"ragdoll_motorized", {0x3c135967f2894356ull, 0x5ec6a986758ad86dull, 0xb0ff5ec0f20cc1c1ull, 0x91ae0053c2845bdeull, 0xd8c052118114a239ull, 0x8e2b670b8763961cull}},
    {"distance_pendulum", {0xaca0423bd6f1ab3dull, 0x36d06769463cbb8eull, 0x348947ba7a1e6cc9ull, 0x5b683f3bdfff20ddull, 0xb711138227dd35e0ull, 0xf2e2de1fe6a5bb4aull}},
    {"rope",              {0xb1eceb06df2a8df4ull, 0x7954a0e986a8047bull, 0x7205a63e754679e4ull, 0xf78d81d62526720dull, 0xf79f60c00a905c78ull, 0xdbf62bae40cf43f6ull}},
    {"pulley",            {0xde7306611c2f0ac4ull, 0x128da0c32c59182cull, 0xaa64b1190db40e9eull, 0x397adbdc7ef28785ull, 0xb65ef162787d04f0ull, 0x7ef2d0ff1afdee21ull}},
    {"top_down",          {0x712786fb2727463eull, 0x6fa11e1553642c0bull, 0x74ce0dddedd3c164ull, 0xbf71aca18ce20441ull, 0xe6dfe5f086ea0ba2ull, 0xea4eb1930532868full}},
    {"motor_drive",       {0x5c5e3f3ca8a0f654ull, 0x6af7044305e07a6cull, 0xe721be738f56f5f9ull, 0x9ba4b58aa49e7ab9ull, 0xe3aad8daf020aab4ull, 0x4e403ba9bde0268cull}},
    {"weld_beam",         {0x304af063c033115full, 0xb32c300819b558b9ull, 0xa61784a2612e5c67ull, 0x893e0ab3d42b73cdull, 0x643b2070f71b73b2ull, 0x201cddcd46675b0eull}},
    {"car",               {0x1f8f48acf70fc1a8ull, 0x1ecbe0cd088bc7f8ull, 0x5c2c0abf9a20c77dull, 0xfc256e0a1b455bfaull, 0x5928e58ac805fd8aull, 0x7bd9c2a10004b967ull}},
    {"elevator",          {0xef57ede3cc03ab4dull, 0x9dc38aad9ae4179dull, 0xa4a17101252601ecull, 0x8ab677f31e2264b4ull, 0xaeba1597808afd1dull, 0xd23d25f599d3926aull}},
    {"pulley_gear",       {0x00e41cbceb720275ull, 0xe915e65c4cb721baull, 0xf750c9bf83dd6067ull, 0xfba02fa4f7dc8ee7ull, 0x6151254e2761ea33ull, 0x97caa27ac84eecf4ull}},
    {"stretched_chain",   {0x22ca703f18ac4fc1ull, 0x45faa16b76479798ull, 0x35f82bb6a5c37f52ull, 0x8b71e4dcc2a224f3ull, 0xca21ba38663b0655ull, 0x834561a8ac34284cull}},
    {"ball_chain",        {0xd75c0003b3a8de4eull, 0x75f3c1c668ae779bull, 0x3043fd88a306ff0eull, 0xc5b1bbd1f91e2570ull, 0x98c67c84b6886681ull, 0xe8bf8afb51f1e99cull}},
    {"mass_ratio",        {0x0c85cc098e8f316aull, 0x62ed532afe76fb18ull, 0x4ad535757aae5e37ull, 0xad2259ff77a5aca6ull, 0x4d5d793061635538ull, 0x4ad1f5ac3da26688ull}},
    {"heavy_stack",       {0xa714a48ff2658fe8ull, 0xe2b6f4102628f4b1ull, 0x9d330ff5f81699faull, 0x41d8df6dcb541b63ull, 0x77d37f0894995f9cull, 0x14eaa679a280eca5ull}},
    {"overlap_recovery",  {0x5b1007d988821b58ull, 0x987dde3f15cc1c89ull, 0x5de22f9b943bb676ull, 0x1b0832114a018ecfull, 0x6b314d5802ceba1cull, 0xb5c1fed88575346dull}},
    {"far_chain",         {0x2b8f66bcf8a1aa03ull, 0x19c630d1f8ef3edcull, 0xc1b00a97f2772f0aull, 0x8f6fff52f3b362ccull, 0x5e7acc5398d96178ull, 0x2e4a47f6bddfdfccull}},
    {"ramps",             {0xb8fad9d74bcfe764ull, 0x003d0e8ac758ffedull, 0x2556865dcfae3605ull, 0xc0bbc320e3a2bda1ull, 0xbff3177bf57b3d48ull, 0xbcfabdfbc03f2952ull}},
    {"bullets",           {0x77f02831254008c3ull, 0x33ddd9c42d96201eull, 0x6349d1e1c3156a19ull, 0x33184de016a777fcull, 0x00d91835b19d1707ull, 0x60fcc6da21d0dd92ull}},
    {"platformer",        {0x29d18cf851431bd6ull, 0x7303f86551ee18f3ull, 0xc439014047a26c04ull, 0xb2e9921717ded306ull, 0xd37681f40597de9aull, 0xcf25253376df934dull}},
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
            std::printf("    {\"%s\",%*s{", info.name,
                        static_cast<int>(18 - std::strlen(info.name)), "");
            for (int s = 0; s < kPositionSolverCount; ++s) {
                std::printf("%s0x%016llxull", s == 0 ? "" : ", ",
                            static_cast<unsigned long long>(hashes[s]));
            }
            std::printf("}},\n");
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
    // result is merged in a fixed order: the state is bit-identical for any worker count, with
    // either policy for the broad phase's boxes.
    for (const BroadPhaseBoxes boxes : {BroadPhaseBoxes::Predictive, BroadPhaseBoxes::Compact}) {
        for (const SceneInfo& info : allScenes()) {
            std::uint64_t hashes[2];
            for (int workers = 1; workers <= 2; ++workers) {
                SceneOptions options;
                options.workerCount = workers;
                options.broadPhaseBoxes = boxes;
                Scene scene = buildScene(info, options);
                RunSettings settings;
                settings.steps = 300;
                runScene(scene, settings);
                hashes[workers - 1] = scene.world->stateHash();
            }
            EXPECT_EQ(hashes[0], hashes[1]) << info.name << " boxes " << static_cast<int>(boxes);
        }
    }
}
