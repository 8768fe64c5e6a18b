// Once a world has stepped with a stable set of bodies, World::step allocates nothing: every
// buffer it needs (islands, solver arrays, pair buffers, events) keeps its capacity from one
// step to the next. Counted with a replaced global operator new.
#include <gtest/gtest.h>

#include <algorithm>

#include "heap/counting_new.h"
#include "scenes/metrics.h"
#include "scenes/parts.h"
#include "scenes/scene.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::scenes;

class EveryScene : public testing::TestWithParam<std::tuple<std::string, int>> {};

namespace {

// Steps the scene past every scripted event (drops, grabs, releases: they create bodies and
// joints, which may allocate) and until the number of contacts has peaked: 10 s, or 7 s after a
// late disturbance (the platformer's crate, dropped at 8 s, breaks a bridge whose planks tumble
// into a pit for seconds after). A new peak may still come later (the far chain's swinging
// links reach a new most of contacts now and then, long after their first seconds): the step's
// arrays are reserved for the contact pool rounded up to a power of two, so only a pool that
// has doubled allocates.
void warmUp(Scene& scene) {
    const int steps = std::max(600, scene.disturbanceEndStep + 420);
    for (int i = 0; i < steps; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, i);
        scene.world->step(1.0f / 60.0f);
    }
}

// Steps the scene past its warm-up, then returns what 300 more steps allocated.
long long warmStepAllocations(SceneOptions options, const std::string& name) {
    Scene scene = buildScene(*findScene(name), options);
    World& world = *scene.world;
    warmUp(scene);
    heap::Counter counter;
    for (int i = 0; i < 300; ++i) world.step(1.0f / 60.0f);
    return counter.allocations();
}

}  // namespace

// Under the default boxes (Compact, Box2D v3's: the tree refitted and regrouped, its scratch
// reserved for the whole tree).
TEST_P(EveryScene, StepsWithoutAllocatingOnceWarm) {
    SceneOptions options;
    options.workerCount = std::get<1>(GetParam());
    EXPECT_EQ(warmStepAllocations(options, std::get<0>(GetParam())), 0) << std::get<0>(GetParam());
}

// Under Box2D 2.4.1's boxes (moved proxies re-inserted) as well.
TEST_P(EveryScene, StepsWithoutAllocatingOnceWarmUnderPredictiveBoxes) {
    SceneOptions options;
    options.workerCount = std::get<1>(GetParam());
    options.broadPhaseBoxes = BroadPhaseBoxes::Predictive;
    EXPECT_EQ(warmStepAllocations(options, std::get<0>(GetParam())), 0) << std::get<0>(GetParam());
}

// Under Box2D v3's continuous collision (FastBodies: the bullets scene's fast bodies swept).
TEST_P(EveryScene, StepsWithoutAllocatingOnceWarmUnderFastBodies) {
    SceneOptions options;
    options.workerCount = std::get<1>(GetParam());
    options.continuousCollision = ContinuousCollision::FastBodies;
    EXPECT_EQ(warmStepAllocations(options, std::get<0>(GetParam())), 0) << std::get<0>(GetParam());
}

// Rollback: a game restores a snapshot and re-simulates a few steps, over and over. Restore
// copies the snapshot into the world's own storage, keeping its capacity, and reserves what a
// step sizes by the pools: from the first restore into a warm world on, the steps allocate
// nothing (restore itself does: it decodes the snapshot). The steps after the first restore
// allocated 7 times when restore moved freshly decoded buffers into the world.
TEST_P(EveryScene, StepsWithoutAllocatingAfterARestore) {
    SceneOptions options;
    options.workerCount = std::get<1>(GetParam());
    const std::string name = std::get<0>(GetParam());
    Scene scene = buildScene(*findScene(name), options);
    World& world = *scene.world;
    warmUp(scene);
    const std::vector<std::uint8_t> saved = world.snapshot();
    long long allocations = 0;
    for (int round = 0; round < 6; ++round) {
        world.restore(saved);
        heap::Counter counter;
        for (int i = 0; i < 4; ++i) world.step(1.0f / 60.0f);
        allocations += counter.allocations();
    }
    EXPECT_EQ(allocations, 0) << name;
}

namespace {
std::vector<std::string> sceneNames() {
    std::vector<std::string> names;
    for (const SceneInfo& info : allScenes()) names.push_back(info.name);
    return names;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene,
                         testing::Combine(testing::ValuesIn(sceneNames()), testing::Values(1, 2)),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" +
                                    std::to_string(std::get<1>(info.param)) + "_workers";
                         });

// Big islands are coloured and solved by every worker together (src/islands/team.h): their
// schedules and arrays are reused too. A 30 x 30 joint grid and a 40-row pyramid, side by side.
// With a game's task system (WorldDef::enqueueTask) too, one that allocates nothing itself (it
// runs each task at once): the world's side of it allocates nothing either.
TEST(ColouredIslands, StepWithoutAllocatingOnceWarm) {
    for (int variant : {1, 2, 3}) {
        WorldDef def = oneSubstepDef();
        def.workerCount = variant == 1 ? 1 : 2;
        if (variant == 3) {
            def.enqueueTask = [](StepTask task) -> void* {
                task();
                return nullptr;
            };
            def.finishTask = [](void*) {};
        }
        World world(def);
        addShelf(world, -50.0f, 50.0f, 0.0f);
        PyramidSpec pyramid;  // as the coloured-island reference test's
        pyramid.rows = 40;
        pyramid.pitchX = 1.1f;
        pyramid.pitchY = 1.0f;
        pyramid.floorGap = 0.0f;
        addPyramid(world, pyramid);
        ShapeDef circle;
        circle.filter.categoryBits = 0x0002;
        circle.filter.maskBits = 0x0001;
        std::vector<BodyId> grid;
        for (int row = 0; row < 30; ++row) {
            for (int col = 0; col < 30; ++col) {
                BodyDef body;
                body.type = row == 0 && col % 10 == 0 ? BodyType::Static : BodyType::Dynamic;
                body.position = {100.0f + float(col), 100.0f - float(row)};
                BodyId id = world.createBody(body);
                world.createShape(id, circle, Circle{{0.0f, 0.0f}, 0.4f});
                grid.push_back(id);
                if (row > 0) {
                    world.createJoint(RevoluteJointDef::atWorldAnchor(
                        grid[(row - 1) * 30 + col], id, body.position + Vec2{0.0f, 0.5f}));
                }
                if (col > 0) {
                    world.createJoint(RevoluteJointDef::atWorldAnchor(
                        grid[row * 30 + col - 1], id, body.position - Vec2{0.5f, 0.0f}));
                }
            }
        }
        for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);
        heap::Counter counter;
        for (int i = 0; i < 300; ++i) world.step(1.0f / 60.0f);
        EXPECT_EQ(counter.allocations(), 0)
            << def.workerCount << " workers" << (variant == 3 ? ", task system" : "");
    }
}

// Contacts that never settle: 200 elastic balls bouncing in a closed box without gravity or
// sleep, so pairs begin and end every step for ever. Every container must reach its working
// size during the warm-up and keep it; in particular the contact pair map must not re-create
// its table as pairs come and go. Counts the steps that allocated, not only the allocations, so
// a failure says how often it happens.
TEST(ChurningContacts, StepWithoutAllocatingOnceWarm) {
    for (int workers : {1, 2}) {
        WorldDef def = oneSubstepDef();
        def.gravity = {0.0f, 0.0f};
        def.enableSleep = false;
        def.workerCount = workers;
        World world(def);
        BodyId walls = world.createBody(BodyDef{});
        ShapeDef wall;
        wall.density = 0.0f;
        wall.friction = 0.0f;
        wall.restitution = 1.0f;
        world.createShape(walls, wall, Polygon::box(21.0f, 1.0f, {0.0f, -21.0f}, 0.0f));
        world.createShape(walls, wall, Polygon::box(21.0f, 1.0f, {0.0f, 21.0f}, 0.0f));
        world.createShape(walls, wall, Polygon::box(1.0f, 21.0f, {-21.0f, 0.0f}, 0.0f));
        world.createShape(walls, wall, Polygon::box(1.0f, 21.0f, {21.0f, 0.0f}, 0.0f));
        ShapeDef ball;
        ball.friction = 0.0f;
        ball.restitution = 1.0f;
        std::uint32_t seed = 12345;
        auto unit = [&seed] {  // a small fixed generator: the scene is the same everywhere
            seed = seed * 1664525u + 1013904223u;
            return float(seed >> 8) * (1.0f / 16777216.0f);
        };
        for (int i = 0; i < 200; ++i) {
            BodyDef body;
            body.type = BodyType::Dynamic;
            body.position = {-18.0f + 1.8f * float(i % 20), -18.0f + 1.8f * float(i / 20)};
            body.linearVelocity = {20.0f * unit() - 10.0f, 20.0f * unit() - 10.0f};
            world.createShape(world.createBody(body), ball, Circle{{0.0f, 0.0f}, 0.5f});
        }
        for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);
        int stepsThatAllocated = 0;
        long long total = 0;
        std::size_t begins = 0, ends = 0;
        for (int i = 0; i < 10000; ++i) {
            heap::Counter counter;
            world.step(1.0f / 60.0f);
            long long made = counter.allocations();
            total += made;
            if (made > 0) ++stepsThatAllocated;
            // After the count: the event lists are returned as copies, which allocate.
            begins += world.contactBeginEvents().size();
            ends += world.contactEndEvents().size();
        }
        EXPECT_EQ(total, 0) << workers << " workers: " << stepsThatAllocated
                            << " of 10000 warm steps allocated";
        // The scene really churns: on average a ball starts and ends a touch every few steps.
        EXPECT_GT(begins, 10000u);
        EXPECT_GT(ends, 10000u);
    }
}

// Queries allocate nothing either: a game may cast hundreds of rays a frame. A settled pyramid,
// queried with rays (closest and every hit), boxes, points and shapes over it.
TEST(Queries, AllocateNothing) {
    Scene scene = buildScene(*findScene("pyramid"), SceneOptions{});
    World& world = *scene.world;
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    heap::Counter counter;
    int hits = 0, found = 0;
    for (int i = 0; i < 1000; ++i) {
        const float x = -12.0f + 0.024f * float(i);
        hits += world.castRayClosest({x, 30.0f}, {0.3f, -40.0f}).has_value();
        world.castRay({-30.0f, 0.1f * float(i % 100)}, {60.0f, 1.0f}, QueryFilter{},
                      [&](const RayHit&) {
                          ++found;
                          return 1.0f;
                      });
        world.queryAABB(AABB{{x, 0.0f}, {x + 2.0f, 3.0f}}, QueryFilter{}, [&](ShapeId) {
            ++found;
            return true;
        });
        world.queryPoint({x, 1.0f}, QueryFilter{}, [&](ShapeId) {
            ++found;
            return true;
        });
        hits += world
                    .castShapeClosest(Circle{{0.0f, 0.0f}, 0.3f}, Transform{{x, 30.0f}, Rot(0.0f)},
                                      {0.0f, -40.0f})
                    .has_value();
        world.queryShape(Polygon::box(1.0f, 0.5f), Transform{{x, 2.0f}, Rot(0.3f)}, QueryFilter{},
                         [&](ShapeId) {
                             ++found;
                             return true;
                         });
    }
    EXPECT_EQ(counter.allocations(), 0);
    EXPECT_GT(hits, 1000);  // the queries did find things
    EXPECT_GT(found, 1000);
}
