// The wide contact sweeps (four lanes, eight with AVX2), velocity, relax and NGS position
// (src/constraints/contact_solver_wide.cpp), against the same sweeps one contact at a time: a
// coloured island must step to the same bits either way, with every kind of contact the wide
// path meets (two-point boxes solved as blocks, one-point discs, capsules, circle pairs, faces of
// A and of B, friction, restitution) and every contact correction (NGS, Baumgarte, soft with
// relax sweeps), on one worker and on two; and small islands whose contacts alone are coloured.
#include <gtest/gtest.h>

#include <memory>

#include "constraints/contact_solver.h"
#include "islands/island_schedule.h"
#include "pivot/pivot.h"
#include "scoped_switch.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A world with sleep off and a ground `halfWidth` m either side of the origin.
std::unique_ptr<World> grounded(ContactCorrection correction, int substeps, int workers,
                                float halfWidth) {
    WorldDef def = oneSubstepDef();
    def.contactCorrection = correction;
    def.substepCount = substeps;
    def.workerCount = workers;
    def.enableSleep = false;
    auto world = std::make_unique<World>(def);
    ShapeDef ground;
    ground.density = 0.0f;
    world->createShape(world->createBody(BodyDef{}), ground,
                       Polygon::box(halfWidth, 0.5f, {0.0f, -0.5f}, 0.0f));
    return world;
}

// A pyramid of unit boxes with `rows` rows on the ground, its lowest row starting at x = left.
void addPyramid(World& world, int rows, float left, const ShapeDef& solid) {
    const float pitch = 1.0f + 2.0f * kPolygonRadius - kLinearSlop;
    for (int row = 0; row < rows; ++row) {
        for (int i = 0; i < rows - row; ++i) {
            BodyDef body;
            body.type = BodyType::Dynamic;
            body.position = {left + pitch * (0.5f * static_cast<float>(row) + i),
                             0.5f + pitch * static_cast<float>(row) + 0.01f};
            world.createShape(world.createBody(body), solid, Polygon::box(0.5f, 0.5f));
        }
    }
}

// A pile big enough to be one coloured island (well over 1024 contacts): a pyramid of boxes,
// and discs and capsules (some bouncy) dropped beside and onto it.
std::unique_ptr<World> pile(ContactCorrection correction, int substeps, int workers) {
    auto world = grounded(correction, substeps, workers, 50.0f);
    ShapeDef solid;
    solid.friction = 0.6f;
    addPyramid(*world, 50, -25.0f, solid);
    ShapeDef bouncy = solid;
    bouncy.restitution = 0.5f;
    for (int i = 0; i < 300; ++i) {
        BodyDef body;
        body.type = BodyType::Dynamic;
        body.position = {-40.0f + 0.23f * static_cast<float>(i % 260), 2.0f + 0.9f * (i / 20)};
        body.angularVelocity = 0.1f * static_cast<float>(i % 7);
        const BodyId id = world->createBody(body);
        if (i % 3 == 0) {
            world->createShape(id, bouncy, Circle{{0.0f, 0.0f}, 0.3f});
        } else if (i % 3 == 1) {
            world->createShape(id, solid, Capsule{{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.2f});
        } else {
            world->createShape(id, bouncy, Polygon::box(0.3f, 0.2f));
        }
    }
    return world;
}

// Four pyramids of 78 boxes apart on one ground: four islands too small to be shared by a team
// (under kColoringThreshold constraints) but with their contacts coloured (over
// kWideContactThreshold), each solved by one worker a colour at a time.
std::unique_ptr<World> smallPiles(ContactCorrection correction, int substeps, int workers) {
    auto world = grounded(correction, substeps, workers, 80.0f);
    ShapeDef solid;
    solid.friction = 0.6f;
    for (int pile = 0; pile < 4; ++pile) {
        addPyramid(*world, 12, -60.0f + 30.0f * static_cast<float>(pile), solid);
    }
    return world;
}

using WideSolving = ScopedSwitch<&ContactSolver::setWideSolving>;

using Build = std::unique_ptr<World> (*)(ContactCorrection, int, int);

void expectSameBits(ContactCorrection correction, int substeps, int velocity, int position,
                    Build build = pile) {
    const bool big = build == pile;
    for (int workers : {1, 2}) {
        auto wide = build(correction, substeps, workers);
        auto single = build(correction, substeps, workers);
        int colouredSteps = 0;
        for (int step = 0; step < 150; ++step) {
            {
                WideSolving on(true);
                wide->step(kDt, velocity, position);
            }
            {
                WideSolving off(false);
                single->step(kDt, velocity, position);
            }
            ASSERT_EQ(wide->stateHash(), single->stateHash())
                << "step " << step << ", workers " << workers;
            const StepStats& stats = wide->lastStepStats();
            const bool coloured =
                big ? stats.touchingCount >= kColoringThreshold
                    : stats.islandCount == 4 && stats.touchingCount >= 4 * kWideContactThreshold;
            colouredSteps += coloured ? 1 : 0;
        }
        // The pile must have been one big island for most of the run (Baumgarte keeps the
        // fewest points touching), or little of the wide path was tested.
        EXPECT_GE(colouredSteps, 60) << "workers " << workers;
    }
}

}  // namespace

TEST(WideContacts, NgsContactsStepToTheSameBitsAsOneByOne) {
    expectSameBits(ContactCorrection::NGS, 1, 8, 3);
}

TEST(WideContacts, BaumgarteContactsStepToTheSameBitsAsOneByOne) {
    expectSameBits(ContactCorrection::Baumgarte, 1, 8, 3);
}

TEST(WideContacts, SoftContactsAndRelaxSweepsStepToTheSameBitsAsOneByOne) {
    expectSameBits(ContactCorrection::Soft, 4, 1, 1);
}

TEST(WideContacts, SmallIslandsWithManyContactsStepToTheSameBitsAsOneByOne) {
    expectSameBits(ContactCorrection::NGS, 1, 8, 3, smallPiles);
    expectSameBits(ContactCorrection::Soft, 4, 1, 1, smallPiles);
}
