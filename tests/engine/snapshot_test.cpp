// World snapshots (issue 15 item 5): a restored world continues bit for bit, into a fresh world
// on 1 and 2 workers and into the same world (a rollback); bytes that are not a snapshot, of
// another version, truncated or corrupted are refused and change nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/scene.h"
#include "snapshot_bytes.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr std::size_t kHeader = test_support::kSnapshotHeader;
using test_support::reseal;
using test_support::restoreError;
using test_support::stateOf;

// A small world of every kind of object: shapes of each type, a joint of each type, a mouse
// joint, sleeping and awake bodies, contacts.
void buildSmallWorld(World& world) {
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(10.0f, 0.5f));
    world.createChain(ground, ShapeDef{}, Chain{{{12, 3}, {10, 0.5f}, {6, 0.5f}, {4, 2}}, false});
    BodyDef dynamic;
    dynamic.type = BodyType::Dynamic;
    BodyId previous = ground;
    for (int i = 0; i < 4; ++i) {
        dynamic.position = {-4.0f + 2.0f * i, 2.0f};
        const BodyId b = world.createBody(dynamic);
        if (i % 2 == 0) {
            world.createShape(b, ShapeDef{}, Polygon::box(0.4f, 0.4f));
        } else {
            world.createShape(b, ShapeDef{}, Capsule{{-0.3f, 0}, {0.3f, 0}, 0.2f});
        }
        if (i > 0) {
            DistanceJointDef rope;
            rope.bodyA = previous;
            rope.bodyB = b;
            rope.length = 2.0f;
            world.createJoint(rope);
        }
        previous = b;
    }
    dynamic.position = {0.0f, 5.0f};
    const BodyId wheel = world.createBody(dynamic);
    world.createShape(wheel, ShapeDef{}, Circle{{0, 0}, 0.5f});
    world.createJoint(RevoluteJointDef::atWorldAnchor(previous, wheel, {0.0f, 5.0f}));
    MouseJointDef mouse;
    mouse.body = wheel;
    mouse.target = {1.0f, 6.0f};
    mouse.maxForce = 100.0f;
    world.createMouseJoint(mouse);
}

}  // namespace

TEST(Snapshot, RoundTripsASmallWorldExactly) {
    World world{oneSubstepDef()};
    buildSmallWorld(world);
    for (int i = 0; i < 30; ++i) world.step(kDt);
    const std::vector<std::uint8_t> bytes = world.snapshot();
    EXPECT_EQ(bytes, world.snapshot());  // a function of the state
    World copy{oneSubstepDef()};
    copy.restore(bytes);
    EXPECT_EQ(copy.stateHash(), world.stateHash());
    EXPECT_EQ(stateOf(copy.snapshot()), stateOf(bytes));
    EXPECT_EQ(copy.bodyCount(), world.bodyCount());
    EXPECT_EQ(copy.jointCount(), world.jointCount());
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        copy.step(kDt);
    }
    EXPECT_EQ(copy.stateHash(), world.stateHash());
}

// Every testbed scene, with either policy for the broad phase's boxes: step N (with its script),
// snapshot, step M; restored into fresh worlds of 1 and 2 workers, and into the same world, M
// steps give the same hash. A restored world's own snapshot holds the same state, byte for byte
// (under its own lineage).
class EverySceneSnapshot : public testing::TestWithParam<std::string> {};

namespace {

void continuesBitForBit(const std::string& name, BroadPhaseBoxes boxes) {
    SCOPED_TRACE(static_cast<int>(boxes));
    SceneOptions options;
    options.broadPhaseBoxes = boxes;
    Scene scene = buildScene(*findScene(name), options);
    World& world = *scene.world;
    constexpr int kBefore = 90, kAfter = 90;
    for (int i = 0; i < kBefore; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, i);
        world.step(kDt);
    }
    const std::vector<std::uint8_t> bytes = world.snapshot();
    const std::uint64_t atSnapshot = world.stateHash();
    for (int i = 0; i < kAfter; ++i) world.step(kDt);
    const std::uint64_t expected = world.stateHash();

    for (int workers : {1, 2}) {
        WorldDef def = oneSubstepDef();
        def.workerCount = workers;
        World restored(def);
        restored.restore(bytes);
        EXPECT_EQ(restored.stateHash(), atSnapshot) << workers << " workers";
        EXPECT_EQ(restored.broadPhaseBoxes(), boxes);
        EXPECT_TRUE(stateOf(restored.snapshot()) == stateOf(bytes)) << workers << " workers";
        for (int i = 0; i < kAfter; ++i) restored.step(kDt);
        EXPECT_EQ(restored.stateHash(), expected) << workers << " workers";
    }
    // A rollback: the same world, its ids still valid.
    world.restore(bytes);
    EXPECT_EQ(world.stateHash(), atSnapshot);
    for (int i = 0; i < kAfter; ++i) world.step(kDt);
    EXPECT_EQ(world.stateHash(), expected);
}

}  // namespace

TEST_P(EverySceneSnapshot, ContinuesBitForBitOnOneAndTwoWorkers) {
    continuesBitForBit(GetParam(), BroadPhaseBoxes::Predictive);
    continuesBitForBit(GetParam(), BroadPhaseBoxes::Compact);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EverySceneSnapshot, testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const SceneInfo& info : allScenes()) names.push_back(info.name);
                             return names;
                         }()),
                         [](const auto& info) { return info.param; });

TEST(Snapshot, RollbackKeepsTheGamesIds) {
    World world{oneSubstepDef()};
    buildSmallWorld(world);
    const std::vector<BodyId> bodies = world.bodyIds();
    for (int i = 0; i < 10; ++i) world.step(kDt);
    const std::vector<std::uint8_t> bytes = world.snapshot();
    const Vec2 before = world.bodyPosition(bodies.back());
    const BodyId added = world.createBody(BodyDef{});
    for (int i = 0; i < 20; ++i) world.step(kDt);
    world.restore(bytes);
    EXPECT_EQ(world.bodyPosition(bodies.back()), before);
    EXPECT_FALSE(world.isValid(added));  // made after the snapshot: gone
    // The slot it took is handed out again, with the generation it had then.
    EXPECT_EQ(world.createBody(BodyDef{}), added);
}

TEST(Snapshot, RefusesWhatIsNotASnapshotAndChangesNothing) {
    World source{oneSubstepDef()};
    buildSmallWorld(source);
    for (int i = 0; i < 10; ++i) source.step(kDt);
    const std::vector<std::uint8_t> good = source.snapshot();

    World target{oneSubstepDef()};
    buildSmallWorld(target);
    const std::uint64_t before = target.stateHash();
    EXPECT_NE(restoreError(target, {}).find("not a pivot2d snapshot"), std::string::npos);
    EXPECT_NE(restoreError(target, {'h', 'e', 'l', 'l', 'o'}).find("not a pivot2d snapshot"),
              std::string::npos);
    std::vector<std::uint8_t> version = good;
    version[8] = 99;  // a later pivot2d's
    EXPECT_NE(restoreError(target, version).find("format version 99"), std::string::npos);
    // Every cut is truncated.
    for (std::size_t size = 8; size < good.size(); size += 1 + size / 64) {
        const std::vector<std::uint8_t> cut(good.begin(), good.begin() + size);
        EXPECT_NE(restoreError(target, cut).find("truncated"), std::string::npos) << size;
    }
    std::vector<std::uint8_t> longer = good;
    longer.push_back(0);
    EXPECT_NE(restoreError(target, longer).find("after its end"), std::string::npos);
    // Every flipped byte of the payload or checksum is caught by the checksum.
    for (std::size_t i = kHeader; i < good.size(); i += 1 + i / 97) {
        std::vector<std::uint8_t> bad = good;
        bad[i] ^= 0x5A;
        EXPECT_NE(restoreError(target, bad).find("corrupted"), std::string::npos) << i;
    }
    EXPECT_EQ(target.stateHash(), before);
}

// Past the checksum (re-sealed), the reader's own checks catch what would break the engine: a
// flag that is not 0 or 1, an index out of range, a broken list. Whatever is accepted steps.
TEST(Snapshot, ResealedDamageIsRefusedOrStepsSafely) {
    World source{oneSubstepDef()};
    buildSmallWorld(source);
    for (int i = 0; i < 10; ++i) source.step(kDt);
    const std::vector<std::uint8_t> good = source.snapshot();
    World target{oneSubstepDef()};
    const std::uint64_t empty = target.stateHash();
    int refused = 0, accepted = 0;
    std::uint32_t seed = 99;
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<std::uint8_t> bad = good;
        seed = seed * 1664525u + 1013904223u;
        const std::size_t at = kHeader + (seed >> 8) % (good.size() - kHeader - 8);
        seed = seed * 1664525u + 1013904223u;
        bad[at] = static_cast<std::uint8_t>(bad[at] ^ (1u + (seed >> 24) % 255u));
        reseal(bad);
        World scratch{oneSubstepDef()};
        try {
            scratch.restore(bad);
            ++accepted;
            for (int i = 0; i < 5; ++i) scratch.step(kDt);
        } catch (const Error& e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find("World::restore"), std::string::npos);
            EXPECT_EQ(scratch.stateHash(), empty);
        }
    }
    EXPECT_GT(refused, 300);
    EXPECT_GT(accepted, 300);  // most bytes are numbers: any finite value restores
}

TEST(Snapshot, IsRefusedFromInsideACallback) {
    World world{oneSubstepDef()};
    buildSmallWorld(world);
    const std::vector<std::uint8_t> bytes = world.snapshot();
    bool refused = false;
    world.queryAABB({{-100, -100}, {100, 100}}, QueryFilter{}, [&](ShapeId) {
        try {
            world.restore(bytes);
        } catch (const Error&) {
            refused = true;
        }
        return false;
    });
    EXPECT_TRUE(refused);
}
