// When the engine lets go of a joint, and what the user sees and can do about it: by default a
// joint is never let go for how far apart it is (as in Box2D); letting go beyond a distance is
// opt-in per world and per joint, reported in an event list, and undone by rearmJoint. A joint
// whose reactions stop being finite is always let go (the containment that keeps NaN out).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "all_solvers.h"
#include "joints/joint.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;
constexpr const auto& kSolvers = test_support::kAllSolvers;

// A chain of three boxes hanging from the ground at (0, 10); the last box is then teleported
// 50 m away, tearing its joint open.
struct TornChain {
    World world{oneSubstepDef()};
    std::vector<BodyId> boxes;
    std::vector<JointId> joints;

    TornChain(const WorldDef& def, PositionSolver solver, std::optional<float> letGo = {})
        : world(def) {
        BodyId previous = world.createBody(BodyDef{});
        for (int i = 0; i < 3; ++i) {
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.position = {float(i) + 0.5f, 10.0f};
            BodyId box = world.createBody(bd);
            world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.1f));
            RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(previous, box, {float(i), 10.0f});
            jd.positionSolver = solver;
            jd.letGoSeparation = letGo;
            joints.push_back(world.createJoint(jd));
            boxes.push_back(box);
            previous = box;
        }
        world.step(kDt);
        world.setBodyTransform(boxes[2], {52.5f, 10.0f}, 0.0f);
        world.setBodyLinearVelocity(boxes[2], {0.0f, 0.0f});
    }
};

WorldDef letGoBeyond(float separation) {
    WorldDef def = oneSubstepDef();
    def.jointLetGoSeparation = separation;
    return def;
}

}  // namespace

TEST(JointLetGo, ByDefaultAJointIsNeverLetGoHoweverFarApart) {
    for (PositionSolver solver : kSolvers) {
        TornChain chain(oneSubstepDef(), solver);
        const float torn = chain.world.jointSeparation(chain.joints[2]);
        ASSERT_GT(torn, 40.0f);
        for (int i = 0; i < 120; ++i) {
            chain.world.step(kDt);
            ASSERT_EQ(chain.world.lastStepStats().letGoJointCount, 0);
            ASSERT_TRUE(chain.world.jointLetGoEvents().empty());
        }
        EXPECT_FALSE(chain.world.isJointLetGo(chain.joints[2])) << positionSolverName(solver);
        EXPECT_EQ(chain.world.jointLetGoSeparation(chain.joints[2]), 0.0f);
        // Still solved: the joint has pulled the box back towards the chain.
        EXPECT_LT(chain.world.jointSeparation(chain.joints[2]), 0.5f * torn)
            << positionSolverName(solver);
    }
}

TEST(JointLetGo, BeyondTheWorldsSeparationAJointIsLetGoAndReported) {
    for (PositionSolver solver : kSolvers) {
        TornChain chain(letGoBeyond(10.0f), solver);
        World& world = chain.world;
        world.step(kDt);
        ASSERT_EQ(world.lastStepStats().letGoJointCount, 1) << positionSolverName(solver);
        const std::vector<JointLetGoEvent> events = world.jointLetGoEvents();
        ASSERT_EQ(events.size(), 1u);
        EXPECT_EQ(events[0].joint, chain.joints[2]);
        EXPECT_EQ(events[0].reason, JointLetGoReason::Separation);
        EXPECT_NEAR(events[0].separation, 50.0f, 1.0f);
        EXPECT_TRUE(world.isJointLetGo(chain.joints[2]));
        EXPECT_FALSE(world.isJointLetGo(chain.joints[0]));
        EXPECT_FALSE(world.isJointLetGo(chain.joints[1]));
        EXPECT_EQ(world.jointReactionForce(chain.joints[2]), (Vec2{0.0f, 0.0f}));
        for (int i = 0; i < 59; ++i) world.step(kDt);
        EXPECT_TRUE(world.jointLetGoEvents().empty());  // cleared by the next step
        // Free fall since the teleport: nothing pulled the box sideways.
        EXPECT_NEAR(world.bodyPosition(chain.boxes[2]).x, 52.5f, 1e-4f);
        EXPECT_LT(world.bodyPosition(chain.boxes[2]).y, 10.0f - 4.0f);
        EXPECT_LT(world.jointSeparation(chain.joints[1]), 0.05f);
        EXPECT_TRUE(world.isJointLetGo(chain.joints[2]));
    }
}

TEST(JointLetGo, AJointsOwnSettingOverridesTheWorlds) {
    // The world lets go beyond 10 m, this joint never.
    TornChain never(letGoBeyond(10.0f), PositionSolver::FullNGS);
    never.world.setJointLetGoSeparation(never.joints[2], 0.0f);
    never.world.step(kDt);
    EXPECT_FALSE(never.world.isJointLetGo(never.joints[2]));
    EXPECT_EQ(never.world.jointLetGoSeparation(never.joints[2]), 0.0f);
    EXPECT_EQ(never.world.jointLetGoSeparation(never.joints[1]), 10.0f);
    // The world never lets go, this joint beyond 20 m.
    TornChain beyond(oneSubstepDef(), PositionSolver::FullNGS, 20.0f);
    beyond.world.step(kDt);
    EXPECT_TRUE(beyond.world.isJointLetGo(beyond.joints[2]));
    // Back to the world's setting, and a new distance, between steps.
    beyond.world.setJointLetGoSeparation(beyond.joints[1], 1e-3f);
    beyond.world.setJointLetGoSeparation(beyond.joints[2], std::nullopt);
    EXPECT_EQ(beyond.world.jointLetGoSeparation(beyond.joints[2]), 0.0f);
    EXPECT_EQ(beyond.world.jointLetGoSeparation(beyond.joints[1]), 1e-3f);
}

TEST(JointLetGo, ARearmedJointIsSolvedAgain) {
    TornChain chain(letGoBeyond(10.0f), PositionSolver::FullNGS);
    World& world = chain.world;
    world.step(kDt);
    ASSERT_TRUE(world.isJointLetGo(chain.joints[2]));
    // Rearmed while still 50 m apart: let go again at the next step, and reported again.
    world.rearmJoint(chain.joints[2]);
    EXPECT_FALSE(world.isJointLetGo(chain.joints[2]));
    world.step(kDt);
    EXPECT_TRUE(world.isJointLetGo(chain.joints[2]));
    EXPECT_EQ(world.jointLetGoEvents().size(), 1u);
    // Brought back to its anchor first: it holds again.
    const Vec2 anchor = world.jointAnchorA(chain.joints[2]);
    world.setBodyTransform(chain.boxes[2], anchor + Vec2{0.5f, 0.0f}, 0.0f);
    world.rearmJoint(chain.joints[2]);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_FALSE(world.isJointLetGo(chain.joints[2]));
    EXPECT_LT(world.jointSeparation(chain.joints[2]), 0.05f);
    // Rearming a joint that holds changes nothing.
    const std::uint64_t before = world.stateHash();
    world.rearmJoint(chain.joints[0]);
    EXPECT_EQ(world.stateHash(), before);
}

TEST(JointLetGo, SettingsAreValidatedAndARefusedCallChangesNothing) {
    WorldDef def = oneSubstepDef();
    def.jointLetGoSeparation = -1.0f;
    EXPECT_THROW(World{def}, Error);
    def.jointLetGoSeparation = std::nanf("");
    EXPECT_THROW(World{def}, Error);
    TornChain chain(oneSubstepDef(), PositionSolver::FullNGS);
    World& world = chain.world;
    const std::uint64_t before = world.stateHash();
    for (float bad : {-0.5f, std::nanf(""), INFINITY, 2.0f * kMaxMagnitude, 1e-40f}) {
        EXPECT_THROW(world.setJointLetGoSeparation(chain.joints[0], bad), Error) << bad;
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(chain.boxes[0], chain.boxes[2], {});
        jd.letGoSeparation = bad;
        EXPECT_THROW(world.createJoint(jd), Error) << bad;
    }
    EXPECT_EQ(world.stateHash(), before);
}

// The events list every joint a step let go, in the order the step reached them, the same on
// any number of workers.
TEST(JointLetGo, EventsAreTheSameOnAnyNumberOfWorkers) {
    std::vector<std::vector<std::int32_t>> orders;
    for (int workers : {1, 2, 3}) {
        WorldDef def = letGoBeyond(2.0f);
        def.workerCount = workers;
        World world(def);
        std::vector<BodyId> bodies;
        // Enough bodies for the islands to be shared out among the workers.
        for (int i = 0; i < 600; ++i) {
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.position = {3.0f * float(i), 0.0f};
            bodies.push_back(world.createBody(bd));
            world.createShape(bodies.back(), ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
        }
        // Pairs of bodies 3 m apart, jointed midway, except one pair in three whose anchors
        // are at the centres: 3 m apart, beyond the 2 m.
        for (int i = 0; i + 1 < 600; i += 2) {
            RevoluteJointDef jd;
            jd.bodyA = bodies[i];
            jd.bodyB = bodies[i + 1];
            const bool torn = i % 3 == 0;
            jd.localAnchorA = {torn ? 0.0f : 1.5f, 0.0f};
            jd.localAnchorB = {torn ? 0.0f : -1.5f, 0.0f};
            world.createJoint(jd);
        }
        world.step(kDt);
        std::vector<std::int32_t> order;
        for (const JointLetGoEvent& e : world.jointLetGoEvents()) order.push_back(e.joint.index);
        EXPECT_EQ(static_cast<int>(order.size()), world.lastStepStats().letGoJointCount);
        orders.push_back(order);
    }
    EXPECT_EQ(orders[0].size(), 100u);
    EXPECT_EQ(orders[0], orders[1]);
    EXPECT_EQ(orders[0], orders[2]);
}

// A stored impulse that is finite but stands for an infinite force (1e37 N s over a 1/60 s step)
// must not reach jointReactionForce: the step lets such a joint go as non-finite.
TEST(JointLetGo, AReactionThatWouldOverflowIsNotFinite) {
    Joint joint;
    RevoluteJoint& revolute = std::get<RevoluteJoint>(joint.data);
    joint.impulseInvDt = 60.0f;
    revolute.impulse = {1e37f, 0.0f};
    EXPECT_FALSE(joint.hasFiniteReactionsAs<RevoluteJoint>());
    revolute.impulse = {1e30f, 0.0f};
    EXPECT_TRUE(joint.hasFiniteReactionsAs<RevoluteJoint>());
    revolute.motorImpulse = 3e36f;
    revolute.lowerImpulse = 3e36f;  // each times 60 is finite, their sum is not
    EXPECT_TRUE(std::isfinite(60.0f * revolute.motorImpulse));
    EXPECT_FALSE(joint.hasFiniteReactionsAs<RevoluteJoint>());
    joint.letGoFor(JointLetGoReason::NonFinite, 1.0f);
    EXPECT_TRUE(joint.hasFiniteReactionsAs<RevoluteJoint>());
    EXPECT_TRUE(joint.letGo);
}

// The world the fuzz driver found diverging under Baumgarte (tests/fuzz/findings/
// baumgarte_falling_chain.journal): what the engine gives up on is named, not only counted.
TEST(Containment, TheJointsLetGoAndTheBodiesDiscardedAreNamed) {
    WorldDef def = oneSubstepDef();
    def.defaultPositionSolver = PositionSolver::Baumgarte;
    def.enableSleep = false;
    World world(def);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {-2.0f, -15.0f};
    BodyId a = world.createBody(bd);
    world.createShape(a, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.3f});
    bd.position = {2.2f, -6.0f};
    BodyId b = world.createBody(bd);
    world.createShape(b, ShapeDef{},
                      Polygon::fromPoints({{-0.47f, -0.96f}, {-0.32f, -0.71f}, {-0.59f, -0.37f}}));
    bd.position = {0.2f, -6.0f};
    BodyId c = world.createBody(bd);
    world.createShape(c, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.3f});
    world.createJoint(RevoluteJointDef::atWorldAnchor(a, b, {-2.0f, -15.0f}));
    world.createJoint(RevoluteJointDef::atWorldAnchor(b, c, {0.2f, -6.0f}));
    int discarded = 0, letGo = 0;
    for (int i = 0; i < 600; ++i) {
        world.step(kDt);
        const std::vector<BodyId> bodies = world.discardedBodies();
        ASSERT_EQ(static_cast<int>(bodies.size()), world.lastStepStats().discardedBodyCount);
        for (BodyId body : bodies) EXPECT_TRUE(body == a || body == b || body == c);
        const std::vector<JointLetGoEvent> joints = world.jointLetGoEvents();
        ASSERT_EQ(static_cast<int>(joints.size()), world.lastStepStats().letGoJointCount);
        for (const JointLetGoEvent& e : joints) EXPECT_EQ(e.reason, JointLetGoReason::NonFinite);
        discarded += static_cast<int>(bodies.size());
        letGo += static_cast<int>(joints.size());
    }
    EXPECT_GT(discarded, 0);
    EXPECT_EQ(letGo, 2);
    for (BodyId body : {a, b, c}) {
        EXPECT_TRUE(std::isfinite(world.bodyPosition(body).x));
        EXPECT_TRUE(std::isfinite(world.bodyAngularVelocity(body)));
    }
}
