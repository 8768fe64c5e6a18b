// The pulley joint: the rope's constant, balance by the ratio, every position solver, and its
// API.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "all_solvers.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

// Two boxes hung by their tops from wheels at (-2, 10) and (2, 10).
struct Pulley {
    World world{oneSubstepDef()};
    BodyId a, b;
    JointId joint;

    Pulley(float densityA, float densityB, float ratio, PositionSolver solver, Vec2 startB = {2, 5})
        : world(oneSubstepDef()) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-2, 5};
        a = world.createBody(def);
        ShapeDef shape;
        shape.density = densityA;
        world.createShape(a, shape, Polygon::box(0.5f, 0.5f));
        def.position = startB;
        b = world.createBody(def);
        shape.density = densityB;
        world.createShape(b, shape, Polygon::box(0.5f, 0.5f));
        PulleyJointDef jd;
        jd.bodyA = a;
        jd.bodyB = b;
        jd.groundAnchorA = {-2, 10};
        jd.groundAnchorB = {2, 10};
        jd.localAnchorA = {0, 0.5f};
        jd.localAnchorB = {0, 0.5f};
        jd.ratio = ratio;
        jd.positionSolver = solver;
        joint = world.createJoint(jd);
    }
};

constexpr const auto& kSolvers = test_support::kAllSolvers;
}  // namespace

TEST(PulleyJoint, TheLengthsDefaultToTheAnchorsDistances) {
    Pulley p(1, 1, 1.5f, PositionSolver::FullNGS);
    EXPECT_EQ(p.world.jointType(p.joint), JointType::Pulley);
    EXPECT_NEAR(p.world.pulleyJointLengthA(p.joint), 4.5f, 1e-6f);
    EXPECT_NEAR(p.world.pulleyJointLengthB(p.joint), 4.5f, 1e-6f);
    EXPECT_EQ(p.world.pulleyJointRatio(p.joint), 1.5f);
    EXPECT_EQ(p.world.pulleyJointGroundAnchorB(p.joint), (Vec2{2, 10}));
    EXPECT_EQ(p.world.jointSeparation(p.joint), 0.0f);
}

TEST(PulleyJoint, LoadsInTheRatioBalance) {
    // Side B moves 1.5 times less far than side A pays out (lengthA + 1.5 lengthB is kept), so
    // the rope pulls B 1.5 times harder: B balances A at 1.5 times its weight.
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Pulley p(1.0f, 1.5f, 1.5f, solver);
        const float yA = p.world.bodyPosition(p.a).y;
        for (int i = 0; i < 120; ++i) p.world.step(kDt);
        EXPECT_NEAR(p.world.bodyPosition(p.a).y, yA, 1e-3f);
        // The rope holds each load's weight: the force on B is its weight, upwards.
        const float weightB = p.world.bodyMass(p.b) * 10.0f;
        EXPECT_NEAR(p.world.jointReactionForce(p.joint).y, weightB, 0.01f * weightB);
    }
}

TEST(PulleyJoint, TheRopeKeepsItsLengthWithEverySolver) {
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        // Unbalanced, and B swinging off its wheel.
        Pulley p(2, 1, 1.5f, solver, {2.5f, 5});
        float worst = 0.0f;
        for (int i = 0; i < 300; ++i) {
            p.world.step(kDt);
            worst = std::max(worst, p.world.jointSeparation(p.joint));
        }
        const float ratio = 1.5f;
        const float total =
            p.world.pulleyJointLengthA(p.joint) + ratio * p.world.pulleyJointLengthB(p.joint);
        // 4.5 + 1.5 * |(2.5, 5.5) - (2, 10)| at the start.
        const float start = 4.5f + ratio * std::sqrt(0.25f + 4.5f * 4.5f);
        if (solver == PositionSolver::ModifiedNGS || solver == PositionSolver::FullNGS) {
            EXPECT_LT(worst, 0.01f);
            EXPECT_NEAR(total, start, 2.0f * kLinearSlop);
        } else {
            EXPECT_LT(worst, 0.5f);  // 0.46 m (Baumgarte) and 0.27 m at worst, measured
            EXPECT_NEAR(total, start, 0.05f);
        }
        // The heavy box went down.
        EXPECT_LT(p.world.bodyPosition(p.a).y, 4.0f);
    }
}

TEST(PulleyJoint, BadInputIsRefusedAndChangesNothing) {
    Pulley p(1, 1, 1, PositionSolver::FullNGS);
    World& world = p.world;
    const std::uint64_t hash = world.stateHash();
    auto expectRefused = [&](auto&& call, const std::string& words) {
        try {
            call();
            ADD_FAILURE() << "accepted; expected an error about " << words;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.stateHash(), hash);
    };
    PulleyJointDef def;
    def.bodyA = p.a;
    def.bodyB = p.b;
    def.groundAnchorA = {-2, 10};
    def.groundAnchorB = {2, 10};
    def.ratio = 0.0f;
    expectRefused([&] { world.createJoint(def); }, "def.ratio");
    def.ratio = 1000.0f;
    expectRefused([&] { world.createJoint(def); }, "def.ratio");
    def.ratio = 1.0f;
    def.lengthA = 0.01f;
    expectRefused([&] { world.createJoint(def); }, "def.lengthA must be in [kMinPulleyLength");
    def.lengthA.reset();
    def.groundAnchorB = {2, 5};  // B's anchor, its centre, is at its wheel
    expectRefused([&] { world.createJoint(def); }, "def.lengthB (anchor B's distance)");
    def.groundAnchorB = {std::nanf(""), 10};
    expectRefused([&] { world.createJoint(def); }, "def.groundAnchorB");
    expectRefused([&] { world.jointMotor(p.joint); }, "is a pulley joint; this call is for");
    expectRefused([&] { world.distanceJointLimit(p.joint); }, "for distance joints");
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(p.a, p.b, {0, 5}));
    try {
        world.pulleyJointRatio(pin);
        ADD_FAILURE() << "accepted a revolute joint";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("this call is for pulley joints"), std::string::npos);
    }
}
