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
    {"pendulum",          {0x0f3857802aa4fda5ull, 0x9832b5d2d5c5abe4ull, 0x5635033fc8b427fcull, 0xdf034746d2a19aefull, 0x4fe787aa6ae37891ull, 0x7faa692c936f02bbull}},
    {"pendulum_limit",    {0x70d529281a493e1eull, 0x4f18111c7610edd5ull, 0xaf3ee861cf2333ddull, 0x59a445e91faa6459ull, 0x6fb08f15fdb5fdb5ull, 0x016776bdef590392ull}},
    {"double_pendulum",   {0x8a1c3a3a272ebfccull, 0x65471b2d9b08802dull, 0x8eb85280a53d79e5ull, 0xe832794b80ba870aull, 0xe3f53eef265d7598ull, 0x7204d4647eb092b6ull}},
    {"motor_wheel",       {0x290c77d756b91af0ull, 0xb657b6ec3e188fb7ull, 0xe9c9ae84aea95f4dull, 0x85fb5a9d7247d119ull, 0x3798f68e659ea424ull, 0x99e5adf30138a858ull}},
    {"bridge",            {0xa530fa7a8ae07437ull, 0xcce3a4917a53726aull, 0x81222961a3f4a2abull, 0xf5816a7e0379921aull, 0x9c522c1122f63f9bull, 0xf843341a998e099full}},
    {"chain",             {0xab203d16d3eab52cull, 0x106a6cb46c834f54ull, 0xc85d4016acdae61bull, 0xb3b2ea90256c5f4full, 0x60d21cf88c88fdb3ull, 0xbb79738fb85a8850ull}},
    {"bridge_heavy",      {0x41a99e948035f694ull, 0x8a79e2d6dc0c0cafull, 0x0faa4beec26882e7ull, 0x37443348139107c2ull, 0x5f5a0dd3f3cdb52bull, 0xa7367c827d44bca7ull}},
    {"pyramid",           {0x33374f5211e3838eull, 0x7a4f83ed7c2acef7ull, 0x2fc968ff77f7ae04ull, 0xcea594887e52707dull, 0x00e6c689d4438b3aull, 0xbd740aeacbdc2a63ull}},
    {"tumbler",           {0xa468ffb0d1d6388eull, 0x504a98908f7d9ecaull, 0xd26f2783555faf73ull, 0x61b1fb69e5cc961full, 0x48e11e24bd801e51ull, 0xfbc7c2cdf2b346e6ull}},
    {"pendulum_drag",     {0x06a23888fe39691bull, 0x9afe6c2e2167d5ccull, 0xe6c61ec2f5185bfbull, 0xfb387053841b4bd0ull, 0x36b62083f50deb38ull, 0x2cba08f26325c3ecull}},
    {"chain_drag",        {0xb872497f840b821aull, 0xf1341218c48eb238ull, 0x3d4525bd1579c706ull, 0x152bfe078567bc9full, 0xc65fd1b9eb7e6cbfull, 0xda3f20c05d5e8c28ull}},
    {"ragdoll",           {0x986a78436167194dull, 0xc396f341c5a179eeull, 0x45897ec3e5b175b9ull, 0x07cc21557f9f5b4full, 0x0dbc7b87cef64af7ull, 0xc5f0ea1a8ab23831ull}},
    {"ragdoll_motorized", {0xded5e98975600d27ull, 0x7e87e83c497924aeull, 0x217b56c1cf46214bull, 0xe47cfe25e0627942ull, 0xc192ef15a6c63819ull, 0x6ea81af50b902719ull}},
    {"distance_pendulum", {0xd1964694720a8e70ull, 0xeb7346be27492100ull, 0x1e35eace498130d8ull, 0x1e415cc507746a14ull, 0x7a8b82b620242a1bull, 0x61523b497ad65498ull}},
    {"rope",              {0xa68318da37632d94ull, 0x49db622000f4f379ull, 0x96b6c83077dca2d5ull, 0x107b784abe487d50ull, 0xd1d598d94c730b4bull, 0x0adb24f7988531bdull}},
    {"pulley",            {0xeeefd922f060bb30ull, 0x8c5fcf8031eabf19ull, 0xd34fb0c41a150427ull, 0x512c6b2eba8854aaull, 0x31bf5b9c56352545ull, 0x36eaccc23bf8b2c0ull}},
    {"top_down",          {0xf3640b234b73893dull, 0x31c01f8215235f1cull, 0xaeeb44376fa4240bull, 0xca93bf612f861b82ull, 0xbd9279b84cdf5659ull, 0x0f95dc550a29e3a8ull}},
    {"motor_drive",       {0x219e8351c028691cull, 0xec5d93e75f90de80ull, 0xde8c32bfb5d572b5ull, 0x0eb63675aacac719ull, 0xee10856645c6cf74ull, 0xbb879c4e39b8cd30ull}},
    {"weld_beam",         {0xf4aa1610f9cbad91ull, 0x3da6cc378e39ef85ull, 0xaeb6b8ebe4773043ull, 0xc309103e6d4f92d6ull, 0xb49db31650770e16ull, 0x4f2833f3f51de7e4ull}},
    {"car",               {0xd5856f3e7a68ea3full, 0x3955fef5f7444707ull, 0xcbfd3d3b2112093bull, 0x2347258b5c67c0f7ull, 0x7c26c3438f371ac4ull, 0x5c3e3302c9dd6d15ull}},
    {"elevator",          {0x2bc5877b156b2692ull, 0x680591cab71fca3full, 0xf15ac09c6ca38d47ull, 0xc9eca8551f156da3ull, 0xc6dcf64f7ba810abull, 0xd589206d793c84ceull}},
    {"pulley_gear",       {0xe52bf8b11dac06d3ull, 0x97101f5f7ded6424ull, 0x81cd9fe5f05c540cull, 0x632e4225479dfa3aull, 0xc43f0cc3d72e4be1ull, 0x644fd16936b05605ull}},
    {"stretched_chain",   {0xf1d6f2d41db2723cull, 0x5d4194dbfcabf712ull, 0xee504abefc9d994full, 0xef66ba65ab6445e0ull, 0x7e6423ab96d7b648ull, 0x9eb7c8bd5813d27aull}},
    {"ball_chain",        {0x3b745929917ebf4aull, 0x3cd7ae76fb09efbaull, 0x75d6ea2b7e84cc68ull, 0xa33aa4f143b8fe7cull, 0xa8b13788c2d7aa10ull, 0xa7698be786980df2ull}},
    {"mass_ratio",        {0x27b0b8bbdfece63aull, 0x1efd442b3530d9dfull, 0x94449ea87cafd829ull, 0x77b4877c61a58670ull, 0x936c59e0c2642ae7ull, 0xc8bea528583a6496ull}},
    {"heavy_stack",       {0x08c475b272262242ull, 0xcf8992d1c7ce371full, 0x6034900afcc6d710ull, 0x692b26b863ecc1adull, 0xaeafd31e373eab0eull, 0x14f09ea1d3196a6bull}},
    {"overlap_recovery",  {0xb1f33b4b74b3d82bull, 0xf3e51cf809fa54beull, 0x7014479612dcbd91ull, 0x61c2fc806591620cull, 0xb331f301df8d8f97ull, 0xc9fb20ce20d3015aull}},
    {"far_chain",         {0x81fb2025224fdea3ull, 0x71cbe8c9908acb6eull, 0xb35adbaea103c602ull, 0x2729620802baade1ull, 0xd1dc607b2ac3ed93ull, 0xac454c9b17b2d73bull}},
    {"ramps",             {0xf096bdc60e24e01dull, 0xc487832dd7280297ull, 0x94348676d3349586ull, 0x9207c967b85896aeull, 0x95a36b4e690e6f24ull, 0x1b23d648e760c1ecull}},
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
