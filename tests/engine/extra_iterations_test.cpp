// Per-joint extra position iterations (extraPositionIterations on the defs, World::
// setJointExtraPositionIterations): sweeps over only the NGS joints that ask for more, after the
// island's shared ones. They hold the asking joints tighter, cost only their solves, and give the
// same bits on any worker count (the extra sweeps run on one thread, in solving order).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/parts.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A rope of 20 planks released level holding a ball of 20 links' mass; the 5 joints nearest the
// ball ask for `extra` sweeps more. Returns the largest separation of those 5 over 5 s, and the
// extra solves the steps reported.
struct RopeRun {
    float nearLoad = 0.0f;
    long extraSolves = 0;
};
RopeRun rope(int extra, int positionIterations) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef link;
    link.density = 20.0f;
    ShapeDef load;
    load.density = 100.0f / (kPi * 0.25f);
    std::vector<JointId> nearLoad;
    BodyId previous = ground;
    for (int i = 0; i <= 20; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        const Vec2 anchor{static_cast<float>(i), 20.0f};
        def.position = anchor + Vec2{0.5f, 0.0f};
        const BodyId body = world.createBody(def);
        if (i < 20) {
            world.createShape(body, link, Polygon::box(0.5f, 0.125f));
        } else {
            world.createShape(body, load, Circle{{0.0f, 0.0f}, 0.5f});
        }
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(previous, body, anchor);
        if (i > 15) jd.extraPositionIterations = extra;
        const JointId joint = world.createJoint(jd);
        if (i > 15) nearLoad.push_back(joint);
        previous = body;
    }
    RopeRun run;
    for (int s = 0; s < 300; ++s) {
        world.step(kDt, 8, positionIterations);
        run.extraSolves += world.lastStepStats().extraPositionSolves;
        for (JointId j : nearLoad) run.nearLoad = std::max(run.nearLoad, world.jointSeparation(j));
    }
    return run;
}

}  // namespace

TEST(ExtraPositionIterations, HoldTheAskingJointsTighterForOnlyTheirSolves) {
    const RopeRun shared = rope(0, 1);
    const RopeRun extra = rope(6, 1);
    EXPECT_EQ(shared.extraSolves, 0);
    EXPECT_GT(extra.extraSolves, 0);
    // At most 5 joints x 6 sweeps a step.
    EXPECT_LE(extra.extraSolves, 5L * 6L * 300L);
    EXPECT_LT(extra.nearLoad, 0.5f * shared.nearLoad)
        << "extra " << extra.nearLoad << " m, shared only " << shared.nearLoad << " m";
}

TEST(ExtraPositionIterations, AreCheckedAndReadBack) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {1.0f, 0.0f};
    const BodyId ball = world.createBody(def);
    world.createShape(ball, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.25f});
    RevoluteJointDef pin = RevoluteJointDef::atWorldAnchor(ground, ball, {0.0f, 0.0f});
    const std::uint64_t empty = world.stateHash();
    pin.extraPositionIterations = -1;
    EXPECT_THROW(world.createJoint(pin), Error);
    pin.extraPositionIterations = kMaxIterations + 1;
    EXPECT_THROW(world.createJoint(pin), Error);
    EXPECT_EQ(world.stateHash(), empty);
    pin.extraPositionIterations = 4;
    const JointId joint = world.createJoint(pin);
    EXPECT_EQ(world.jointExtraPositionIterations(joint), 4);
    world.setJointExtraPositionIterations(joint, 2);
    EXPECT_EQ(world.jointExtraPositionIterations(joint), 2);
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(world.setJointExtraPositionIterations(joint, -3), Error);
    EXPECT_EQ(world.stateHash(), before);
    // A velocity-only joint has no position phase to repeat.
    MotorJointDef motor;
    motor.bodyA = ground;
    motor.bodyB = ball;
    const JointId drive = world.createJoint(motor);
    EXPECT_THROW(world.setJointExtraPositionIterations(drive, 1), Error);
    // The count travels with a snapshot.
    const std::vector<std::uint8_t> saved = world.snapshot();
    world.setJointExtraPositionIterations(joint, 5);
    world.restore(saved);
    EXPECT_EQ(world.jointExtraPositionIterations(joint), 2);
}

// A grid of 1,740 joints is one coloured island, solved by every worker together; the extra
// sweeps of half its joints run on one of them, in solving order: the same bits on 1 and 2.
TEST(ExtraPositionIterations, StepToTheSameBitsOnAnyWorkerCount) {
    std::vector<std::uint64_t> hashes;
    for (int workers : {1, 2}) {
        WorldDef def = oneSubstepDef();
        def.workerCount = workers;
        def.adaptWorkerCount = false;
        World world(def);
        scenes::JointGridSpec spec;
        spec.size = 30;
        spec.pinnedHalfWidth = 1;
        const std::vector<JointId> joints = scenes::addJointGrid(world, spec).joints;
        for (std::size_t k = 0; k < joints.size(); k += 2) {
            world.setJointExtraPositionIterations(joints[k], 3);
        }
        long extra = 0;
        for (int i = 0; i < 60; ++i) {
            world.step(kDt, 4, 1);
            extra += world.lastStepStats().extraPositionSolves;
        }
        EXPECT_GT(extra, 0) << workers << " workers";
        hashes.push_back(world.stateHash());
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}
