// What a snapshot can make restore allocate (docs/snapshots.md, "Memory"): at most
// kSnapshotMemoryPerByte bytes per byte of the snapshot, plus a fixed few kilobytes, whatever
// its counts claim. A pool slot of a destroyed object costs 5 bytes of snapshot and its whole
// slot in memory: the writer pads a snapshot of pools full of them, and the reader refuses
// counts that ask for more than its size allows, before it allocates. Counted with the
// replaced global operator new.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/snapshot_io.h"
#include "heap/counting_new.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr long long kFixedBytes = 64 * 1024;

BodyId ballAt(World& world, Vec2 position) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Circle{{}, 0.5f});
    return body;
}

// Restores `bytes` into a fresh world; returns the bytes restore asked of operator new.
long long restoreCost(const std::vector<std::uint8_t>& bytes, bool* refused = nullptr) {
    World world{oneSubstepDef()};
    heap::Counter counter;
    try {
        world.restore(bytes);
        if (refused) *refused = false;
    } catch (const Error&) {
        if (refused) *refused = true;
    }
    return counter.allocatedBytes();
}

void expectWithinBound(const std::string& what, const std::vector<std::uint8_t>& bytes) {
    const long long cost = restoreCost(bytes);
    const long long bound =
        static_cast<long long>(kSnapshotMemoryPerByte * bytes.size()) + kFixedBytes;
    std::printf("%-34s %9zu bytes, restore allocated %10lld (%.1f per byte)\n", what.c_str(),
                bytes.size(), cost, double(cost) / double(bytes.size()));
    EXPECT_LE(cost, bound) << what << ": " << bytes.size() << " bytes of snapshot";
}

}  // namespace

// Worlds that keep many destroyed objects' slots, of each pool, and one of live objects; the
// counts just past a power of two (restore reserves the step's arrays rounded up to one) and not.
TEST(SnapshotMemory, RestoreTakesAtMostItsBound) {
    for (const int n : {16385, 20000}) {
        {
            World world{oneSubstepDef()};
            std::vector<BodyId> bodies;
            for (int i = 0; i < n; ++i) bodies.push_back(world.createBody(BodyDef{}));
            for (BodyId b : bodies) world.destroyBody(b);
            expectWithinBound("destroyed bodies", world.snapshot());
        }
        {
            World world{oneSubstepDef()};
            const BodyId body = world.createBody(BodyDef{});
            std::vector<ShapeId> shapes;
            for (int i = 0; i < n; ++i) {
                shapes.push_back(world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.5f)));
            }
            for (ShapeId s : shapes) world.destroyShape(s);
            expectWithinBound("destroyed shapes", world.snapshot());
        }
        {
            World world{oneSubstepDef()};
            const BodyId a = ballAt(world, {0.0f, 0.0f});
            const BodyId b = ballAt(world, {2.0f, 0.0f});
            std::vector<JointId> joints;
            for (int i = 0; i < n; ++i) {
                DistanceJointDef def;
                def.bodyA = a;
                def.bodyB = b;
                joints.push_back(world.createJoint(def));
            }
            for (JointId j : joints) world.destroyJoint(j);
            expectWithinBound("destroyed joints", world.snapshot());
        }
        {
            // Contacts: a pile of overlapping balls makes them; destroying the balls frees them.
            World world{oneSubstepDef()};
            const BodyId ground = world.createBody(BodyDef{});
            world.createShape(ground, ShapeDef{}, Polygon::box(100.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
            std::vector<BodyId> balls;
            for (int i = 0; i < 2000; ++i) {
                balls.push_back(ballAt(world, {-50.0f + 0.05f * float(i), 0.5f}));
            }
            world.step(1.0f / 60.0f);
            for (BodyId b : balls) world.destroyBody(b);
            expectWithinBound("destroyed contacts", world.snapshot());
        }
        {
            World world{oneSubstepDef()};
            const BodyId ball = ballAt(world, {0.0f, 0.0f});
            std::vector<MouseJointId> mice;
            for (int i = 0; i < n; ++i) {
                MouseJointDef def;
                def.body = ball;
                mice.push_back(world.createMouseJoint(def));
            }
            for (MouseJointId m : mice) world.destroyMouseJoint(m);
            expectWithinBound("destroyed mouse joints", world.snapshot());
        }
        {
            World world{oneSubstepDef()};
            const BodyId ground = world.createBody(BodyDef{});
            world.createShape(ground, ShapeDef{}, Polygon::box(100.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
            BodyId previous = ground;
            for (int i = 0; i < 2000; ++i) {
                const BodyId b = ballAt(world, {-50.0f + 0.05f * float(i), 0.5f});
                world.createJoint(RevoluteJointDef::atWorldAnchor(previous, b, {0.0f, 3.0f}));
                previous = b;
            }
            for (int i = 0; i < 3; ++i) world.step(1.0f / 60.0f);
            expectWithinBound("live bodies, joints and contacts", world.snapshot());
        }
    }
}

// A crafted snapshot claiming 2 million destroyed bodies, 5 bytes of it each: refused, having
// allocated little.
TEST(SnapshotMemory, CountsAskingForMoreThanTheBoundAreRefusedFirst) {
    World source{oneSubstepDef()};
    const std::vector<std::uint8_t> small = source.snapshot();
    // The body pool's slot count follows the settings, 67 bytes of them after the lineage.
    const std::size_t countAt = 20 + 4 + 67;
    ASSERT_EQ(small[countAt], 0);
    const std::uint32_t claimed = 2000000;
    std::vector<std::uint8_t> bytes(small.begin(), small.begin() + countAt);
    for (int i = 0; i < 4; ++i) bytes.push_back(std::uint8_t(claimed >> (8 * i)));
    for (std::uint32_t i = 0; i < claimed; ++i) {
        const std::uint8_t deadSlot[5] = {2, 0, 0, 0, 0};  // generation 2, not alive
        bytes.insert(bytes.end(), deadSlot, deadSlot + 5);
    }
    bytes.insert(bytes.end(), small.begin() + countAt + 4, small.end());
    // The header's payload size, and the checksum.
    const std::uint64_t payload = bytes.size() - 20 - 8;
    for (int i = 0; i < 8; ++i) bytes[12 + i] = std::uint8_t(payload >> (8 * i));
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 20; i < bytes.size() - 8; ++i) {
        h ^= bytes[i];
        h *= 0x100000001b3ull;
    }
    for (int i = 0; i < 8; ++i) bytes[bytes.size() - 8 + i] = std::uint8_t(h >> (8 * i));
    bool refused = false;
    const long long cost = restoreCost(bytes, &refused);
    EXPECT_TRUE(refused);
    EXPECT_LE(cost, kFixedBytes) << bytes.size() << " bytes of snapshot";
}
