// Islands: what is solved together.
#include <gtest/gtest.h>

#include "islands/island_builder.h"
#include "pivot/pivot.h"
#include "scenes/scene.h"

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
    World world;
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
    World world;
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
    WorldDef def;
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

TEST(Islands, TheContactTableFindsWhatTheListsFind) {
    // The search reads contacts from the bodies' lists or from a table it builds from the
    // contact pool; both must give the same islands in the same order, hence the same bits.
    // Scenes with contacts made and destroyed, sensors, sleep and waking, continuous collision.
    using scenes::SceneOptions;
    for (const char* name : {"pyramid", "ramps", "bullets", "platformer", "heavy_stack",
                             "overlap_recovery", "top_down", "car"}) {
        for (int workers = 1; workers <= 2; ++workers) {
            SceneOptions options;
            options.workerCount = workers;
            scenes::Scene lists = scenes::buildScene(*scenes::findScene(name), options);
            scenes::Scene table = scenes::buildScene(*scenes::findScene(name), options);
            for (int i = 0; i < 300; ++i) {
                if (lists.beforeStep) lists.beforeStep(lists, i);
                if (table.beforeStep) table.beforeStep(table, i);
                {
                    ContactReading reading(IslandBuilder::ContactReading::Lists);
                    lists.world->step(1.0f / options.hz);
                }
                {
                    ContactReading reading(IslandBuilder::ContactReading::Table);
                    table.world->step(1.0f / options.hz);
                }
                ASSERT_EQ(lists.world->stateHash(), table.world->stateHash())
                    << name << ", workers " << workers << ", step " << i;
            }
        }
    }
}
