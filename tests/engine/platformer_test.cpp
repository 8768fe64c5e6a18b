// The platformer scene (issue 15 item 6) does what it says: the character goes up through the
// one-way platforms and lands on them, picks up the coin, crosses the bridge, which breaks under
// the crate behind it; and a snapshot taken halfway, restored after the run ends, replays to the
// same end state on one worker and on two.
#include <gtest/gtest.h>

#include <vector>

#include "pivot/pivot.h"
#include "scenes/scene.h"

using namespace pivot;
using namespace pivot::scenes;

namespace {
constexpr float kDt = 1.0f / 60.0f;
constexpr int kSteps = 600;
}  // namespace

TEST(Platformer, PlaysItsStory) {
    Scene scene = buildScene(*findScene("platformer"), SceneOptions{});
    World& world = *scene.world;
    const BodyId character = scene.bodies[0];
    bool onPlatform1 = false, onPlatform2 = false, throughFromBelow = false;
    int coinTaken = -1, firstBreak = -1, breaks = 0;
    const int bodiesBefore = world.bodyCount();
    for (int i = 0; i < kSteps; ++i) {
        scene.beforeStep(scene, i);
        if (world.bodyCount() < bodiesBefore && coinTaken < 0) coinTaken = i;
        world.step(kDt);
        const Vec2 p = world.bodyPosition(character);
        const Vec2 v = world.bodyLinearVelocity(character);
        // Standing on a platform's top (1.9 m, 2.7 m) plus the capsule's 0.7 m to its foot.
        if (p.x > -13.5f && p.x < -8.0f && std::fabs(p.y - 2.6f) < 0.03f && std::fabs(v.y) < 0.1f)
            onPlatform1 = true;
        if (p.x > -5.5f && p.x < 0.0f && std::fabs(p.y - 3.4f) < 0.03f && std::fabs(v.y) < 0.1f)
            onPlatform2 = true;
        // Rising through platform 1's slab (1.7 to 1.9 m) from below.
        if (p.x > -14.0f && p.x < -8.0f && p.y + 0.7f > 1.7f && p.y - 0.7f < 1.9f && v.y > 1.0f)
            throughFromBelow = true;
        for (const JointLetGoEvent& e : world.jointLetGoEvents()) {
            EXPECT_EQ(e.reason, JointLetGoReason::Force);
            EXPECT_GT(e.reaction, 1200.0f);
            if (firstBreak < 0) firstBreak = i;
            ++breaks;
        }
    }
    EXPECT_TRUE(throughFromBelow);
    EXPECT_TRUE(onPlatform1);
    EXPECT_TRUE(onPlatform2);
    EXPECT_GT(coinTaken, 0);
    // The bridge held the character and broke under the crate (dropped at 8 s).
    EXPECT_GT(firstBreak, 480);
    EXPECT_GE(breaks, 2);
    // The character ran on to the end of the level, on the ground.
    EXPECT_NEAR(world.bodyPosition(character).x, 22.0f, 0.2f);
    EXPECT_NEAR(world.bodyPosition(character).y, 0.7f, 0.03f);
}

// Save halfway; at the end, roll back to it and replay: the same end, bit for bit.
TEST(Platformer, RollingBackHalfwayReplaysToTheSameEnd) {
    for (int workers : {1, 2}) {
        SceneOptions options;
        options.workerCount = workers;
        Scene scene = buildScene(*findScene("platformer"), options);
        World& world = *scene.world;
        std::vector<std::uint8_t> halfway;
        for (int i = 0; i < kSteps; ++i) {
            if (i == kSteps / 2) halfway = world.snapshot();
            scene.beforeStep(scene, i);
            world.step(kDt);
        }
        const std::uint64_t end = world.stateHash();
        world.restore(halfway);
        for (int i = kSteps / 2; i < kSteps; ++i) {
            scene.beforeStep(scene, i);
            world.step(kDt);
        }
        EXPECT_EQ(world.stateHash(), end) << workers << " workers";
    }
}
