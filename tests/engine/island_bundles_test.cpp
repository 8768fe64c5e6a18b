// Small islands solved together (solver/island_bundles.h): every island of a bundle must end
// each step with the bits, the report and the events it has when solved alone.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "all_solvers.h"
#include "pivot/pivot.h"
#include "same_step_stats.h"
#include "scoped_switch.h"
#include "solver/island_bundles.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;
using IslandBundling = ScopedSwitch<&setIslandBundling>;

// Chains of every position solver and of several lengths (so bundled islands converge after
// different numbers of NGS sweeps), some with limits, one that breaks, one let go for its
// separation, falling onto a ground with loose bricks and pairs of bricks (islands of contacts
// only) that come to rest and sleep.
std::unique_ptr<World> smallIslands(int substeps, ContactCorrection contacts, int workers) {
    WorldDef def = oneSubstepDef();
    def.substepCount = substeps;
    def.contactCorrection = contacts;
    def.workerCount = workers;
    auto world = std::make_unique<World>(def);
    BodyId ground = world->createBody(BodyDef{});
    world->createShape(ground, ShapeDef{}, Polygon::box(80.0f, 1.0f, {0.0f, -1.0f}, 0.0f));

    float x = -70.0f;
    int chain = 0;
    for (PositionSolver solver : test_support::kAllSolvers) {
        for (int links : {3, 6, 11}) {
            BodyId previous = ground;
            for (int i = 0; i < links; ++i) {
                BodyDef bd;
                bd.type = BodyType::Dynamic;
                bd.position = {x + 0.5f + float(i), 6.0f};
                const BodyId link = world->createBody(bd);
                world->createShape(link, ShapeDef{}, Polygon::box(0.5f, 0.1f));
                RevoluteJointDef jd =
                    RevoluteJointDef::atWorldAnchor(previous, link, {x + float(i), 6.0f});
                jd.positionSolver = solver;
                if (chain % 3 == 1) jd.limit = {true, -0.6f, 0.6f};
                if (chain == 4 && i == links - 1)
                    jd.breakForce = 0.5f;  // less than the link it holds weighs
                if (chain == 8 && i == 2) jd.letGoSeparation = 0.02f;
                // Joints asking for more sweeps than the world's: an island stops its own
                // extra sweeps when its asking joints are within slop, as it would alone.
                if (chain % 4 == 2) jd.extraPositionIterations = 1 + i % 3;
                world->createJoint(jd);
                previous = link;
            }
            x += float(links) + 1.5f;
            ++chain;
        }
    }
    for (int i = 0; i < 12; ++i) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {x + 1.5f * float(i), 0.6f + 0.1f * float(i % 3)};
        bd.angle = 0.1f * float(i % 4);
        world->createShape(world->createBody(bd), ShapeDef{}, Polygon::box(0.5f, 0.5f));
        if (i % 2 == 0) {
            bd.position.y += 1.2f;
            world->createShape(world->createBody(bd), ShapeDef{}, Polygon::box(0.4f, 0.4f));
        }
    }
    return world;
}

}  // namespace

TEST(IslandBundles, EachIslandStepsToTheBitsItHasAlone) {
    for (int substeps : {1, 4}) {
        for (ContactCorrection contacts : {ContactCorrection::NGS, ContactCorrection::Soft}) {
            for (int workers : {1, 2}) {
                SCOPED_TRACE(testing::Message()
                             << substeps << " substeps, contacts " << static_cast<int>(contacts)
                             << ", " << workers << " workers");
                auto bundled = smallIslands(substeps, contacts, workers);
                auto alone = smallIslands(substeps, contacts, workers);
                const std::uint64_t bundledBefore = islandsSolvedInBundles();
                int letGo = 0, maxIslands = 0;
                for (int step = 0; step < 300; ++step) {
                    {
                        IslandBundling on(true);
                        bundled->step(kDt);
                    }
                    {
                        IslandBundling off(false);
                        alone->step(kDt);
                    }
                    ASSERT_EQ(bundled->stateHash(), alone->stateHash()) << "step " << step;
                    const StepStats& a = bundled->lastStepStats();
                    ASSERT_TRUE(test_support::sameSolverStats(a, alone->lastStepStats()))
                        << "step " << step;
                    const std::vector<JointLetGoEvent> x = bundled->jointLetGoEvents();
                    const std::vector<JointLetGoEvent> y = alone->jointLetGoEvents();
                    ASSERT_EQ(x.size(), y.size());
                    for (std::size_t k = 0; k < x.size(); ++k) {
                        EXPECT_EQ(x[k].joint.index, y[k].joint.index);
                        EXPECT_EQ(x[k].reason, y[k].reason);
                    }
                    letGo += a.letGoJointCount;
                    maxIslands = std::max(maxIslands, a.islandCount);
                }
                // The case covered what it is meant to: bundles, let-go joints, sleep.
                EXPECT_GT(islandsSolvedInBundles(), bundledBefore);
                EXPECT_GE(letGo, 1);
                EXPECT_GT(maxIslands, 20);
                EXPECT_GT(bundled->lastStepStats().sleepingBodyCount, 0);
            }
        }
    }
}

TEST(IslandBundles, OffSolvesNoIslandInABundle) {
    auto world = smallIslands(1, ContactCorrection::NGS, 1);
    IslandBundling off(false);
    const std::uint64_t before = islandsSolvedInBundles();
    for (int step = 0; step < 10; ++step) world->step(kDt);
    EXPECT_EQ(islandsSolvedInBundles(), before);
}
