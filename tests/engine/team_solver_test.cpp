// Big islands: graph colouring and the team of workers that solves one island together
// (src/islands/graph_coloring.h, island_schedule.h, team.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <set>
#include <thread>
#include <type_traits>
#include <vector>

#include "islands/graph_coloring.h"
#include "islands/island_schedule.h"
#include "islands/team.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Coloring {
    std::vector<std::int32_t> order;
    std::vector<Batch> batches;
};

Coloring colorAll(const std::vector<BodyPair>& pairs, const std::vector<std::uint8_t>& fixed) {
    std::vector<std::int32_t> items(pairs.size());
    for (std::size_t i = 0; i < items.size(); ++i) items[i] = static_cast<std::int32_t>(i);
    GraphColoring coloring;
    Coloring result;
    coloring.color(items.data(), static_cast<int>(items.size()), pairs.data(), fixed.data(),
                   static_cast<int>(fixed.size()), result.order, result.batches, 0);
    return result;
}

TEST(GraphColoring, NoColourTouchesAMovableBodyTwiceAndEveryConstraintAppearsOnce) {
    std::mt19937 random(7);
    const int bodies = 300;
    std::vector<std::uint8_t> fixed(bodies, 0);
    for (int i = 0; i < bodies; i += 17) fixed[i] = 1;
    std::uniform_int_distribution<int> pick(0, bodies - 1);
    std::vector<BodyPair> pairs;
    while (pairs.size() < 2000) {
        int a = pick(random), b = pick(random);
        if (a != b) pairs.push_back({a, b});
    }
    Coloring c = colorAll(pairs, fixed);

    std::vector<std::int32_t> sorted = c.order;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], std::int32_t(i));
    ASSERT_FALSE(c.batches.empty());
    EXPECT_EQ(c.batches.front().begin, 0);
    EXPECT_EQ(c.batches.back().end, 2000);
    for (std::size_t k = 0; k < c.batches.size(); ++k) {
        const Batch& batch = c.batches[k];
        if (k > 0) {
            EXPECT_EQ(batch.begin, c.batches[k - 1].end);
        }
        if (batch.serial) continue;
        std::set<std::int32_t> seen;
        for (std::int32_t at = batch.begin; at < batch.end; ++at) {
            const BodyPair& p = pairs[c.order[at]];
            for (std::int32_t body : p) {
                if (!fixed[body]) {
                    EXPECT_TRUE(seen.insert(body).second) << "colour " << k;
                }
            }
            // Within a colour, constraints keep the island's order.
            if (at > batch.begin) {
                EXPECT_LT(c.order[at - 1], c.order[at]);
            }
        }
    }
}

TEST(GraphColoring, RegionsOrderEachColourAndChangeNoColour) {
    // With regions, a colour lists its constraints region by region, each region's in their
    // original order; the colours themselves, and the serial overflow's order, are those
    // found without regions.
    std::mt19937 random(11);
    const int bodies = 120;
    std::vector<std::uint8_t> fixed(bodies, 0);
    std::uniform_int_distribution<int> pick(0, bodies - 1);
    std::vector<BodyPair> pairs;
    while (pairs.size() < 3000) {  // dense enough to overflow
        int a = pick(random), b = pick(random);
        if (a != b) pairs.push_back({a, b});
    }
    std::vector<std::int32_t> items(pairs.size());
    std::vector<std::uint8_t> regions(pairs.size());
    std::uniform_int_distribution<int> region(0, GraphColoring::kRegions - 1);
    for (std::size_t i = 0; i < items.size(); ++i) {
        items[i] = static_cast<std::int32_t>(i);
        regions[i] = static_cast<std::uint8_t>(region(random));
    }
    const Coloring plain = colorAll(pairs, fixed);
    GraphColoring coloring;
    Coloring zoned;
    coloring.color(items.data(), static_cast<int>(items.size()), pairs.data(), fixed.data(), bodies,
                   zoned.order, zoned.batches, 0, regions.data());
    ASSERT_EQ(zoned.batches.size(), plain.batches.size());
    ASSERT_TRUE(plain.batches.back().serial);
    for (std::size_t k = 0; k < plain.batches.size(); ++k) {
        const Batch& batch = zoned.batches[k];
        EXPECT_EQ(batch.begin, plain.batches[k].begin);
        EXPECT_EQ(batch.end, plain.batches[k].end);
        EXPECT_EQ(batch.serial, plain.batches[k].serial);
        std::vector<std::int32_t> mine(zoned.order.begin() + batch.begin,
                                       zoned.order.begin() + batch.end);
        std::vector<std::int32_t> theirs(plain.order.begin() + batch.begin,
                                         plain.order.begin() + batch.end);
        if (batch.serial) {
            EXPECT_EQ(mine, theirs);
            continue;
        }
        for (std::size_t at = 1; at < mine.size(); ++at) {
            const int before = regions[static_cast<std::size_t>(mine[at - 1])];
            const int here = regions[static_cast<std::size_t>(mine[at])];
            EXPECT_TRUE(before < here || (before == here && mine[at - 1] < mine[at]))
                << "colour " << k;
        }
        std::sort(mine.begin(), mine.end());
        EXPECT_EQ(mine, theirs) << "colour " << k;
    }
}

TEST(GraphColoring, ABodyWithMoreConstraintsThanColoursSpillsIntoASerialBatch) {
    const int spokes = GraphColoring::kMaxColors + 8;
    std::vector<std::uint8_t> fixed(spokes + 1, 0);
    std::vector<BodyPair> pairs;
    for (int i = 1; i <= spokes; ++i) pairs.push_back({0, i});
    Coloring c = colorAll(pairs, fixed);
    ASSERT_EQ(c.batches.size(), std::size_t(GraphColoring::kMaxColors + 1));
    EXPECT_TRUE(c.batches.back().serial);
    EXPECT_EQ(c.batches.back().end - c.batches.back().begin, 8);
    for (int k = 0; k < GraphColoring::kMaxColors; ++k) EXPECT_FALSE(c.batches[k].serial);
}

TEST(GraphColoring, BodiesThatNeverMoveDoNotSeparateConstraints) {
    // A static ground under 50 boxes: one colour, since only the ground is shared.
    std::vector<std::uint8_t> fixed(51, 0);
    fixed[0] = 1;
    std::vector<BodyPair> pairs;
    for (int i = 1; i <= 50; ++i) pairs.push_back({0, i});
    Coloring c = colorAll(pairs, fixed);
    ASSERT_EQ(c.batches.size(), 1u);
    EXPECT_FALSE(c.batches[0].serial);
}

// A grid of circles jointed to their neighbours above and to the left, hanging from its top
// row's middle; circles do not collide (as in the joint_grid benchmark). Strategies cycle so
// every group of a coloured island has joints.
struct JointGrid {
    World world{oneSubstepDef()};
    std::vector<JointId> joints;
};

// With `distanceJoints`, the horizontal links are distance joints (rods, every third a rope of
// 0.9 to 1.1 m, every fifth with a spring), so a coloured island holds both joint types.
// A grid of circles hung from three static ones, each linked to the one above by a pin and to
// its left neighbour by a pin, or (everyType) by every joint type in turn: distance, prismatic
// along the row, weld, pulley (wheels 3 m above each), friction, motor, wheel (sprung
// vertically) and revolute; and gears: between a cell's pin and its left neighbour's (four
// bodies), its pin and the pin above (one body on both sides), and a prismatic link and the
// left neighbour's pin (the same, the other way round).
void buildGrid(JointGrid& grid, int n, bool mixedSolvers, bool everyType = false) {
    World& world = grid.world;
    std::vector<BodyId> bodies;
    std::vector<JointId> pins(std::size_t(n) * std::size_t(n));  // each cell's pin from above
    ShapeDef shape;
    shape.filter.categoryBits = 0x0002;
    shape.filter.maskBits = 0x0001;
    const PositionSolver solvers[] = {PositionSolver::FullNGS,        PositionSolver::Baumgarte,
                                      PositionSolver::PseudoVelocity, PositionSolver::ModifiedNGS,
                                      PositionSolver::SoftStep,       PositionSolver::XPBD};
    for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
            BodyDef def;
            def.type =
                row == 0 && std::abs(col - n / 2) <= 1 ? BodyType::Static : BodyType::Dynamic;
            def.position = {float(col), -float(row)};
            BodyId body = world.createBody(def);
            world.createShape(body, shape, Circle{{0.0f, 0.0f}, 0.4f});
            bodies.push_back(body);
            const std::size_t k = grid.joints.size();
            const PositionSolver solver = solvers[k % std::size(solvers)];
            const auto link = [&](BodyId other, Vec2 anchor) {
                RevoluteJointDef joint = RevoluteJointDef::atWorldAnchor(other, body, anchor);
                if (mixedSolvers)
                    joint.positionSolver = solvers[grid.joints.size() % std::size(solvers)];
                grid.joints.push_back(world.createJoint(joint));
            };
            if (row > 0) {
                link(bodies[(row - 1) * n + col], {float(col), 0.5f - float(row)});
                pins[row * n + col] = grid.joints.back();
            }
            const auto gear = [&](JointId joint1, JointId joint2, float ratio) {
                GearJointDef joint;
                joint.joint1 = joint1;
                joint.joint2 = joint2;
                joint.ratio = ratio;
                if (mixedSolvers)
                    joint.positionSolver = solvers[grid.joints.size() % std::size(solvers)];
                grid.joints.push_back(world.createJoint(joint));
            };
            if (everyType && row > 1 && (col + row) % 8 == 7) {
                gear(pins[row * n + col], pins[(row - 1) * n + col], 1.0f);
            }
            if (col == 0) continue;
            if (everyType && row > 0 && (col + row) % 8 == 4) {
                gear(pins[row * n + col], pins[row * n + col - 1], -1.0f);
            }
            const BodyId left = bodies[row * n + col - 1];
            const Vec2 middle{float(col) - 0.5f, -float(row)};
            const auto add = [&](auto jointDef) {
                if constexpr (!std::is_same_v<decltype(jointDef), FrictionJointDef> &&
                              !std::is_same_v<decltype(jointDef), MotorJointDef>) {
                    if (mixedSolvers) jointDef.positionSolver = solver;
                }
                grid.joints.push_back(world.createJoint(jointDef));
            };
            switch (everyType ? (col + row) % 8 : 7) {
                case 0: {
                    DistanceJointDef joint;
                    joint.bodyA = left;
                    joint.bodyB = body;
                    if (k % 3 == 0) joint.limit = {true, 0.9f, 1.1f};
                    if (k % 5 == 0) joint.spring = {true, 4.0f, 0.3f};
                    add(joint);
                    break;
                }
                case 1: {
                    PrismaticJointDef joint =
                        PrismaticJointDef::atWorldAnchor(left, body, middle, {1.0f, 0.0f});
                    if (k % 3 == 0) joint.limit = {true, -0.1f, 0.1f};
                    if (k % 5 == 0) joint.spring = {true, 4.0f, 0.3f};
                    add(joint);
                    if (row > 0) gear(grid.joints.back(), pins[row * n + col - 1], 2.0f);
                    break;
                }
                case 2: {
                    WeldJointDef joint = WeldJointDef::atWorldAnchor(left, body, middle);
                    if (k % 5 == 0) joint.angularSpring = {true, 4.0f, 0.3f};
                    add(joint);
                    break;
                }
                case 3: {
                    PulleyJointDef joint;
                    joint.bodyA = left;
                    joint.bodyB = body;
                    joint.groundAnchorA = {float(col) - 1.0f, 3.0f - float(row)};
                    joint.groundAnchorB = {float(col), 3.0f - float(row)};
                    add(joint);
                    break;
                }
                case 4: {
                    FrictionJointDef joint;
                    joint.bodyA = left;
                    joint.bodyB = body;
                    joint.maxForce = 5.0f;
                    joint.maxTorque = 1.0f;
                    add(joint);
                    break;
                }
                case 5: {
                    MotorJointDef joint;
                    joint.bodyA = left;
                    joint.bodyB = body;
                    joint.maxForce = 20.0f;
                    add(joint);
                    break;
                }
                case 6: {
                    WheelJointDef joint =
                        WheelJointDef::atWorldAnchor(left, body, middle, {0.0f, 1.0f});
                    joint.spring = {true, 4.0f, 0.7f};
                    if (k % 3 == 0) joint.limit = {true, -0.1f, 0.1f};
                    add(joint);
                    break;
                }
                default: link(left, middle);
            }
        }
    }
}

// Boxes on the plane y = 0 (a static ground unless the caller provides its own floor).
void buildPyramid(World& world, int rows, bool withGround = true) {
    if (withGround) {
        BodyId ground = world.createBody(BodyDef{});
        ShapeDef groundShape;
        groundShape.density = 0.0f;
        world.createShape(ground, groundShape,
                          Polygon::box(rows + 10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    }
    ShapeDef box;
    box.friction = 0.6f;
    for (int row = 0; row < rows; ++row) {
        const int count = rows - row;
        for (int i = 0; i < count; ++i) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {-0.55f * float(count - 1) + 1.1f * float(i), 0.5f + 1.0f * row};
            world.createShape(world.createBody(def), box, Polygon::box(0.5f, 0.5f));
        }
    }
}

std::uint64_t gridHash(int workers, bool mixed, int steps, bool everyType = false) {
    WorldDef def = oneSubstepDef();
    def.workerCount = workers;
    def.enableSleep = false;
    JointGrid grid{World(def), {}};
    buildGrid(grid, 30, mixed, everyType);
    for (int i = 0; i < steps; ++i) grid.world.step(kDt);
    return grid.world.stateHash();
}

std::uint64_t pyramidHash(int workers, ContactCorrection correction, int steps, int substeps = 1) {
    WorldDef def = oneSubstepDef();
    def.workerCount = workers;
    def.contactCorrection = correction;
    def.substepCount = substeps;
    World world(def);
    buildPyramid(world, 40);  // 820 boxes, about 2,400 contacts: one coloured island
    for (int i = 0; i < steps; ++i) world.step(kDt);
    return world.stateHash();
}

}  // namespace

namespace {

// Runs `stages` stages of `items` items on a team of the pool's workers; member 1 first waits
// for `arrive` when given. Returns how many times each item was done, and counts the blocks
// member 1 did.
std::vector<int> runStages(TaskPool& pool, int stages, int items, std::atomic<bool>* arrive,
                           int& lateBlocks) {
    std::vector<int> done(static_cast<std::size_t>(items), 0);
    std::atomic<int> late{0};
    std::atomic<bool> leaderFinished{false};
    pool.region([&](int member) {
        const Team team(pool, member);
        if (member == 1 && arrive) {
            while (!arrive->load()) std::this_thread::yield();
        }
        for (int s = 0; s < stages; ++s) {
            team.forBlocks(items, [&](IndexRange r) {
                for (int i = r.begin; i < r.end; ++i) ++done[static_cast<std::size_t>(i)];
                if (member == 1) ++late;
            });
            team.sync();
        }
        if (member == 0) leaderFinished = true;
        if (member == 0 && arrive) arrive->store(true);
    });
    lateBlocks = late.load();
    EXPECT_TRUE(leaderFinished.load());
    return done;
}

}  // namespace

TEST(TeamSolver, EveryBlockOfEveryStageIsDoneOnce) {
    TaskPool pool(2);
    int lateBlocks = 0;
    const std::vector<int> done = runStages(pool, 500, 1000, nullptr, lateBlocks);
    EXPECT_EQ(std::count(done.begin(), done.end(), 500), 1000);
}

TEST(TeamSolver, AMemberThatHasNotArrivedHoldsNobodyUp) {
    // Member 1 arrives only once the leader has run every stage (as a worker without a core
    // would): members that waited for each other at each stage would never finish. The
    // leader does every block; member 1 then finds its stages done.
    TaskPool pool(2);
    std::atomic<bool> arrive{false};
    int lateBlocks = -1;
    const std::vector<int> done = runStages(pool, 300, 1000, &arrive, lateBlocks);
    EXPECT_EQ(std::count(done.begin(), done.end(), 300), 1000);
    EXPECT_EQ(lateBlocks, 0);
}

TEST(StageBoard, EachMemberClaimsItsOwnStretchFirstThenWhatTheOthersLeft) {
    // Two members, eight blocks: member 0's stretch is blocks 0 to 3, member 1's 4 to 7. Claims
    // made one after the other, as two members might make them.
    StageBoard board;
    board.reset(2);
    ASSERT_TRUE(board.enter(1));
    EXPECT_EQ(board.claim(1, 8, 0, 2), 0);
    EXPECT_EQ(board.claim(1, 8, 1, 2), 4);
    EXPECT_EQ(board.claim(1, 8, 1, 2), 5);
    EXPECT_EQ(board.claim(1, 8, 1, 2), 6);
    EXPECT_EQ(board.claim(1, 8, 1, 2), 7);
    // Member 1's stretch is done: it takes member 0's next block, and member 0 the one after.
    EXPECT_EQ(board.claim(1, 8, 1, 2), 1);
    EXPECT_EQ(board.claim(1, 8, 0, 2), 2);
    EXPECT_EQ(board.claim(1, 8, 0, 2), 3);
    EXPECT_EQ(board.claim(1, 8, 0, 2), -1);
    EXPECT_EQ(board.claim(1, 8, 1, 2), -1);
    for (int b = 0; b < 7; ++b) board.finish(1);
    EXPECT_FALSE(board.finished(1, 8));
    board.finish(1);
    EXPECT_TRUE(board.finished(1, 8));
}

TEST(StageBoard, EveryBlockIsClaimedOnceWhateverTheTeamAndBlockCounts) {
    // More members than segments share them; fewer blocks than members leave some without.
    for (int members : {1, 2, 3, 5, StageBoard::kMaxSegments + 3}) {
        for (int blocks : {1, 2, 3, 7, 8, 64, 1000}) {
            StageBoard board;
            board.reset(members);
            ASSERT_TRUE(board.enter(7));
            std::vector<int> claimed(static_cast<std::size_t>(blocks), 0);
            // Members take turns, each claiming until it finds nothing left.
            std::vector<bool> out(static_cast<std::size_t>(members), false);
            int left = members;
            for (int turn = 0; left > 0; ++turn) {
                const int member = turn % members;
                if (out[static_cast<std::size_t>(member)]) continue;
                const int b = board.claim(7, blocks, member, members);
                if (b < 0) {
                    out[static_cast<std::size_t>(member)] = true;
                    --left;
                    continue;
                }
                ASSERT_LT(b, blocks);
                ++claimed[static_cast<std::size_t>(b)];
                board.finish(7);
            }
            EXPECT_EQ(std::count(claimed.begin(), claimed.end(), 1), blocks)
                << members << " members, " << blocks << " blocks";
            EXPECT_TRUE(board.finished(7, blocks));
        }
    }
}

TEST(StageBoard, AStageWhoseSlotWasReusedIsFinishedLongAgo) {
    // A member that comes back after the others have run kSlots stages on finds its stage's
    // slot holding a later one: nothing to claim, nothing to wait for. Member 0 does all of
    // stage 3 (its own segment, then member 1's), and later takes the same slot for stage 3 +
    // kSlots.
    StageBoard board;
    board.reset(2);
    ASSERT_TRUE(board.enter(3));
    for (int b = 0; b < 4; ++b) {
        EXPECT_EQ(board.claim(3, 4, 0, 2), b);
        board.finish(3);
    }
    EXPECT_EQ(board.claim(3, 4, 0, 2), -1);
    const std::uint32_t later = 3 + StageBoard::kSlots;
    ASSERT_TRUE(board.enter(later));
    EXPECT_EQ(board.claim(later, 4, 0, 2), 0);
    EXPECT_FALSE(board.enter(3));
    EXPECT_EQ(board.claim(3, 4, 1, 2), -1);
    EXPECT_TRUE(board.finished(3, 4));
    EXPECT_FALSE(board.finished(later, 4));
}

TEST(TaskPool, EveryIndexIsDoneOnceWhateverTheWorkersAndTheChunks) {
    // Each worker takes its own stretch of chunks first, then the others' leftovers: every
    // index must still be done exactly once, whoever comes and whenever.
    for (int workers : {1, 2, 3, 5}) {
        TaskPool pool(workers);
        for (int count : {1, 7, 100, 1001, 4096}) {
            for (int minChunk : {1, 16, 256}) {
                std::vector<std::atomic<int>> done(static_cast<std::size_t>(count));
                for (int round = 0; round < 20; ++round) {
                    pool.parallelFor(count, minChunk, [&](int begin, int end, int worker) {
                        EXPECT_LT(worker, workers);
                        for (int i = begin; i < end; ++i) ++done[static_cast<std::size_t>(i)];
                    });
                }
                int wrong = 0;
                for (const std::atomic<int>& d : done) wrong += d.load() != 20;
                EXPECT_EQ(wrong, 0)
                    << workers << " workers, " << count << " items, chunks of " << minChunk;
            }
        }
    }
}

TEST(TeamSolver, AnIndependentBatchIsCutWhereTheContactTilesStart) {
    // The wide contact sweeps find their tiles at multiples of kBatchAlignment from a batch's
    // start (constraints/contact_tiles.h): every block must start there, on any team size,
    // and the blocks must cover the batch once.
    for (int workers : {1, 2, 3}) {
        for (int size : {7, 100, 1000, 4099}) {
            TaskPool pool(workers);
            const Batch batch{13, 13 + size, false};
            std::vector<std::atomic<int>> done(static_cast<std::size_t>(batch.end));
            std::atomic<int> misaligned{0};
            pool.region([&](int member) {
                const Team team(pool, member);
                team.forBlocks(batch, [&](IndexRange r) {
                    if ((r.begin - batch.begin) % kBatchAlignment != 0) ++misaligned;
                    for (int i = r.begin; i < r.end; ++i) ++done[static_cast<std::size_t>(i)];
                });
                team.sync();
            });
            EXPECT_EQ(misaligned.load(), 0) << workers << " workers, " << size;
            for (int i = 0; i < batch.end; ++i) {
                EXPECT_EQ(done[static_cast<std::size_t>(i)].load(), i < batch.begin ? 0 : 1)
                    << workers << " workers, " << size << ", item " << i;
            }
        }
    }
}

TEST(TeamSolver, BatchSharesCoverEveryConstraintOnceWhereTheTilesStart) {
    // forBatchShares cuts each batch into members' shares (serial ones too) at multiples of
    // kBatchAlignment from the batch's start, on any team size, covering every constraint once.
    const std::vector<Batch> batches{{0, 1000, false},
                                     {1000, 1007, false},
                                     {1007, 1100, false},
                                     {1100, 3333, false},
                                     {3333, 3400, true}};
    for (int workers : {1, 2, 3}) {
        TaskPool pool(workers);
        std::vector<std::atomic<int>> done(static_cast<std::size_t>(batches.back().end));
        std::atomic<int> misaligned{0};
        pool.region([&](int member) {
            const Team team(pool, member);
            team.forBatchShares(batches, [&](IndexRange r) {
                const bool atTile =
                    std::any_of(batches.begin(), batches.end(), [&](const Batch& b) {
                        return r.begin >= b.begin && r.end <= b.end &&
                               (r.begin - b.begin) % kBatchAlignment == 0;
                    });
                if (!atTile && workers > 1) ++misaligned;
                for (int i = r.begin; i < r.end; ++i) ++done[static_cast<std::size_t>(i)];
            });
            team.sync();
        });
        EXPECT_EQ(misaligned.load(), 0) << workers << " workers";
        int wrong = 0;
        for (const std::atomic<int>& d : done) wrong += d.load() != 1;
        EXPECT_EQ(wrong, 0) << workers << " workers";
    }
}

TEST(TeamSolver, BigIslandsAreColoured) {
    // The scenes below must really exercise the coloured path.
    JointGrid grid{World(oneSubstepDef()), {}};
    buildGrid(grid, 30, false);
    EXPECT_GE(int(grid.joints.size()), kColoringThreshold);
    grid.world.step(kDt);
    EXPECT_EQ(grid.world.lastStepStats().islandCount, 1);
}

TEST(TeamSolver, AJointGridStepsToTheSameBitsOnAnyNumberOfWorkers) {
    for (bool mixed : {false, true}) {
        const std::uint64_t one = gridHash(1, mixed, 120);
        EXPECT_EQ(gridHash(2, mixed, 120), one) << "mixed " << mixed;
        EXPECT_EQ(gridHash(3, mixed, 120), one) << "mixed " << mixed;
    }
}

TEST(TeamSolver, AGridOfEveryJointTypeStepsToTheSameBitsOnAnyNumberOfWorkers) {
    // Every joint type with every strategy in one coloured island.
    JointGrid grid{World(oneSubstepDef()), {}};
    buildGrid(grid, 30, true, true);
    grid.world.step(kDt);
    ASSERT_EQ(grid.world.lastStepStats().islandCount, 1);
    ASSERT_GE(grid.world.lastStepStats().jointCount, kColoringThreshold);
    const std::uint64_t one = gridHash(1, true, 120, true);
    EXPECT_EQ(gridHash(2, true, 120, true), one);
    EXPECT_EQ(gridHash(3, true, 120, true), one);
    EXPECT_EQ(gridHash(4, true, 120, true), one);
}

TEST(TeamSolver, APyramidStepsToTheSameBitsOnAnyNumberOfWorkers) {
    for (ContactCorrection correction : {ContactCorrection::NGS, ContactCorrection::Baumgarte}) {
        const std::uint64_t one = pyramidHash(1, correction, 120);
        EXPECT_EQ(pyramidHash(2, correction, 120), one);
        EXPECT_EQ(pyramidHash(4, correction, 120), one);
    }
    // Soft contacts with substeps: built at the first, re-measured from the bodies' motion at
    // the others.
    const std::uint64_t one = pyramidHash(1, ContactCorrection::Soft, 120, 4);
    EXPECT_EQ(pyramidHash(2, ContactCorrection::Soft, 120, 4), one);
    EXPECT_EQ(pyramidHash(4, ContactCorrection::Soft, 120, 4), one);
}

TEST(TeamSolver, AKinematicCarrierUnderABigPileMovesExactlyAsAlone) {
    // Every contact with the carrier gets its own copy of it; the copies must all agree with
    // the body itself, which moves at its set velocity whatever rests on it.
    const auto carrier = [](World& world) {
        BodyDef def;
        def.type = BodyType::Kinematic;
        def.position = {0.0f, -0.5f};
        def.linearVelocity = {0.5f, 0.0f};
        BodyId body = world.createBody(def);
        world.createShape(body, ShapeDef{}, Polygon::box(40.0f, 0.5f));
        return body;
    };
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    World loaded(def);
    BodyId carried = carrier(loaded);
    buildPyramid(loaded, 40, false);
    World alone(def);
    BodyId lone = carrier(alone);
    for (int i = 0; i < 60; ++i) {
        loaded.step(kDt);
        alone.step(kDt);
    }
    EXPECT_GE(loaded.lastStepStats().touchingCount, kColoringThreshold);
    EXPECT_EQ(loaded.bodyPosition(carried).x, alone.bodyPosition(lone).x);
    EXPECT_EQ(loaded.bodyPosition(carried).y, alone.bodyPosition(lone).y);
    EXPECT_EQ(loaded.bodyLinearVelocity(carried).x, 0.5f);
}
