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
//   PIVOT_PRINT_HASHES=1 ./build/tests/engine/pivot-engine-tests
//   --gtest_filter=Determinism.RecordedHashes
// which prints it in this form, and paste it over this one. Recorded with GCC 12 on x86-64
// (Release and the Debug sanitizer build agree); other compilers and CPUs may differ
// (docs/reliability.md).
// clang-format off
const RecordedHashes kRecorded[] = {
    // scene               baumgarte             pseudo_velocity       modified_ngs          full_ngs
    {"pendulum",          {0x4fe7894fd259f68eull, 0x634899c533087a69ull, 0x922b18b9bca48db0ull, 0x9770556e3b673f68ull, 0xfaf6ff628d4da094ull, 0xa23e6ace33aceceeull}},
    {"pendulum_limit",    {0x87ab9983e11f1258ull, 0xb7ef59b1da275b5aull, 0xdfab0ff8107ebc2dull, 0x0112f9164ff50aeaull, 0xb2f12863af94c127ull, 0xf97bc1ed6c025615ull}},
    {"double_pendulum",   {0x01e3e3d4c5f2de65ull, 0x44bafa6603a46237ull, 0x0915464d2bcda714ull, 0x27e8914c592b4a02ull, 0xba1503a67a7aa7c0ull, 0x8112e3415d6a0717ull}},
    {"motor_wheel",       {0x1ecf25ec15d13a7cull, 0x3f90c701480c3a71ull, 0xec6e99cf76e3afcdull, 0x6e383f02127f7945ull, 0xf1cc3468e7430009ull, 0xa07c65f7ba535a95ull}},
    {"bridge",            {0xd9e28f2168b64469ull, 0x3308ef709d3b46c5ull, 0xbd35b6783499fe4full, 0x5c530ef41ce24fc2ull, 0xbaab53d3b81f974aull, 0xa09eb929d8e53ab4ull}},
    {"chain",             {0x086a447f9e37e18aull, 0x3f893a6942cf5700ull, 0xd76a550c26627768ull, 0x1159bdebaa0caf38ull, 0x1b9dbbe7a72c92d3ull, 0xaed025b92cf7d86full}},
    {"bridge_heavy",      {0x836c62042d48040bull, 0x7f206bca8f8219c2ull, 0x54b52ff919dff9f1ull, 0xbbbc598355e1324eull, 0xedebfba7a3ccad5cull, 0x95abac0a0ecfbe4eull}},
    {"pyramid",           {0x3853469e51132496ull, 0xb26f2d59651d27afull, 0x580896034c02b148ull, 0xc2325e044a598d39ull, 0x0d3e26e0b46fac02ull, 0xf38b50cdf5074a8bull}},
    {"tumbler",           {0x6a391cd16fa705bcull, 0xbe6b2d541795835full, 0x314ce84ae87b07cbull, 0x757dd80c6c672fa7ull, 0x670e2d0c4c0ce9e5ull, 0xfb07434461aeab2bull}},
    {"pendulum_drag",     {0xaebef8d8b067672cull, 0xbb70602a74d89bc2ull, 0x3c67c686e205a50dull, 0x8154d8d3fb836f5aull, 0x2c818b78f59bcfc0ull, 0xba25dc7af6b60631ull}},
    {"chain_drag",        {0x7d22f8e6a514d3cdull, 0x825859bbe194056aull, 0xf546d53714e0f0f3ull, 0x4cbac203874d74b1ull, 0x07b78d39917bfe7aull, 0x6a3d43d29c8abd99ull}},
    {"ragdoll",           {0x62ecec6e9c6bd57eull, 0x20a1813dd756651full, 0x36a84dff80ce9b82ull, 0xf18e0e9501684072ull, 0x33ba50d3e7a200fbull, 0x5e5fe44e4942a738ull}},
    {"ragdoll_motorized", {0x3bf7c701015a3605ull, 0xcafb451b7a15e69cull, 0xf76aa77de8bcd58full, 0x587499e5cec06b6cull, 0xe9e11a3dbbd401e0ull, 0x7fbc0674e2b0d619ull}},
    {"distance_pendulum", {0x79727b7257c23efcull, 0x89717a71c817e1fbull, 0xcfe2bbf1cf794ad6ull, 0xe617a11f9bdc422aull, 0x63e0aec6e8ead975ull, 0xb91105c8d6d3f337ull}},
    {"rope",              {0x28aae9ce8042badbull, 0x100031242d9c5297ull, 0xeb8f9d49f1c8c395ull, 0xf805247481148830ull, 0x46849f78b333056bull, 0x06f16869eec1a10eull}},
    {"pulley",            {0x5f5681cfd688edd5ull, 0xa46182dd5b4afa28ull, 0xf95fff3a58451996ull, 0x24d27a448e6897c9ull, 0xd39a5d34d4b6ef50ull, 0x9ea296ff07748f80ull}},
    {"top_down",          {0x73faeeea9ca4eb31ull, 0x9762abb0cbfb71c0ull, 0x0a2b06603d1544f7ull, 0x271ace15da0309f6ull, 0xff5ad59545ca7da5ull, 0x62a0116a371e67d4ull}},
    {"motor_drive",       {0x53f3f2cc6276216aull, 0xa95b8e97a552fd6aull, 0x9d2cc2a1618d1443ull, 0xfc25b3766d56e9d3ull, 0xe235386aab331cdaull, 0xa8836460123cd2baull}},
    {"weld_beam",         {0x2009434b1e2f41c3ull, 0x6c93e14a1f731f99ull, 0xf231e724a9e18ab3ull, 0x5c4d1f06800facf1ull, 0xbb9304ade7953404ull, 0x672aa44ccf182a66ull}},
    {"car",               {0x768d69f9f4ef324aull, 0xc40654434524efd2ull, 0xd8215dacd0697ee4ull, 0x36c563669718aa58ull, 0xe8ab01544dbb99a0ull, 0x770cac8f6acf7950ull}},
    {"elevator",          {0xeede27a3b775e881ull, 0x08f3c5d78c338e60ull, 0x4eebf55691421b2full, 0x25dbd98078ffdadbull, 0x5f5a6886490de5d4ull, 0xd0294a750be7b44cull}},
    {"pulley_gear",       {0xf9d9eff86cb4f48bull, 0x039970dde4b527cdull, 0x29acab3865b55968ull, 0xf757740da4eae51aull, 0x7c20850f4112d6f3ull, 0x5d6cac0f77083eb7ull}},
    {"stretched_chain",   {0x94e6f4294c62b156ull, 0x131fcc669981ac2bull, 0xf3e6964ede57ad66ull, 0xe064d1485c865a1cull, 0xb71ca3ddef9605c4ull, 0x0e5e64e5f64a91d9ull}},
    {"ball_chain",        {0x46dd193824130e41ull, 0x1074d0b0d2d8e97dull, 0xdfc44acd5f697b81ull, 0xead4223f680bade5ull, 0xee69464f307de597ull, 0x3344b420ee91eabaull}},
    {"mass_ratio",        {0xe38e39b901de7f13ull, 0xf2d6edefe412f955ull, 0x7c544452ac6fed42ull, 0x0cfa6896f150182bull, 0x9bace78fa3b6a56dull, 0x8c701ff652cc7689ull}},
    {"heavy_stack",       {0xe1e39b52cb6e9abfull, 0x8e942e7e5adfdbeeull, 0x2917bf6b8cefbeadull, 0x054147ab7c5e81fcull, 0x59e5d479d30aad33ull, 0xe1d1bf6ae81730b2ull}},
    {"overlap_recovery",  {0x413cd254a8b353fbull, 0xbdebe35648852092ull, 0x0ef3a4e1510852d5ull, 0xa2733892ca634b6cull, 0x0ec3f48ba0c38047ull, 0xdba1e56cdd64f4feull}},
    {"far_chain",         {0xa0879e71a5500d68ull, 0xbc48b2fc3db4596full, 0x8a427675fff14b8aull, 0xf0c68d276757f908ull, 0x21009b1aebb5cd8bull, 0x1ad3d1605e7eb0c0ull}},
    {"ramps",             {0x77696e4ee1700d4eull, 0xdf77d5d2e2dc6664ull, 0x2a83fb4909f74ec5ull, 0x99a274168e8bc548ull, 0xc19056b45dbb5aeaull, 0xef35fb1ed2cbd672ull}},
    {"bullets",           {0x72c5caccb501a653ull, 0x415b64a7aef0a692ull, 0xb380fedc6d5a1eadull, 0xb5735e8367e1d6dcull, 0xfd7a1c8dfea68677ull, 0x1fe6741f0df124a6ull}},
    {"platformer",        {0x35a9572da6df5cb3ull, 0x84845b5378399e11ull, 0xa5c77d6117fa1f8full, 0xb01554219222b5ccull, 0xe002232ddfbffc99ull, 0x8f0657795fbf43e3ull}},
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
