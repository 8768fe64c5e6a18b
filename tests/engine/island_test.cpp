// Islands: what is solved together.
#include <gtest/gtest.h>

#include "islands/island_builder.h"
#include "pivot/pivot.h"
#include "scenes/scene.h"
#include "solver/stepper.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
BodyId link(World& world, Vec2 p) {
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = p;
    BodyId b = world.createBody(bd);
    world.createShape(b, ShapeDef{}, Polygon::box(0.5f, 0.1f));
    return b;
}
}  // namespace

TEST(Islands, StaticBodiesDoNotJoinIslands) {
    // Two pendulums on one static ground: two islands, each with the ground in it.
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId left = link(world, {-5, 0});
    BodyId right = link(world, {5, 0});
    world.createJoint(RevoluteJointDef::atWorldAnchor(ground, left, {-5.5f, 0}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(ground, right, {4.5f, 0}));
    BodyId loose = link(world, {0, 10});  // a body with no joint is an island of its own
    (void)loose;
    world.step(1.0f / 60.0f);
    const StepStats& s = world.lastStepStats();
    EXPECT_EQ(s.islandCount, 3);
    EXPECT_EQ(s.jointCount, 2);
    EXPECT_EQ(s.bodyCount, 2 + 2 + 1);  // the ground has a slot in each pendulum's island
}

TEST(Islands, JointsBetweenDynamicBodiesJoinThem) {
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId a = link(world, {0.5f, 0});
    BodyId b = link(world, {1.5f, 0});
    BodyId c = link(world, {2.5f, 0});
    world.createJoint(RevoluteJointDef::atWorldAnchor(ground, a, {0, 0}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(a, b, {1, 0}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(b, c, {2, 0}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(c, ground, {3, 0}));
    world.step(1.0f / 60.0f);
    EXPECT_EQ(world.lastStepStats().islandCount, 1);
    EXPECT_EQ(world.lastStepStats().jointCount, 4);
    EXPECT_EQ(world.lastStepStats().bodyCount, 4);  // ground reached from both ends, slotted once
}

TEST(Islands, NgsIterationsAreReportedAndZeroWithoutNgsJoints) {
    WorldDef def = oneSubstepDef();
    def.defaultPositionSolver = PositionSolver::Baumgarte;
    World world(def);
    BodyId ground = world.createBody(BodyDef{});
    BodyId a = link(world, {0.5f, 0});
    world.createJoint(RevoluteJointDef::atWorldAnchor(ground, a, {0, 0}));
    world.step(1.0f / 60.0f);
    EXPECT_EQ(world.lastStepStats().positionIterations, 0);
}

namespace {

struct ContactReading {
    explicit ContactReading(IslandBuilder::ContactReading reading) {
        IslandBuilder::setContactReading(reading);
    }
    ~ContactReading() { IslandBuilder::setContactReading(IslandBuilder::ContactReading::Auto); }
};

}  // namespace

namespace {

// Builds `info` twice on `workers` workers and steps the two side by side, each step of the
// first made by stepFirst(world, dt) and of the second by stepSecond(world, dt) (under whatever
// switch each sets), failing at the first step where their states differ.
template <typename StepFirst, typename StepSecond>
void expectLockstep(const scenes::SceneInfo& info, int workers, int steps, StepFirst stepFirst,
                    StepSecond stepSecond) {
    scenes::SceneOptions options;
    options.workerCount = workers;
    scenes::Scene first = scenes::buildScene(info, options);
    scenes::Scene second = scenes::buildScene(info, options);
    const float dt = 1.0f / options.hz;
    for (int i = 0; i < steps; ++i) {
        if (first.beforeStep) first.beforeStep(first, i);
        if (second.beforeStep) second.beforeStep(second, i);
        stepFirst(*first.world, dt);
        stepSecond(*second.world, dt);
        ASSERT_EQ(first.world->stateHash(), second.world->stateHash())
            << info.name << ", workers " << workers << ", step " << i;
    }
}

}  // namespace

TEST(Islands, TheContactTableFindsWhatTheListsFind) {
    // The search reads contacts from the bodies' lists or from a table it builds from the
    // contact pool; both must give the same islands in the same order, hence the same bits.
    // Scenes with contacts made and destroyed, sensors, sleep and waking, continuous collision.
    const auto stepReading = [](IslandBuilder::ContactReading how) {
        return [how](World& world, float dt) {
            ContactReading reading(how);
            world.step(dt);
        };
    };
    for (const char* name : {"pyramid", "ramps", "bullets", "platformer", "heavy_stack",
                             "overlap_recovery", "top_down", "car"}) {
        for (int workers = 1; workers <= 2; ++workers) {
            expectLockstep(*scenes::findScene(name), workers, 300,
                           stepReading(IslandBuilder::ContactReading::Lists),
                           stepReading(IslandBuilder::ContactReading::Table));
        }
    }
}

namespace {

struct IslandReuse {
    explicit IslandReuse(Stepper::IslandReuse reuse) { Stepper::setIslandReuse(reuse); }
    ~IslandReuse() { Stepper::setIslandReuse(Stepper::IslandReuse::Keep); }
};

}  // namespace

TEST(Islands, KeptIslandsAreTheOnesTheSearchFinds) {
    // A step keeps the last step's islands, and their plans, when nothing the search reads has
    // changed since (IslandRevision). Every scene (scripted events, sleep, contacts made and
    // ended, joints let go) on one and two workers: searched every step, no step that would
    // have kept its islands finds others; and a world that keeps them steps to the same bits
    // as one that searches and plans every step. (pivot-fuzz --verify-islands drives the
    // world's calls between steps the same way.)
    const auto stepReusing = [](Stepper::IslandReuse how) {
        return [how](World& world, float dt) {
            IslandReuse reuse(how);
            world.step(dt);
        };
    };
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        for (int workers = 1; workers <= 2; ++workers) {
            const std::uint64_t misKeptBefore = Stepper::islandsMisKept();
            expectLockstep(info, workers, 200, stepReusing(Stepper::IslandReuse::Keep),
                           stepReusing(Stepper::IslandReuse::Verify));
            EXPECT_EQ(Stepper::islandsMisKept(), misKeptBefore)
                << info.name << ", workers " << workers;
        }
    }
}

TEST(Islands, AreKeptWhileNothingChangesAndSearchedAgainWhenSomethingDoes) {
    // The verification above would pass if islands were never kept: a swinging chain keeps
    // them, and a body made, a joint made, a body put to sleep makes the next step search.
    const std::uint64_t misKeptBefore = Stepper::islandsMisKept();
    IslandReuse reuse(Stepper::IslandReuse::Verify);
    WorldDef def = oneSubstepDef();
    def.enableSleep = false;
    World world(def);
    BodyId ground = world.createBody(BodyDef{});
    BodyId a = link(world, {0.5f, 0});
    BodyId b = link(world, {1.5f, 0});
    world.createJoint(RevoluteJointDef::atWorldAnchor(ground, a, {0, 0}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(a, b, {1, 0}));
    const auto unchangedAfterStep = [&world] {
        const std::uint64_t before = Stepper::stepsWithIslandsUnchanged();
        world.step(1.0f / 60.0f);
        return Stepper::stepsWithIslandsUnchanged() > before;
    };
    EXPECT_FALSE(unchangedAfterStep());  // the first step searches
    for (int i = 0; i < 30; ++i) EXPECT_TRUE(unchangedAfterStep()) << "step " << i;
    EXPECT_EQ(world.lastStepStats().islandCount, 1);

    BodyDef loose;
    loose.type = BodyType::Dynamic;
    loose.position = {10, 10};
    BodyId c = world.createBody(loose);
    EXPECT_FALSE(unchangedAfterStep());
    EXPECT_EQ(world.lastStepStats().islandCount, 2);
    EXPECT_TRUE(unchangedAfterStep());
    world.createJoint(RevoluteJointDef::atWorldAnchor(b, c, {2, 0}));
    EXPECT_FALSE(unchangedAfterStep());
    EXPECT_EQ(world.lastStepStats().islandCount, 1);
    world.setBodyAwake(c, false);
    EXPECT_FALSE(unchangedAfterStep());  // searched, and c woken by its joint
    EXPECT_FALSE(unchangedAfterStep());  // c is a seed now: searched again
    EXPECT_TRUE(unchangedAfterStep());
    EXPECT_EQ(Stepper::islandsMisKept(), misKeptBefore);
}
