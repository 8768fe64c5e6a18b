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
std::uint64_t hashOfRun(const SceneInfo& info, const SceneOptions& options, int steps) {
    Scene scene = buildScene(info, options);
    for (int i = 0; i < steps; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, i);
        scene.world->step(1.0f / options.hz);
    }
    return scene.world->stateHash();
}

std::uint64_t hashOfRun(const SceneInfo& info, PositionSolver solver, int steps) {
    SceneOptions options;
    options.solver = solver;
    return hashOfRun(info, options, steps);
}

// Box2D v3's way of stepping, as pivot-bench's soft_step engine sets it up: soft-step joints,
// soft contacts, 4 substeps, continuous collision for fast bodies only.
SceneOptions substeppedOptions() {
    SceneOptions options;
    options.solver = PositionSolver::SoftStep;
    options.contactCorrection = ContactCorrection::Soft;
    options.substepCount = 4;
    options.continuousCollision = ContinuousCollision::FastBodies;
    return options;
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
// which prints it in this form, and paste it over this one. The hash is of the state a snapshot
// holds (docs/snapshots.md), so a change to the snapshot's fields changes it too. Recorded with
// GCC 12 on x86-64 (SSE2, Release); CI's clang 14 build with AVX2 checks the same table; other
// compilers and CPUs may differ (docs/reliability.md).
// clang-format off
const RecordedHashes kRecorded[] = {
    // scene               baumgarte             pseudo_velocity       modified_ngs          full_ngs
    {"pendulum",          {0x8104252269bb09f4ull, 0x26da966005443f5cull, 0x70da3a3a682c027eull, 0x5d58754c5e07a237ull, 0xbc5e50386f6bda41ull, 0xb482bfd6831f6ad2ull}},
    {"pendulum_20",       {0x220b9d3cbc1136cdull, 0xc889884dac93f7bcull, 0x28e40e441fe5bbf4ull, 0xef96da730f2d4c3aull, 0x8dcd6464f410ee9aull, 0x82b51fefe18243f2ull}},
    {"pendulum_limit",    {0x609a430eec8471ffull, 0x91c983d7c480b10eull, 0x385b6a75897d9a3eull, 0x52cff2dd4fb6c370ull, 0xcc751ed559b70abfull, 0x186549d5e70a7fefull}},
    {"double_pendulum",   {0x8193940c4c9894c4ull, 0x9855951b0fa9b719ull, 0x88d838e2a4325119ull, 0xaffac133316bbe69ull, 0xcd4ee4640fd74aa3ull, 0x873a45dd63856d72ull}},
    {"motor_wheel",       {0xfd26b63e1fb61b43ull, 0xc177cdc3bd4f29a9ull, 0xea27fdcaebbe6e2aull, 0x02dfb83ab42648d2ull, 0x405e68a613b0246bull, 0x4b699c6a6c18c833ull}},
    {"bridge",            {0x32963741565211d5ull, 0xc39531d2342c2641ull, 0x82667df0fd829e04ull, 0xfab99b10d9d05f25ull, 0x6cc09097e5edd67dull, 0x212c5e672e5f1c96ull}},
    {"chain",             {0x7c230cd8f96ec8b7ull, 0x4d13262a3cfc1aeaull, 0x7dcec4a066ef07fcull, 0x39672d06c84db2b2ull, 0x7410214e7bc4f8dcull, 0x8f923ad57a5f7063ull}},
    {"long_bridge",       {0x37051d1c437edc88ull, 0x936b5fbbc2ff92ebull, 0x3f286e1479a3c0ceull, 0x10ffe35f0607479full, 0x7daf06f533b4e759ull, 0x6866558c5f55aef2ull}},
    {"bridge_heavy",      {0x3883be2cd7b1a50cull, 0x10240eebd622af46ull, 0x272aac4c01c1dfa7ull, 0x1a61610631cdf95cull, 0x6b5b205089c77940ull, 0x5d0a5061bf5e749cull}},
    {"bridge_crate",      {0xf973c59de6847aaaull, 0x832873f0a9cc2f9aull, 0xc99b7e0f10ad412full, 0x4674d213e28525e8ull, 0x32f581f515fd5269ull, 0x313bef449618ccd8ull}},
    {"pyramid",           {0x537bd0821ffa8438ull, 0x90497426e9443dd7ull, 0x3db68399c5354ca0ull, 0xa58bcc5beb07466dull, 0xe732d8f5178ec535ull, 0x9765166cc6a52dffull}},
    {"tumbler",           {0xcc63685cea596f92ull, 0x368bf6c5b8e2be37ull, 0x6fac306a903a4109ull, 0x8db4d9126507da1dull, 0x9d07c71fba012ef6ull, 0x539efea15c3986d9ull}},
    {"pendulum_drag",     {0x8149b674f4aaa8ebull, 0x7f60f7ec790746e7ull, 0x7bba0c0634d2d615ull, 0x3101c18464cd8ad2ull, 0xa7c6081734316948ull, 0x12d6b9037165f27aull}},
    {"chain_drag",        {0xbd3bd7377934e728ull, 0x59091b6b9c1c7b18ull, 0xa2d2ca5c0311be9full, 0x1df51b693913d12eull, 0xf4991dcdb551c166ull, 0x306edb1e383443b5ull}},
    {"ragdoll",           {0xe49815a680d765c1ull, 0xd1b4448a1c2b0e15ull, 0x8ac721a8fa5c41ccull, 0x65b9062239bd176aull, 0xd6b8753166820118ull, 0xc3684df5db6a56ecull}},
    {"ragdoll_motorized", {0x424ee0b1d27aef7eull, 0xd2448285168edaa5ull, 0x44db235e85ece438ull, 0xb85ac35a1c5a9ba0ull, 0xf97dd59a73cd7f31ull, 0xf939cd46467a38abull}},
    {"ragdoll_pile",      {0xc2147fc62b519648ull, 0x3817908645ff21ccull, 0x906d7240daa17bd0ull, 0xf3b7a5a95b086043ull, 0x654fb5001fea2294ull, 0x07ff0e0dca851e7eull}},
    {"distance_pendulum", {0x8cd6fa53ae7714fbull, 0x76f41bdd7cc6f4cbull, 0x659b72581d0f4e87ull, 0x7d853ce4cad3d451ull, 0x103e5becfdb15dadull, 0xbd6c3510afb6b5acull}},
    {"distance_pendulum_offset",      {0xe24f8b023809ec56ull, 0xfb2e8705433942a7ull, 0xc60a252422e2e8beull, 0xc0ba48a930041c48ull, 0x2f29514a8e5a9dceull, 0x3c41f769713da0ccull}},
    {"rope",              {0x57afcd008c1eb8cfull, 0x40fe72c510de97afull, 0x770050a4894b15f6ull, 0xe82a97e01f37eba4ull, 0xb90d4c4bf4caded1ull, 0xad77352fef8fad77ull}},
    {"plank_rope",        {0x7473c810f5b87cc4ull, 0x8dcdf336bc5df88dull, 0xbf84e31102356ef4ull, 0xbf08a386de779c0dull, 0x4a5f8863ad38f852ull, 0x284b8e5167e954c2ull}},
    {"pulley",            {0xe70c69742703d44eull, 0xe92e165298bac5d5ull, 0xaa56769cb8ecffabull, 0x2192a88e6a06c3e1ull, 0xaf5c9504544cefe5ull, 0xdeff1d300ea3393cull}},
    {"top_down",          {0x779a5b49fbf9c843ull, 0xbaeaefd482a8e6b2ull, 0x33b4f24351146651ull, 0x109b0dffe58dff66ull, 0xbf56b64488995555ull, 0xef9da0034d72a3a4ull}},
    {"motor_drive",       {0x9c183599e1125683ull, 0x0ec525cd3e3c7b47ull, 0x6577a3f1cc852869ull, 0xfbf00b50ba3ca119ull, 0x8ecf4df4ad77db81ull, 0x8e027493f9c107a7ull}},
    {"weld_beam",         {0xbd3139492e887d31ull, 0x78e44abd7907fcfeull, 0x72fc18243a0229a5ull, 0x95817ef8d782e3e1ull, 0xca78c6299d0fa773ull, 0x018376f8555d0418ull}},
    {"car",               {0x736867dde1d657d1ull, 0x01b1e1c5422778b5ull, 0xfef62616854d7f2aull, 0x20180a782da27ab4ull, 0xda6275756764e129ull, 0xf1924cdc329b9011ull}},
    {"elevator",          {0xf293331debaf1173ull, 0x5f4486805507a94aull, 0xda53cbc52639eec8ull, 0x9dad4fb6c205fa3aull, 0x2b5daea06fa4089eull, 0x1152eb3a6eabb1f1ull}},
    {"pulley_gear",       {0x76ddd0e8f04ab8dcull, 0x16eeaa9c9f37ac18ull, 0xaac23db61713281eull, 0x2b0b675510d84080ull, 0xce557f0789e4c5a8ull, 0xa5ee629f94897b19ull}},
    {"stretched_chain",   {0x5e5fdec229a608b0ull, 0x1fe85e65b64f0d79ull, 0x0e6ec70df847a619ull, 0xaac54a38c2d3bae6ull, 0xa877a1b0c2beff5bull, 0x6ac8b62a089ed363ull}},
    {"stretched_chain_hanging",     {0x7a6f70e4fde16e67ull, 0x6da59538d46f0ce7ull, 0xdeed572a3c35d2f5ull, 0x368cfd67b5e3e4a0ull, 0xf15d57160cc5e43aull, 0x99f5543204d3bc9bull}},
    {"ball_chain",        {0x7d486fcbe89d8df7ull, 0x30543f6404a15293ull, 0x759801a5b0334455ull, 0xa4fb98fbe08b5a69ull, 0x6fe49e3b46de38abull, 0xcfc20dd59c1c2c9full}},
    {"rope_load",         {0x0e20e778f3f3bf99ull, 0x63f6c7792169b29dull, 0x5176a8d19c1543faull, 0xa248bff0117b87daull, 0x9ae50b6242e6b71bull, 0x08af8fdb1d2fff75ull}},
    {"mass_ratio",        {0xee3b465c913c4da2ull, 0xd523353d544c4b1cull, 0x6fe2b38e15d54fb2ull, 0x7f2bd33108c9e891ull, 0xd5e0f99a97c17855ull, 0x0db0024bdbfaeb13ull}},
    {"heavy_stack",       {0x7aa0cdb0ddda8b91ull, 0xcb40b919cec46dc1ull, 0xaa56e3d21a1fd975ull, 0x33f2f688b5a2e046ull, 0x0f35b7eceaf320a2ull, 0xc502b090b421fd03ull}},
    {"light_on_heavy",    {0x412ac5113a1dbc1bull, 0x52f9d1445a8e0ec8ull, 0x8a82f62846cfe53cull, 0xdb4111cb16a68ac2ull, 0x6fbac7214c1950e2ull, 0xbbdf6483cbe71b98ull}},
    {"overlap_recovery",  {0x6c595e47a1f61691ull, 0x0765c923af4bcc68ull, 0x4ae0f91b1ec5016bull, 0xa7d402ce5f74846aull, 0x8d04f5d6b1020144ull, 0x66c595b1bb842aa7ull}},
    {"bridge_chains",     {0xef0fd69dba5d1075ull, 0x61d99f40b2541c7aull, 0xe352fb464e461af6ull, 0x01d3274a38962b66ull, 0x35929266538ed213ull, 0x09eb85ee2218a149ull}},
    {"far_chain",         {0x0e98340a8e5a0678ull, 0xd1289c34fee41d21ull, 0x88cfcd3eaa5be520ull, 0xc953d02ac214908full, 0x2269af8cc8b0389dull, 0xc09e6f3dcc1c3389ull}},
    {"ramps",             {0xe887cb6911c6f6a0ull, 0x47756cce01f1cda0ull, 0x12067a99d5fe29d0ull, 0x810c62b7d7858511ull, 0x56f0f2a9cd66e867ull, 0x61fa07183851a0cdull}},
    {"bullets",           {0x6f47b88745773ab5ull, 0x0b0393f5adf4ca86ull, 0xe2f5e8c37ac533d6ull, 0x05573601d1fabe3eull, 0xa285efda23f1afccull, 0x12291ee4e9a67e51ull}},
    {"platformer",        {0x9bc2b98b555427cfull, 0xcc29547bac14081dull, 0xadf8fcb74754f0f9ull, 0x3f849141a3bb391aull, 0x3ee98ef7c1d69ce6ull, 0xa84b0a25614b5131ull}},
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

// The same for the substepped set-up (substeppedOptions), whose numerics the table above does
// not reach: its worlds step once a frame. Regenerated as kRecorded is, with
// --gtest_filter=Determinism.RecordedSubsteppedHashes. Recorded with GCC 12 (SSE2); CI's clang
// build with AVX2 checks it too.
struct RecordedSubsteppedHash {
    const char* scene;
    std::uint64_t hash;
};
// clang-format off
const RecordedSubsteppedHash kRecordedSubstepped[] = {
    {"pendulum",          0xcd14c01a0008a5d4ull},
    {"pendulum_20",       0x1ccb186267f9b84aull},
    {"pendulum_limit",    0xc1c50f3644ff3040ull},
    {"double_pendulum",   0x219a19e92413d08bull},
    {"motor_wheel",       0x867c0613cf5f0736ull},
    {"bridge",            0x86302a69ff035ad4ull},
    {"chain",             0x4b45cf66d353554bull},
    {"long_bridge",       0x70d1ea13f7e54f42ull},
    {"bridge_heavy",      0x1164968c8a7ce248ull},
    {"bridge_crate",      0xbf7714a5d7de2b4dull},
    {"pyramid",           0x25096a661c4f963bull},
    {"tumbler",           0x0d59ed4edd506d9aull},
    {"pendulum_drag",     0x30d2892b86814f2aull},
    {"chain_drag",        0x750b3d9476f6c0c1ull},
    {"ragdoll",           0x23ee143556614319ull},
    {"ragdoll_motorized", 0x1062662b1e2357e8ull},
    {"ragdoll_pile",      0x238571d296f46283ull},
    {"distance_pendulum", 0x7905875a06463465ull},
    {"distance_pendulum_offset",      0x5dc7a1db5539d4bfull},
    {"rope",              0xaf785e94251002bbull},
    {"plank_rope",        0xa43cf5704ebfc242ull},
    {"pulley",            0x2cb6fefe13dc784aull},
    {"top_down",          0xfeffdffebf84c6a2ull},
    {"motor_drive",       0xddfdc9208b56f245ull},
    {"weld_beam",         0xe56de113fab52bebull},
    {"car",               0x5c6c0724fce6c7b4ull},
    {"elevator",          0x07ec8b806a3300e3ull},
    {"pulley_gear",       0xaf6a5f8647bc40a2ull},
    {"stretched_chain",   0x9eea2127379c1933ull},
    {"stretched_chain_hanging",     0x26840f32e7386583ull},
    {"ball_chain",        0x46f54c0c700902f4ull},
    {"rope_load",         0x27b163dcb1821b18ull},
    {"mass_ratio",        0xc4826867156888edull},
    {"heavy_stack",       0x40d8effa645525e0ull},
    {"light_on_heavy",    0xcd74fe11ac64159dull},
    {"overlap_recovery",  0xcbb1c2291d175d9cull},
    {"bridge_chains",     0x2f2e38338eb545d2ull},
    {"far_chain",         0xc00f883a1a5cb87dull},
    {"ramps",             0xe320c5bc00b1cd1dull},
    {"bullets",           0x19838b952df09d7eull},
    {"platformer",        0x21d56d9d615012bdull},
};
// clang-format on

TEST(Determinism, RecordedSubsteppedHashes) {
    const bool print = std::getenv("PIVOT_PRINT_HASHES") != nullptr;
    EXPECT_EQ(std::size(kRecordedSubstepped), allScenes().size()) << "a scene without a hash";
    for (std::size_t n = 0; n < allScenes().size(); ++n) {
        const SceneInfo& info = allScenes()[n];
        const std::uint64_t hash = hashOfRun(info, substeppedOptions(), 600);
        if (print) {
            std::printf("    {\"%s\",%*s0x%016llxull},\n", info.name,
                        static_cast<int>(18 - std::strlen(info.name)), "",
                        static_cast<unsigned long long>(hash));
        }
        if (n >= std::size(kRecordedSubstepped)) continue;
        EXPECT_STREQ(kRecordedSubstepped[n].scene, info.name);
        EXPECT_EQ(hash, kRecordedSubstepped[n].hash)
            << info.name << ": the substepped numerics changed (see the comment above kRecorded)";
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
