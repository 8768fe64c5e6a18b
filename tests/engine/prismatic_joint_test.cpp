// The prismatic joint: the slide kept straight, the limit, motor and spring along it, every
// position solver, and its API.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "all_solvers.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

constexpr const auto& kSolvers = test_support::kAllSolvers;

// A 2 x 0.5 m box sliding on a rail tilted 30 degrees from the ground, at the ground point
// (0, 5); the box's centre is the anchor, and a second box of 4x the density hangs 1 m to the
// side of it on a pin, so that the slide is twisted as the load swings.
struct Rail {
    World world{oneSubstepDef()};
    BodyId ground, slider, load;
    JointId joint;

    explicit Rail(PositionSolver solver, TranslationLimit limit = {}, LinearMotor motor = {},
                  JointSpring spring = {})
        : world(oneSubstepDef()) {
        ground = world.createBody(BodyDef{});
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0, 5};
        slider = world.createBody(def);
        world.createShape(slider, ShapeDef{}, Polygon::box(1.0f, 0.25f));
        def.position = {1, 4};
        load = world.createBody(def);
        ShapeDef heavy;
        heavy.density = 4.0f;
        world.createShape(load, heavy, Polygon::box(0.25f, 0.25f));
        world.createJoint(RevoluteJointDef::atWorldAnchor(slider, load, {1, 5}));
        const float angle = kPi / 6.0f;
        PrismaticJointDef jd = PrismaticJointDef::atWorldAnchor(ground, slider, {0, 5},
                                                                {std::cos(angle), std::sin(angle)});
        jd.limit = limit;
        jd.motor = motor;
        jd.spring = spring;
        jd.positionSolver = solver;
        joint = world.createJoint(jd);
    }
};
}  // namespace

TEST(PrismaticJoint, TheDefIsTakenFromTheWorldAnchorAndAxis) {
    Rail r(PositionSolver::FullNGS);
    EXPECT_EQ(r.world.jointType(r.joint), JointType::Prismatic);
    EXPECT_STREQ(jointTypeName(JointType::Prismatic), "prismatic");
    const Vec2 axis = r.world.prismaticJointAxis(r.joint);
    EXPECT_NEAR(axis.x, std::cos(kPi / 6.0f), 1e-6f);
    EXPECT_NEAR(axis.y, 0.5f, 1e-6f);
    EXPECT_EQ(r.world.jointTranslation(r.joint), 0.0f);
    EXPECT_EQ(r.world.jointSeparation(r.joint), 0.0f);
    EXPECT_EQ(r.world.jointAngle(r.joint), 0.0f);
    // An axis of any length is normalised.
    PrismaticJointDef def;
    def.bodyA = r.ground;
    def.bodyB = r.slider;
    def.localAxisA = {0, 3};
    const JointId upright = r.world.createJoint(def);
    EXPECT_EQ(r.world.prismaticJointAxis(upright), (Vec2{0, 1}));
}

TEST(PrismaticJoint, TheSlideStaysStraightWithEverySolver) {
    // Gravity pulls the slider down the rail and the swinging load twists it: the anchor must
    // stay on the line and the angle fixed, while the translation runs freely.
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Rail r(solver);
        float worst = 0.0f, worstAngle = 0.0f;
        for (int i = 0; i < 120; ++i) {
            r.world.step(kDt);
            worst = std::max(worst, r.world.jointSeparation(r.joint));
            worstAngle = std::max(worstAngle, std::fabs(r.world.jointAngle(r.joint)));
        }
        // Nothing pushes along the rail but gravity: the centre of mass of slider and load
        // slides 120 steps at g sin 30 degrees, while the load swings about it. Semi-implicit
        // Euler moves it a h^2 n (n + 1) / 2, 10.083 m.
        const Vec2 axis = r.world.prismaticJointAxis(r.joint);
        const float mS = r.world.bodyMass(r.slider), mL = r.world.bodyMass(r.load);
        const Vec2 centre = (1.0f / (mS + mL)) * (mS * r.world.bodyWorldCenter(r.slider) +
                                                  mL * r.world.bodyWorldCenter(r.load));
        const Vec2 start = (1.0f / (mS + mL)) * (mS * Vec2{0, 5} + mL * Vec2{1, 4});
        EXPECT_NEAR(dot(centre - start, axis), -5.0f * kDt * kDt * 120.0f * 121.0f / 2.0f, 1e-3f);
        if (solver == PositionSolver::ModifiedNGS || solver == PositionSolver::FullNGS) {
            EXPECT_LT(worst, 2.0f * kLinearSlop);
            EXPECT_LT(worstAngle, 2.0f * kAngularSlop);
        } else {
            EXPECT_LT(worst, 0.05f);
            EXPECT_LT(worstAngle, 0.05f);
        }
    }
}

TEST(PrismaticJoint, TheLimitStopsTheSlideWithEverySolver) {
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Rail r(solver, {true, -1.0f, 0.5f});
        float lowest = 0.0f;
        for (int i = 0; i < 180; ++i) {
            r.world.step(kDt);
            lowest = std::min(lowest, r.world.jointTranslation(r.joint));
        }
        const float x = r.world.jointTranslation(r.joint);
        if (solver == PositionSolver::ModifiedNGS || solver == PositionSolver::FullNGS) {
            EXPECT_GT(lowest, -1.0f - 2.0f * kLinearSlop);
            EXPECT_NEAR(x, -1.0f, 2.0f * kLinearSlop);
        } else {
            EXPECT_GT(lowest, -1.1f);
            EXPECT_NEAR(x, -1.0f, 0.02f);
        }
        // The limit holds the slider's weight along the rail, pushing B towards +axis.
        const Vec2 axis = r.world.prismaticJointAxis(r.joint);
        EXPECT_GT(dot(r.world.jointReactionForce(r.joint), axis), 0.0f);
    }
}

TEST(PrismaticJoint, TheMotorDrivesUpTheRailWithinItsForce) {
    // 1 m/s up the rail, with force to spare: the slider climbs at the motor's speed.
    Rail r(PositionSolver::FullNGS, {}, {true, 1.0f, 2000.0f});
    for (int i = 0; i < 120; ++i) r.world.step(kDt);
    EXPECT_NEAR(r.world.jointTranslationSpeed(r.joint), 1.0f, 0.01f);
    EXPECT_NEAR(r.world.jointTranslation(r.joint), 2.0f, 0.05f);
    const float force = r.world.prismaticJointMotorForce(r.joint);
    EXPECT_GT(force, 0.0f);
    EXPECT_LE(force, 2000.0f * (1.0f + 1e-6f));
    // Too weak to hold slider and load (2 kg, 10 N along the rail): the motor gives all it has
    // and they slide down.
    r.world.setPrismaticJointMotor(r.joint, {true, 1.0f, 4.0f});
    for (int i = 0; i < 60; ++i) r.world.step(kDt);
    EXPECT_LT(r.world.jointTranslationSpeed(r.joint), -1.0f);
    EXPECT_NEAR(r.world.prismaticJointMotorForce(r.joint), 4.0f, 1e-3f);
    EXPECT_EQ(r.world.prismaticJointMotor(r.joint).maxForce, 4.0f);
}

TEST(PrismaticJoint, TheSpringHoldsTheSliderWhereItsForceBalancesTheWeight) {
    // A damped spring towards translation 0 settles where k x balances slider and load's weight
    // along the rail. Its stiffness is k = (2 pi hertz)^2 / K, K the joint's effective inverse
    // mass along the axis: here 1 / the slider's mass (the load hangs from a pin at the slider,
    // which moves it along without turning the slider's axis row).
    // The load keeps swinging (nothing damps its pin), so the translation is averaged.
    Rail r(PositionSolver::FullNGS, {}, {}, {true, 2.0f, 1.0f});
    for (int i = 0; i < 480; ++i) r.world.step(kDt);
    float sum = 0.0f;
    for (int i = 0; i < 120; ++i) {
        r.world.step(kDt);
        sum += r.world.jointTranslation(r.joint);
    }
    const float weight = (r.world.bodyMass(r.slider) + r.world.bodyMass(r.load)) * 10.0f * 0.5f;
    const float omega = 2.0f * kPi * 2.0f;
    const float k = omega * omega * r.world.bodyMass(r.slider);
    EXPECT_NEAR(sum / 120.0f, -weight / k, 0.002f);
}

TEST(PrismaticJoint, SettersTakeEffectAndLimitsRestartTheirImpulses) {
    Rail r(PositionSolver::FullNGS, {true, -1.0f, 0.5f});
    for (int i = 0; i < 120; ++i) r.world.step(kDt);
    EXPECT_EQ(r.world.prismaticJointLimit(r.joint).lower, -1.0f);
    r.world.setPrismaticJointLimit(r.joint, {true, -2.0f, 0.5f});
    const TranslationLimit l = r.world.prismaticJointLimit(r.joint);
    EXPECT_TRUE(l.enabled);
    EXPECT_EQ(l.lower, -2.0f);
    for (int i = 0; i < 120; ++i) r.world.step(kDt);
    EXPECT_NEAR(r.world.jointTranslation(r.joint), -2.0f, 2.0f * kLinearSlop);
    r.world.setPrismaticJointSpring(r.joint, {true, 1.0f, 0.5f});
    EXPECT_EQ(r.world.prismaticJointSpring(r.joint).hertz, 1.0f);
}

TEST(PrismaticJoint, BadInputIsRefusedAndChangesNothing) {
    Rail r(PositionSolver::FullNGS);
    World& world = r.world;
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
    PrismaticJointDef def;
    def.bodyA = r.ground;
    def.bodyB = r.slider;
    def.localAxisA = {0, 0};
    expectRefused([&] { world.createJoint(def); }, "def.localAxisA must be longer than");
    def.localAxisA = {std::nanf(""), 1};
    expectRefused([&] { world.createJoint(def); }, "def.localAxisA");
    def.localAxisA = {0, 1};
    def.worldAxis = Vec2{1, 0};
    expectRefused([&] { world.createJoint(def); }, "set one or the other");
    def.worldAxis.reset();
    def.worldAnchor = Vec2{0, 5};
    def.referenceAngle = 0.5f;
    expectRefused([&] { world.createJoint(def); }, "set one or the other");
    def.worldAnchor.reset();
    def.limit = {true, 1.0f, -1.0f};
    expectRefused([&] { world.createJoint(def); }, "def.limit.lower must be <=");
    def.limit = {true, -2.0f * kMaxCoordinate, 0.0f};
    expectRefused([&] { world.createJoint(def); }, "def.limit.lower");
    def.limit = {};
    def.motor = {true, 2.0f * kMaxSpeed, 1.0f};
    expectRefused([&] { world.createJoint(def); }, "def.motor.speed");
    def.motor = {true, 1.0f, -1.0f};
    expectRefused([&] { world.createJoint(def); }, "def.motor.maxForce");
    def.motor = {};
    def.spring = {true, 0.0f, 1.0f};
    expectRefused([&] { world.createJoint(def); }, "def.spring.hertz must be > 0");
    def.spring = {};
    def.bodyB = r.ground;
    expectRefused([&] { world.createJoint(def); }, "the same body");
    expectRefused(
        [&] {
            world.setPrismaticJointLimit(r.joint, {true, 0.0f, -1.0f});
        },
        "limit.lower must be <=");
    expectRefused(
        [&] {
            world.setPrismaticJointMotor(r.joint, {true, INFINITY, 1.0f});
        },
        "motor.speed");
    expectRefused([&] { world.jointLimit(r.joint); }, "is a prismatic joint; this call is for");
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(r.ground, r.load, {1, 4}));
    try {
        world.jointTranslation(pin);
        ADD_FAILURE() << "accepted a revolute joint";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("this call is for prismatic and wheel joints"),
                  std::string::npos);
    }
}

TEST(PrismaticJoint, AJointCreatedFarFromItsLineAndAngleIsPulledOntoThem) {
    // The slider starts 5 m off the line and 2.5 rad from the reference angle, with a limit it
    // is already beyond: each NGS solve corrects a capped share, so the joint closes in over
    // a few steps instead of overshooting (prismatic_constraint.h).
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        World world{oneSubstepDef()};
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {3, 5};
        const BodyId slider = world.createBody(def);
        world.createShape(slider, ShapeDef{}, Polygon::box(1.0f, 0.3f));
        const BodyId ground = world.createBody(BodyDef{});
        PrismaticJointDef jd;
        jd.bodyA = slider;
        jd.bodyB = ground;
        jd.localAxisA = {1, 0};
        jd.referenceAngle = 2.5f;
        jd.limit = {true, 1.5f, 1.8f};
        jd.spring = {true, 1.0f, 0.5f};
        jd.positionSolver = solver;
        const JointId joint = world.createJoint(jd);
        for (int i = 0; i < 300; ++i) {
            world.step(kDt);
            ASSERT_TRUE(world.discardedBodies().empty()) << "step " << i;
        }
        EXPECT_TRUE(isFinite(world.bodyPosition(slider)));
        EXPECT_LT(world.jointSeparation(joint), 0.05f);
        EXPECT_LT(std::fabs(world.jointAngle(joint)), 0.05f);
    }
}
