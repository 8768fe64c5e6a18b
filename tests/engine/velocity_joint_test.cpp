// The friction and motor joints: velocity only, the same under every strategy, and their API.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

template <typename Call>
void expectRefused(World& world, Call&& call, const std::string& words) {
    const std::uint64_t hash = world.stateHash();
    try {
        call();
        ADD_FAILURE() << "accepted; expected an error about " << words;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_EQ(world.stateHash(), hash);
}
}  // namespace

TEST(FrictionJoint, StopsASlidingBoxAsFrictionWould) {
    // 1 kg box at 3 m/s, friction force 5 N: it stops after 0.6 s, 0.9 m on.
    WorldDef def = oneSubstepDef();
    def.gravity = {0, 0};
    World world(def);
    BodyId table = world.createBody(BodyDef{});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.linearVelocity = {3, 0};
    BodyId box = world.createBody(bd);
    world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    ASSERT_NEAR(world.bodyMass(box), 1.0f, 1e-6f);
    FrictionJointDef jd;
    jd.bodyA = table;
    jd.bodyB = box;
    jd.maxForce = 5.0f;
    jd.maxTorque = 1.0f;
    JointId joint = world.createJoint(jd);
    EXPECT_EQ(world.jointType(joint), JointType::Friction);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyLinearVelocity(box).x, 0.0f, 1e-5f);
    EXPECT_NEAR(world.bodyPosition(box).x, 0.9f, 0.03f);
    // While sliding it pulled back with the full 5 N.
    world.setBodyLinearVelocity(box, {3, 0});
    world.step(kDt);
    EXPECT_NEAR(world.jointReactionForce(joint).x, -5.0f, 1e-3f);
    EXPECT_EQ(world.jointSeparation(joint), 0.0f);
}

TEST(MotorJoint, DrivesABodyToItsOffsetWithinItsForce) {
    WorldDef def = oneSubstepDef();
    def.gravity = {0, 0};
    World world(def);
    BodyId ground = world.createBody(BodyDef{});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId body = world.createBody(bd);
    world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    MotorJointDef jd;
    jd.bodyA = ground;
    jd.bodyB = body;
    jd.maxForce = 50.0f;
    jd.maxTorque = 50.0f;
    JointId joint = world.createJoint(jd);
    EXPECT_EQ(world.motorJointLinearOffset(joint), (Vec2{0, 0}));  // where B was
    world.setMotorJointLinearOffset(joint, {3, 1});
    world.setMotorJointAngularOffset(joint, 1.0f);
    for (int i = 0; i < 300; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(body).x, 3.0f, 1e-3f);
    EXPECT_NEAR(world.bodyPosition(body).y, 1.0f, 1e-3f);
    EXPECT_NEAR(world.bodyAngle(body), 1.0f, 1e-3f);
    // A force cap of 0 drives nothing.
    world.setJointMaxForce(joint, 0.0f);
    world.setJointMaxTorque(joint, 0.0f);
    world.setMotorJointLinearOffset(joint, {-3, 1});
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(body).x, 3.0f, 1e-3f);
    EXPECT_EQ(world.jointMaxForce(joint), 0.0f);
}

TEST(VelocityJoints, BehaveTheSameUnderTheWorldsEveryDefaultSolver) {
    // The strategy a velocity-only joint sits under changes nothing: the same bits.
    auto run = [](PositionSolver solver) {
        WorldDef def = oneSubstepDef();
        def.defaultPositionSolver = solver;
        World world(def);
        BodyId ground = world.createBody(BodyDef{});
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {0, 5};
        BodyId body = world.createBody(bd);
        world.createShape(body, ShapeDef{}, Polygon::box(1, 0.25f));
        MotorJointDef motor;
        motor.bodyA = ground;
        motor.bodyB = body;
        motor.maxForce = 100;
        motor.linearOffset = Vec2{2, 6};
        world.createJoint(motor);
        for (int i = 0; i < 120; ++i) world.step(kDt);
        return std::make_pair(world.bodyPosition(body), world.bodyAngle(body));
    };
    const auto reference = run(PositionSolver::FullNGS);
    for (PositionSolver solver :
         {PositionSolver::Baumgarte, PositionSolver::PseudoVelocity, PositionSolver::ModifiedNGS,
          PositionSolver::SoftStep, PositionSolver::XPBD}) {
        const auto other = run(solver);
        EXPECT_EQ(other.first, reference.first) << positionSolverName(solver);
        EXPECT_EQ(other.second, reference.second) << positionSolverName(solver);
    }
}

TEST(VelocityJoints, BadInputIsRefusedAndChangesNothing) {
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId body = world.createBody(bd);
    world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    FrictionJointDef friction;
    friction.bodyA = ground;
    friction.bodyB = body;
    friction.maxForce = -1.0f;
    expectRefused(
        world, [&] { world.createJoint(friction); }, "def.maxForce");
    friction.maxForce = 1.0f;
    friction.maxTorque = std::nanf("");
    expectRefused(
        world, [&] { world.createJoint(friction); }, "def.maxTorque");
    friction.maxTorque = 1.0f;
    MotorJointDef motor;
    motor.bodyA = ground;
    motor.bodyB = body;
    motor.correctionFactor = 1.5f;
    expectRefused(
        world, [&] { world.createJoint(motor); }, "def.correctionFactor");
    motor.correctionFactor = 0.3f;
    motor.linearOffset = Vec2{1e30f, 0};
    expectRefused(
        world, [&] { world.createJoint(motor); }, "def.linearOffset");
    motor.linearOffset.reset();
    const JointId f = world.createJoint(friction);
    const JointId m = world.createJoint(motor);
    expectRefused(
        world, [&] { world.setJointPositionSolver(f, PositionSolver::Baumgarte); },
        "is a friction joint, which acts in the velocity phase only");
    expectRefused(
        world, [&] { world.setJointBiasFactor(m, 0.5f); },
        "is a motor joint, which acts in the velocity phase only");
    expectRefused(
        world, [&] { world.setJointMaxForce(f, -2.0f); }, "force");
    expectRefused(
        world, [&] { world.setMotorJointCorrectionFactor(m, -0.1f); }, "factor");
    expectRefused(
        world, [&] { world.motorJointLinearOffset(f); },
        "is a friction joint; this call is for motor joints");
    JointId pin = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, body, {0, 0}));
    expectRefused(
        world, [&] { world.jointMaxForce(pin); }, "for friction and motor joints");
    expectRefused(
        world, [&] { world.jointLimit(m); }, "is a motor joint");
    EXPECT_EQ(world.jointReactionTorque(f), 0.0f);
}
