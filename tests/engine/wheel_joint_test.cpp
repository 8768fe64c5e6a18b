// The wheel joint: the wheel held on its suspension line, the spring, limit and motor, every
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

// A 2.5 x 0.5 m chassis on two 0.4 m wheels 1.8 m apart, sprung vertically, on flat ground.
struct Car {
    World world{oneSubstepDef()};
    BodyId ground, chassis, rear, front;
    JointId rearJoint, frontJoint;

    explicit Car(PositionSolver solver, JointSpring spring = {true, 4.0f, 0.7f},
                 TranslationLimit limit = {}, JointMotor motor = {})
        : world(oneSubstepDef()) {
        ground = world.createBody(BodyDef{});
        ShapeDef slab;
        slab.density = 0.0f;
        world.createShape(ground, slab, Polygon::box(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, 1.3f};
        chassis = world.createBody(def);
        world.createShape(chassis, ShapeDef{}, Polygon::box(1.25f, 0.25f));
        const auto wheel = [&](float x, JointId& joint, JointMotor m) {
            BodyDef w;
            w.type = BodyType::Dynamic;
            w.position = {x, 0.55f};
            const BodyId body = world.createBody(w);
            ShapeDef tyre;
            tyre.friction = 0.9f;
            world.createShape(body, tyre, Circle{{0.0f, 0.0f}, 0.4f});
            WheelJointDef jd = WheelJointDef::atWorldAnchor(chassis, body, {x, 0.55f}, {0, 1});
            jd.spring = spring;
            jd.limit = limit;
            jd.motor = m;
            jd.positionSolver = solver;
            joint = world.createJoint(jd);
            return body;
        };
        rear = wheel(-0.9f, rearJoint, motor);
        front = wheel(0.9f, frontJoint, {});
    }
};
}  // namespace

TEST(WheelJoint, TheDefIsTakenFromTheWorldAnchorAndAxis) {
    Car c(PositionSolver::FullNGS);
    EXPECT_EQ(c.world.jointType(c.rearJoint), JointType::Wheel);
    EXPECT_STREQ(jointTypeName(JointType::Wheel), "wheel");
    EXPECT_EQ(c.world.jointTranslation(c.rearJoint), 0.0f);
    EXPECT_EQ(c.world.jointSeparation(c.rearJoint), 0.0f);
    EXPECT_EQ(c.world.wheelJointSpring(c.rearJoint).hertz, 4.0f);
    EXPECT_EQ(c.world.jointAnchorA(c.frontJoint), (Vec2{0.9f, 0.55f}));
}

TEST(WheelJoint, TheSuspensionCarriesTheChassisWithEverySolver) {
    // At rest the two joints push their wheels down with the chassis's weight between them,
    // and each wheel stays on its line under the chassis.
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Car c(solver);
        float worst = 0.0f;
        for (int i = 0; i < 300; ++i) {
            c.world.step(kDt);
            worst = std::max({worst, c.world.jointSeparation(c.rearJoint),
                              c.world.jointSeparation(c.frontJoint)});
        }
        const float weight = c.world.bodyMass(c.chassis) * 10.0f;
        const float pushed =
            c.world.jointReactionForce(c.rearJoint).y + c.world.jointReactionForce(c.frontJoint).y;
        EXPECT_NEAR(pushed, -weight, 0.01f * weight);
        EXPECT_LT(worst, solver == PositionSolver::Baumgarte ? 0.01f : 2.0f * kLinearSlop);
        // The springs are compressed: the chassis came down towards the wheels, which is a
        // positive translation (anchor B, the wheel, is further up the axis from anchor A).
        EXPECT_GT(c.world.jointTranslation(c.rearJoint), 0.001f);
        EXPECT_NEAR(c.world.jointTranslationSpeed(c.rearJoint), 0.0f, 1e-3f);
    }
}

TEST(WheelJoint, TheMotorTurnsTheWheelAndDrivesTheCar) {
    Car c(PositionSolver::FullNGS, {true, 4.0f, 0.7f}, {}, {true, -10.0f, 20.0f});
    for (int i = 0; i < 180; ++i) c.world.step(kDt);
    // Clockwise, at the motor's speed relative to the chassis: the car rolls to the right.
    EXPECT_NEAR(c.world.jointSpeed(c.rearJoint), -10.0f, 0.1f);
    EXPECT_GT(c.world.bodyPosition(c.chassis).x, 5.0f);
    EXPECT_LE(std::fabs(c.world.jointMotorTorque(c.rearJoint)), 20.0f * (1.0f + 1e-6f));
    EXPECT_TRUE(c.world.jointMotor(c.rearJoint).enabled);
    c.world.setJointMotor(c.rearJoint, {true, 0.0f, 20.0f});  // the brake
    for (int i = 0; i < 240; ++i) c.world.step(kDt);
    EXPECT_NEAR(c.world.bodyLinearVelocity(c.chassis).x, 0.0f, 0.05f);
}

TEST(WheelJoint, TheLimitStopsASoftSuspension) {
    // At 0.5 Hz the suspension alone would sag far; the limit holds it at 5 cm of compression
    // (the upper limit: compression is a positive translation).
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Car c(solver, {true, 0.5f, 0.7f}, {true, -0.05f, 0.05f});
        for (int i = 0; i < 300; ++i) c.world.step(kDt);
        const float tolerance = solver == PositionSolver::Baumgarte ? 0.01f : 2.0f * kLinearSlop;
        EXPECT_NEAR(c.world.jointTranslation(c.rearJoint), 0.05f, tolerance);
        EXPECT_EQ(c.world.wheelJointLimit(c.rearJoint).upper, 0.05f);
    }
}

TEST(WheelJoint, BadInputIsRefusedAndChangesNothing) {
    Car c(PositionSolver::FullNGS);
    World& world = c.world;
    std::uint64_t hash = world.stateHash();
    auto expectRefused = [&](auto&& call, const std::string& words) {
        try {
            call();
            ADD_FAILURE() << "accepted; expected an error about " << words;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.stateHash(), hash);
    };
    WheelJointDef def = WheelJointDef::atWorldAnchor(c.chassis, c.front, {0.9f, 0.55f}, {0, 0});
    expectRefused([&] { world.createJoint(def); }, "def.worldAxis must be longer than");
    def.worldAxis = Vec2{0, 1};
    def.localAnchorB = {0.1f, 0};
    expectRefused([&] { world.createJoint(def); }, "set one or the other");
    def.localAnchorB = {};
    def.spring = {true, -4.0f, 0.7f};
    expectRefused([&] { world.createJoint(def); }, "def.spring.hertz");
    def.spring = {};
    def.limit = {true, 0.1f, -0.1f};
    expectRefused([&] { world.createJoint(def); }, "def.limit.lower must be <=");
    def.limit = {};
    def.motor = {true, 1.0f, -5.0f};
    expectRefused([&] { world.createJoint(def); }, "def.motor.maxTorque");
    expectRefused(
        [&] {
            world.setWheelJointLimit(c.rearJoint, {true, 1.0f, 0.0f});
        },
        "limit.lower must be <=");
    expectRefused([&] { world.setJointMotor(c.rearJoint, {true, NAN, 1.0f}); }, "motor.speed");
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(c.ground, c.chassis, {0, 2}));
    JointId slide =
        world.createJoint(PrismaticJointDef::atWorldAnchor(c.ground, c.chassis, {0, 2}, {1, 0}));
    hash = world.stateHash();
    expectRefused([&] { world.wheelJointSpring(pin); }, "this call is for wheel joints");
    expectRefused([&] { world.jointTranslation(pin); },
                  "this call is for prismatic and wheel joints");
    expectRefused([&] { world.jointMotor(slide); }, "this call is for revolute and wheel joints");
}
