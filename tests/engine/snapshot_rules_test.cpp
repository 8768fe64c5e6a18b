// What restore promises about what it takes in (docs/snapshots.md): a setting only as its
// setter would take it, every relation the solver relies on checked, ids that stay stale, and a
// hash that sees everything that decides what later calls do.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "snapshot_bytes.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::test_support;

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId dynamicBox(World& world, Vec2 position) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Polygon::box(0.25f, 0.25f));
    return body;
}

// The settings' offsets in the state (docs/snapshots.md: the settings in WorldDef's order).
struct SettingField {
    const char* name;
    std::size_t offset;  // from kSnapshotState
    float bad;           // a value the setter (or WorldDef) refuses
};

}  // namespace

TEST(SnapshotRules, ASettingIsRestoredOnlyAsItsSetterWouldTakeIt) {
    World source{oneSubstepDef()};
    dynamicBox(source, {0.0f, 2.0f});
    source.step(kDt);
    const std::vector<std::uint8_t> good = source.snapshot();
    const SettingField fields[] = {
        {"gravity", 0, 1e30f},
        {"contactBiasFactor", 17, 7.0f},
        {"contactHertz", 21, -5.0f},
        {"contactDampingRatio", 25, -1.0f},
        {"contactPushSpeed", 29, 0.0f},
        {"restitutionThreshold", 33, -1.0f},
        {"jointLetGoSeparation", 43, -1.0f},
        {"hitEventThreshold", 59, -1.0f},
    };
    World target{oneSubstepDef()};
    const std::uint64_t before = target.stateHash();
    for (const SettingField& field : fields) {
        std::vector<std::uint8_t> bad = good;
        put(bad, kSnapshotState + field.offset, field.bad);
        reseal(bad);
        const std::string error = restoreError(target, bad);
        EXPECT_NE(error.find(std::string("the snapshot's ") + field.name), std::string::npos)
            << field.name << ": " << error;
        EXPECT_EQ(target.stateHash(), before) << field.name;
    }
    // The integers: the substep count, and the last step's 1/dt.
    for (const auto& [offset, value] : {std::pair<std::size_t, std::int32_t>{47, 0},
                                        std::pair<std::size_t, std::int32_t>{47, 1000}}) {
        std::vector<std::uint8_t> bad = good;
        put(bad, kSnapshotState + offset, value);
        reseal(bad);
        EXPECT_NE(restoreError(target, bad).find("substepCount"), std::string::npos) << value;
    }
    // The iteration counts (World::step(dt) runs them), each in [0, kMaxIterations].
    for (const auto& [offset, name] : {std::pair<std::size_t, const char*>{51, "velocityIterations"},
                                       std::pair<std::size_t, const char*>{55, "positionIterations"}}) {
        for (const std::int32_t value : {-1, kMaxIterations + 1}) {
            std::vector<std::uint8_t> bad = good;
            put(bad, kSnapshotState + offset, value);
            reseal(bad);
            EXPECT_NE(restoreError(target, bad).find(std::string("the snapshot's ") + name),
                      std::string::npos)
                << name << " " << value;
            EXPECT_EQ(target.stateHash(), before) << name;
        }
    }
    std::vector<std::uint8_t> bad = good;
    put(bad, kSnapshotState + 63, -60.0f);
    reseal(bad);
    EXPECT_NE(restoreError(target, bad).find("1/dt"), std::string::npos);
    EXPECT_EQ(target.stateHash(), before);
    // A value the setter takes restores, and reads back as the setter would have left it.
    source.setGravity({0.0f, kMaxGravity});
    target.restore(source.snapshot());
    EXPECT_EQ(target.gravity(), (Vec2{0.0f, kMaxGravity}));
    EXPECT_NO_THROW(target.setGravity(target.gravity()));
}

// The case: a gear whose side names as its base a body of another island. The island
// search and the solver take a gear's bases to be its joints' bodies A, so the reader checks it,
// with the gear's bodies and the geometry it copies.
TEST(SnapshotRules, AGearIsCheckedAgainstTheJointsItCouples) {
    World source{oneSubstepDef()};
    const BodyId ground = source.createBody(BodyDef{});
    const BodyId carrier = dynamicBox(source, {0.0f, 5.0f});  // a dynamic base
    source.createJoint(RevoluteJointDef::atWorldAnchor(ground, carrier, {0.0f, 5.0f}));
    const BodyId wheel1 = dynamicBox(source, {-1.0f, 5.0f});
    const BodyId wheel2 = dynamicBox(source, {1.0f, 5.0f});
    const JointId joint1 =
        source.createJoint(RevoluteJointDef::atWorldAnchor(carrier, wheel1, {-1.0f, 5.0f}));
    const JointId joint2 =
        source.createJoint(RevoluteJointDef::atWorldAnchor(carrier, wheel2, {1.0f, 5.0f}));
    GearJointDef gear;
    gear.joint1 = joint1;
    gear.joint2 = joint2;
    source.createJoint(gear);
    const BodyId elsewhere = dynamicBox(source, {20.0f, 5.0f});  // an island of its own
    for (int i = 0; i < 5; ++i) source.step(kDt);
    const std::vector<std::uint8_t> good = source.snapshot();

    // The gear's first side: revolute (0), joint1's slot, its base (the carrier), its anchor.
    std::vector<std::uint8_t> side{0};
    for (const std::vector<std::uint8_t>& b :
         {bytesOf(joint1.index), bytesOf(carrier.index), bytesOf(-1.0f), bytesOf(0.0f)}) {
        side.insert(side.end(), b.begin(), b.end());
    }
    const std::vector<std::size_t> at = find(good, side);
    ASSERT_EQ(at.size(), 1u);
    const std::size_t base = at[0] + 5;

    World target{oneSubstepDef()};
    const std::uint64_t empty = target.stateHash();
    for (const BodyId other : {elsewhere, wheel2, ground}) {
        std::vector<std::uint8_t> bad = good;
        put(bad, base, other.index);
        reseal(bad);
        EXPECT_NE(restoreError(target, bad).find("gear joint's bodies"), std::string::npos)
            << "base " << other.index;
        EXPECT_EQ(target.stateHash(), empty);
    }
    // Its copy of joint1's anchor on the base.
    std::vector<std::uint8_t> bad = good;
    put(bad, base + 4, -2.0f);
    reseal(bad);
    EXPECT_NE(restoreError(target, bad).find("copy of a joint"), std::string::npos);
    // The good one restores and steps.
    target.restore(good);
    for (int i = 0; i < 5; ++i) target.step(kDt);
}

// A contact's sensor flag follows its shapes (ContactManager::addPair): a solid contact marked a
// sensor contact is refused.
TEST(SnapshotRules, AContactIsOneTheContactManagerCouldHaveMade) {
    World source{oneSubstepDef()};
    const BodyId ground = source.createBody(BodyDef{});
    source.createShape(ground, ShapeDef{}, Polygon::box(5.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 0.5f};
    const BodyId ball = source.createBody(def);
    source.createShape(ball, ShapeDef{}, Circle{{}, 0.5f});
    for (int i = 0; i < 3; ++i) source.step(kDt);
    ASSERT_EQ(source.contacts().size(), 1u);
    const ContactData contact = source.contacts()[0];
    const std::vector<std::uint8_t> good = source.snapshot();
    // The contact's record: its two edges, shape A, shape B, the manifold (72 bytes: two points
    // of 24, the normal, the point, the type and the count), friction, restitution, then the
    // flags touching, needsFiltering, sensor.
    std::vector<std::uint8_t> shapes = bytesOf(contact.shapeA.index);
    const auto b = bytesOf(contact.shapeB.index);
    shapes.insert(shapes.end(), b.begin(), b.end());
    World target{oneSubstepDef()};
    const std::uint64_t empty = target.stateHash();
    int refused = 0;
    for (std::size_t at : find(good, shapes)) {
        const std::size_t sensor = at + 8 + 72 + 8 + 2;
        if (sensor >= good.size() - 8) continue;  // the pair found elsewhere, near the end
        if (good[sensor - 2] != 1 || good[sensor] != 0) continue;  // touching, not a sensor
        std::vector<std::uint8_t> bad = good;
        bad[sensor] = 1;
        reseal(bad);
        if (restoreError(target, bad).find("sensor flag") != std::string::npos) ++refused;
        EXPECT_EQ(target.stateHash(), empty);
    }
    EXPECT_EQ(refused, 1);
}

// The case: a body destroyed in this world, then another world's snapshot restored into
// it. The old id must not name the restored body that took its slot and generation.
TEST(SnapshotRules, AStaleIdStaysStaleWhateverIsRestored) {
    World world{oneSubstepDef()};
    const BodyId gone = dynamicBox(world, {0.0f, 1.0f});
    const std::vector<std::uint8_t> before = world.snapshot();
    world.destroyBody(gone);
    ASSERT_FALSE(world.isValid(gone));

    World other{oneSubstepDef()};
    const BodyId theirs = dynamicBox(other, {3.0f, 1.0f});
    ASSERT_EQ(theirs.index, gone.index);
    ASSERT_EQ(theirs.generation, gone.generation);
    world.restore(other.snapshot());
    EXPECT_FALSE(world.isValid(gone));
    EXPECT_THROW(world.bodyPosition(gone), Error);
    EXPECT_FALSE(world.isValid(theirs));  // another world's id is foreign here
    const std::vector<BodyId> ids = world.bodyIds();
    ASSERT_EQ(ids.size(), 1u);
    EXPECT_EQ(world.bodyPosition(ids[0]), (Vec2{3.0f, 1.0f}));
    // Back to this world's own earlier snapshot: ids from before the foreign restore stay stale
    // too (the world has moved on to another lineage), and the ones it hands out work.
    world.restore(before);
    EXPECT_FALSE(world.isValid(gone));
    EXPECT_FALSE(world.isValid(ids[0]));
    EXPECT_EQ(world.bodyIds().size(), 1u);
    // A rollback within one lineage keeps the ids (Snapshot.RollbackKeepsTheGamesIds).
    const BodyId now = world.bodyIds()[0];
    const std::vector<std::uint8_t> saved = world.snapshot();
    world.destroyBody(now);
    world.restore(saved);
    EXPECT_TRUE(world.isValid(now));
}

// Two worlds that hash alike answer the same calls alike: a fresh world and one where a body was
// made and destroyed differ in the slot the next body takes, so they must not hash alike.
TEST(SnapshotRules, EqualHashesGiveEqualFutures) {
    World fresh, used;
    used.destroyBody(used.createBody(BodyDef{}));
    EXPECT_NE(fresh.stateHash(), used.stateHash());
    const BodyId a = dynamicBox(fresh, {0.0f, 1.0f});
    const BodyId b = dynamicBox(used, {0.0f, 1.0f});
    EXPECT_NE(a.generation, b.generation);

    // And a world restored from another's snapshot hashes alike and goes on alike, ids too.
    World copy{oneSubstepDef()};
    copy.restore(used.snapshot());
    EXPECT_EQ(copy.stateHash(), used.stateHash());
    const BodyId c = dynamicBox(copy, {1.0f, 1.0f});
    const BodyId d = dynamicBox(used, {1.0f, 1.0f});
    EXPECT_EQ(c.index, d.index);
    EXPECT_EQ(c.generation, d.generation);
    for (int i = 0; i < 30; ++i) {
        copy.step(kDt);
        used.step(kDt);
    }
    EXPECT_EQ(copy.stateHash(), used.stateHash());
}
