// The four position solvers: each removes a joint's error, each in its own way, and the choice
// really is per joint.
#include <gtest/gtest.h>

#include <string>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A unit box (density 1) pinned to static ground at the world origin by the middle of its
// left edge, in zero gravity, then pulled away from the pin by `offset`.
struct PerturbedPin {
    World world{oneSubstepDef({0.0f, 0.0f})};
    BodyId box;
    JointId joint;

    PerturbedPin(PositionSolver solver, Vec2 offset, std::optional<float> bias = std::nullopt) {
        BodyId ground = world.createBody(BodyDef{});
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.5f, 0.0f};
        box = world.createBody(def);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(ground, box, {0.0f, 0.0f});
        jd.positionSolver = solver;
        jd.biasFactor = bias;
        joint = world.createJoint(jd);
        world.setBodyTransform(box, Vec2{0.5f, 0.0f} + offset, 0.0f);
    }

    float separation() const { return world.jointSeparation(joint); }
    float speed() const {
        return length(world.bodyLinearVelocity(box)) + std::fabs(world.bodyAngularVelocity(box));
    }
};

std::string solverName(const testing::TestParamInfo<PositionSolver>& info) {
    return positionSolverName(info.param);
}

const auto kAllSolvers = testing::Values(PositionSolver::Baumgarte, PositionSolver::PseudoVelocity,
                                         PositionSolver::ModifiedNGS, PositionSolver::FullNGS);

}  // namespace

class EverySolver : public testing::TestWithParam<PositionSolver> {};

TEST_P(EverySolver, DrivesAPerturbedJointsErrorBelowTheSlop) {
    PerturbedPin pin(GetParam(), {0.2f, 0.25f});
    float start = pin.separation();
    ASSERT_GT(start, 0.3f);
    pin.world.step(kDt);
    EXPECT_LT(pin.separation(), start) << "the first step must already reduce the error";
    for (int i = 0; i < 179; ++i) pin.world.step(kDt);
    EXPECT_LT(pin.separation(), kLinearSlop);
}

TEST_P(EverySolver, IsWhatTheWorldDefaultNamesWhenTheDefLeavesItUnset) {
    WorldDef wd = oneSubstepDef();
    wd.defaultPositionSolver = GetParam();
    World world(wd);
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId body = world.createBody(def);
    JointId j = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, body, {0, 0}));
    EXPECT_EQ(world.jointPositionSolver(j), GetParam());
    EXPECT_EQ(world.jointBiasFactor(j), defaultBiasFactor(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(PositionSolvers, EverySolver, kAllSolvers, solverName);

// One step from a 0.3 m error shows each algorithm's signature.
TEST(PositionSolverSignature, BaumgarteRemovesAFractionAndAddsMomentum) {
    PerturbedPin pin(PositionSolver::Baumgarte, {0.0f, 0.3f});
    pin.world.step(kDt);
    float ratio = pin.separation() / 0.3f;
    EXPECT_NEAR(ratio, 1.0f - kDefaultBaumgarteBias, 0.05f);
    // The correction went through the velocity: the box now moves.
    EXPECT_GT(pin.speed(), 1.0f);
}

TEST(PositionSolverSignature, PseudoVelocityRemovesAFractionWithoutMomentum) {
    PerturbedPin pin(PositionSolver::PseudoVelocity, {0.0f, 0.3f});
    pin.world.step(kDt);
    EXPECT_NEAR(pin.separation() / 0.3f, 1.0f - kDefaultPseudoVelocityBias, 0.05f);
    EXPECT_EQ(pin.speed(), 0.0f);
}

TEST(PositionSolverSignature, NgsRemovesTheWholeErrorWithoutMomentum) {
    for (PositionSolver s : {PositionSolver::ModifiedNGS, PositionSolver::FullNGS}) {
        PerturbedPin pin(s, {0.0f, 0.3f});
        pin.world.step(kDt);
        EXPECT_LT(pin.separation(), 0.01f) << positionSolverName(s);
        EXPECT_EQ(pin.speed(), 0.0f) << positionSolverName(s);
        EXPECT_EQ(pin.world.lastStepStats().positionIterations, kBox2D241PositionIterations);
    }
}

TEST(PositionSolverSignature, ModifiedAndFullNgsDifferOnceTheBodyHasTurned) {
    // The error is across the radius, so the first correction turns the box; from the second
    // sweep ModifiedNGS uses a stale effective mass and lands elsewhere than FullNGS.
    PerturbedPin modified(PositionSolver::ModifiedNGS, {0.0f, 0.3f});
    PerturbedPin full(PositionSolver::FullNGS, {0.0f, 0.3f});
    modified.world.step(kDt);
    full.world.step(kDt);
    EXPECT_NE(modified.world.bodyAngle(modified.box), full.world.bodyAngle(full.box));
}

TEST(PositionSolverSignature, NgsStopsEarlyOnceWithinSlop) {
    // Along the radius the correction is a pure translation: one sweep fixes it, the second
    // sees an error below the slop and ends the phase.
    PerturbedPin pin(PositionSolver::FullNGS, {0.3f, 0.0f});
    pin.world.step(kDt, 8, 10);
    EXPECT_EQ(pin.world.lastStepStats().positionIterations, 2);
    EXPECT_LT(pin.separation(), 1e-6f);
}

TEST(PositionSolverSettings, BiasFactorIsPerJoint) {
    PerturbedPin pin(PositionSolver::PseudoVelocity, {0.0f, 0.3f}, 0.5f);
    pin.world.step(kDt);
    EXPECT_NEAR(pin.separation() / 0.3f, 0.5f, 0.05f);
    EXPECT_EQ(pin.world.jointBiasFactor(pin.joint), 0.5f);
}

TEST(PositionSolverSettings, ChangingTheSolverBetweenStepsTakesEffectAtTheNextStep) {
    PerturbedPin pin(PositionSolver::FullNGS, {0.0f, 0.3f});
    pin.world.setJointPositionSolver(pin.joint, PositionSolver::PseudoVelocity);
    EXPECT_EQ(pin.world.jointPositionSolver(pin.joint), PositionSolver::PseudoVelocity);
    // A default bias follows the solver: 0.2 now, not NGS's 1.0.
    EXPECT_EQ(pin.world.jointBiasFactor(pin.joint), kDefaultPseudoVelocityBias);
    pin.world.step(kDt);
    EXPECT_NEAR(pin.separation() / 0.3f, 0.8f, 0.05f);

    pin.world.setJointPositionSolver(pin.joint, PositionSolver::FullNGS);
    pin.world.step(kDt);
    EXPECT_LT(pin.separation(), 0.01f);
}

TEST(PositionSolverSettings, ExplicitBiasSurvivesASolverChangeAndCanBeReset) {
    PerturbedPin pin(PositionSolver::Baumgarte, {0.0f, 0.3f}, 0.1f);
    pin.world.setJointPositionSolver(pin.joint, PositionSolver::PseudoVelocity);
    EXPECT_EQ(pin.world.jointBiasFactor(pin.joint), 0.1f);
    pin.world.setJointBiasFactor(pin.joint, std::nullopt);
    EXPECT_EQ(pin.world.jointBiasFactor(pin.joint), kDefaultPseudoVelocityBias);
}

TEST(PositionSolverNames, RoundTripAndRejectUnknown) {
    for (int i = 0; i < kPositionSolverCount; ++i) {
        auto s = static_cast<PositionSolver>(i);
        EXPECT_EQ(parsePositionSolver(positionSolverName(s)), s);
    }
    EXPECT_FALSE(parsePositionSolver("full-ngs").has_value());
    EXPECT_STREQ(positionSolverName(static_cast<PositionSolver>(9)), "invalid");
}

// --- two solvers in one world ----------------------------------------------------------------

namespace {

// A pendulum: a unit box hung 5 m below `pivot` and 0.5 m to the side, swinging at 6 rad/s.
// The offset matters: were the pin's line through the centre, every correction would be
// radial, would never turn the body, and ModifiedNGS's frozen K would equal FullNGS's.
BodyId addPendulum(World& world, Vec2 pivot, PositionSolver solver) {
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = pivot + Vec2{0.5f, -5.0f};
    def.angularVelocity = 6.0f;
    def.linearVelocity = cross(6.0f, def.position - pivot);
    BodyId ball = world.createBody(def);
    world.createShape(ball, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(ground, ball, pivot);
    jd.positionSolver = solver;
    world.createJoint(jd);
    return ball;
}

struct Pose {
    Vec2 c;
    float a;
    bool operator==(const Pose& o) const { return c == o.c && a == o.a; }
};

Pose poseOf(const World& world, BodyId body) {
    return {world.bodyWorldCenter(body), world.bodyAngle(body)};
}

Pose runAlone(PositionSolver solver, Vec2 pivot, int steps) {
    World world{oneSubstepDef()};
    BodyId ball = addPendulum(world, pivot, solver);
    for (int i = 0; i < steps; ++i) world.step(kDt);
    return poseOf(world, ball);
}

}  // namespace

TEST(MixedSolvers, EachJointInOneWorldRunsItsOwnAlgorithm) {
    const Vec2 left{-20.0f, 10.0f}, right{20.0f, 10.0f};
    for (int a = 0; a < kPositionSolverCount; ++a) {
        for (int b = 0; b < kPositionSolverCount; ++b) {
            if (a == b) continue;
            auto sa = static_cast<PositionSolver>(a), sb = static_cast<PositionSolver>(b);
            World world{oneSubstepDef()};
            BodyId ballA = addPendulum(world, left, sa);
            BodyId ballB = addPendulum(world, right, sb);
            for (int i = 0; i < 120; ++i) world.step(kDt);
            // Bit for bit what each solver does alone...
            EXPECT_EQ(poseOf(world, ballA), runAlone(sa, left, 120));
            EXPECT_EQ(poseOf(world, ballB), runAlone(sb, right, 120));
            // ...and the two algorithms really differ.
            EXPECT_FALSE(runAlone(sa, left, 120) == runAlone(sb, left, 120))
                << positionSolverName(sa) << " vs " << positionSolverName(sb);
        }
    }
}

TEST(MixedSolvers, OneIslandWithEveryStrategyStaysTogether) {
    // A hanging chain of 8 links whose joints cycle through the solvers. Changing one
    // joint's solver changes the result, so each joint's choice is honoured inside an island.
    auto run = [](PositionSolver firstJoint) {
        World world{oneSubstepDef()};
        BodyId previous = world.createBody(BodyDef{});
        std::vector<JointId> joints;
        for (int i = 0; i < 8; ++i) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {0.5f + float(i), 10.0f};
            BodyId link = world.createBody(def);
            world.createShape(link, ShapeDef{}, Polygon::box(0.6f, 0.125f));
            RevoluteJointDef jd =
                RevoluteJointDef::atWorldAnchor(previous, link, {float(i), 10.0f});
            jd.positionSolver =
                i == 0 ? firstJoint : static_cast<PositionSolver>(i % kPositionSolverCount);
            joints.push_back(world.createJoint(jd));
            previous = link;
        }
        float maxSeparation = 0.0f;
        for (int s = 0; s < 300; ++s) {
            world.step(kDt);
            for (JointId j : joints)
                maxSeparation = std::max(maxSeparation, world.jointSeparation(j));
        }
        EXPECT_EQ(world.lastStepStats().islandCount, 1);
        EXPECT_LT(maxSeparation, 0.5f);
        return world.stateHash();
    };
    std::uint64_t withBaumgarte = run(PositionSolver::Baumgarte);
    std::uint64_t withFullNgs = run(PositionSolver::FullNGS);
    EXPECT_NE(withBaumgarte, withFullNgs);
}
