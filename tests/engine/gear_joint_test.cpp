// The gear joint: meshing wheels and a rack and pinion with every position solver, the
// acceleration the coupling's effective mass predicts, a gearbox on a moving body (the cross
// terms of a shared body), its API and its refusals.
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

BodyId disc(World& world, Vec2 at, float radius) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Circle{{0, 0}, radius});
    return body;
}

// Two wheels of radii 1 and 2 pinned to `base` 3 m apart and meshed by a gear (ratio 2: the
// big one turns half as fast, the other way); a motor drives the small one.
struct Wheels {
    World world{oneSubstepDef()};
    BodyId base, small, big;
    JointId pin1, pin2, gear;

    explicit Wheels(PositionSolver solver, bool floatingBase = false)
        : world(makeDef(floatingBase)) {
        BodyDef baseDef;
        if (floatingBase) baseDef.type = BodyType::Dynamic;
        base = world.createBody(baseDef);
        world.createShape(base, ShapeDef{}, Polygon::box(3.0f, 0.25f));
        small = disc(world, {-1, 0}, 1.0f);
        big = disc(world, {2, 0}, 2.0f);
        RevoluteJointDef pin = RevoluteJointDef::atWorldAnchor(base, small, {-1, 0});
        pin.motor = {true, 2.0f, 50.0f};
        pin.positionSolver = solver;
        pin1 = world.createJoint(pin);
        RevoluteJointDef pinBig = RevoluteJointDef::atWorldAnchor(base, big, {2, 0});
        pinBig.positionSolver = solver;
        pin2 = world.createJoint(pinBig);
        GearJointDef gd;
        gd.joint1 = pin1;
        gd.joint2 = pin2;
        gd.ratio = 2.0f;
        gd.positionSolver = solver;
        gear = world.createJoint(gd);
    }
    static WorldDef makeDef(bool floatingBase) {
        WorldDef def = oneSubstepDef();
        if (floatingBase) def.gravity = {0, 0};
        return def;
    }
};

// A pinion of radius 0.5 pinned at (0, 5), and a 1 x 0.2 m rack on a vertical prismatic joint
// beside it (0.05 m clear), falling under its weight and turning the pinion.
struct RackAndPinion {
    World world{oneSubstepDef()};
    BodyId ground, pinion, rack;
    JointId pin, slide, gear;

    explicit RackAndPinion(PositionSolver solver) : world(oneSubstepDef()) {
        ground = world.createBody(BodyDef{});
        pinion = disc(world, {0, 5}, 0.5f);
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.65f, 5};
        rack = world.createBody(def);
        ShapeDef heavy;
        heavy.density = 5.0f;
        world.createShape(rack, heavy, Polygon::box(0.1f, 0.5f));
        pin = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, pinion, {0, 5}));
        slide =
            world.createJoint(PrismaticJointDef::atWorldAnchor(ground, rack, {0.65f, 5}, {0, 1}));
        GearJointDef gd;
        gd.joint1 = pin;
        gd.joint2 = slide;
        gd.ratio = -2.0f;  // the rack rises as the pinion turns counter-clockwise
        gd.positionSolver = solver;
        gear = world.createJoint(gd);
    }
};
}  // namespace

TEST(GearJoint, TheDefIsTakenFromTheTwoJoints) {
    Wheels w(PositionSolver::FullNGS);
    EXPECT_EQ(w.world.jointType(w.gear), JointType::Gear);
    EXPECT_STREQ(jointTypeName(JointType::Gear), "gear");
    EXPECT_EQ(w.world.jointBodyA(w.gear), w.small);
    EXPECT_EQ(w.world.jointBodyB(w.gear), w.big);
    EXPECT_EQ(w.world.gearJointJoint1(w.gear), w.pin1);
    EXPECT_EQ(w.world.gearJointJoint2(w.gear), w.pin2);
    EXPECT_EQ(w.world.gearJointRatio(w.gear), 2.0f);
    EXPECT_EQ(w.world.jointAnchorA(w.gear), (Vec2{-1, 0}));
    EXPECT_EQ(w.world.jointAnchorB(w.gear), (Vec2{2, 0}));
    EXPECT_EQ(w.world.jointSeparation(w.gear), 0.0f);
    EXPECT_EQ(w.world.jointPositionSolver(w.gear), PositionSolver::FullNGS);
}

TEST(GearJoint, MeshedWheelsTurnInTheRatioWithEverySolver) {
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Wheels w(solver);
        for (int i = 0; i < 120; ++i) w.world.step(kDt);
        const float small = w.world.bodyAngle(w.small);
        const float big = w.world.bodyAngle(w.big);
        EXPECT_GT(small, 2.0f);  // the motor turned it (2 rad/s for 2 s, less the spin-up)
        EXPECT_NEAR(big, -small / 2.0f, 1e-3f);
        EXPECT_LT(w.world.jointSeparation(w.gear), 1e-3f);
        EXPECT_NEAR(w.world.bodyAngularVelocity(w.big), -w.world.bodyAngularVelocity(w.small) / 2,
                    1e-3f);
    }
}

TEST(GearJoint, TheRackFallsAsSlowlyAsThePinionsInertiaPredicts) {
    // With the pinion's angle held to -ratio x, the rack of mass m moves as a body of mass
    // m + I ratio^2: a = m g / (m + I ratio^2), and the gear holds the rest of its weight.
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        RackAndPinion r(solver);
        const float m = r.world.bodyMass(r.rack);
        const float inertia = r.world.bodyRotationalInertia(r.pinion);
        const float expected = m * 10.0f / (m + inertia * 4.0f);
        const float y0 = r.world.bodyPosition(r.rack).y;
        const int steps = 30;
        for (int i = 0; i < steps; ++i) r.world.step(kDt);
        const float t = steps * kDt;
        const float fallen = y0 - r.world.bodyPosition(r.rack).y;
        // Semi-implicit Euler: x_n = a h^2 n (n + 1) / 2.
        EXPECT_NEAR(fallen, expected * kDt * kDt * steps * (steps + 1) / 2, 1e-3f);
        EXPECT_NEAR(-r.world.bodyLinearVelocity(r.rack).y, expected * t, 1e-3f);
        // The pinion turns clockwise as the rack falls: angle = -ratio x = 2 (y - y0).
        EXPECT_NEAR(r.world.bodyAngle(r.pinion), -2.0f * fallen, 1e-3f);
        EXPECT_LT(r.world.jointSeparation(r.gear), 1e-3f);
        // The force on the rack (body B) is what its weight does not spend on accelerating it.
        EXPECT_NEAR(r.world.jointReactionForce(r.gear).y, m * (10.0f - expected), 0.01f * m);
        EXPECT_NEAR(r.world.jointReactionForce(r.gear).x, 0.0f, 1e-4f);
    }
}

TEST(GearJoint, AGearboxOnAFloatingBodyHoldsItsRatioInOneVelocityIteration) {
    // Both pins hang from one dynamic body: the gear's row acts on it twice, and its effective
    // mass needs the cross term of the two (Box2D 2.4.1 leaves it out). The gear is the last
    // joint of its strategy solved in an iteration, so with the right K one velocity iteration
    // leaves its speed at zero whatever the pins did before it (Baumgarte aside: its rows aim
    // at a speed that removes the error).
    for (PositionSolver solver :
         {PositionSolver::PseudoVelocity, PositionSolver::ModifiedNGS, PositionSolver::FullNGS}) {
        SCOPED_TRACE(positionSolverName(solver));
        Wheels w(solver, true);
        w.world.setBodyAngularVelocity(w.small, 5.0f);
        for (int i = 0; i < 10; ++i) {
            w.world.step(kDt, 1, 3);
            const float base = w.world.bodyAngularVelocity(w.base);
            const float speed = (w.world.bodyAngularVelocity(w.small) - base) +
                                2.0f * (w.world.bodyAngularVelocity(w.big) - base);
            ASSERT_NEAR(speed, 0.0f, 1e-4f) << "step " << i;
        }
        EXPECT_LT(w.world.jointSeparation(w.gear), 1e-3f);
    }
}

TEST(GearJoint, AGearedMechanismAtRestSleepsAndItsSettersWakeIt) {
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        RackAndPinion r(solver);
        r.world.setPrismaticJointLimit(r.slide, {true, -0.5f, 0.5f});
        for (int i = 0; i < 300; ++i) r.world.step(kDt);  // falls onto the limit and stops
        EXPECT_NEAR(r.world.jointTranslation(r.slide), -0.5f, 0.01f);
        EXPECT_FALSE(r.world.isBodyAwake(r.rack));
        EXPECT_FALSE(r.world.isBodyAwake(r.pinion));
        EXPECT_LT(r.world.jointSeparation(r.gear), 1e-3f);
        r.world.setGearJointRatio(r.gear, -1.0f);
        EXPECT_TRUE(r.world.isBodyAwake(r.rack));
        EXPECT_TRUE(r.world.isBodyAwake(r.pinion));
    }
}

TEST(GearJoint, ChangingTheRatioKeepsThePresentErrorAndDrivesTheNewRatio) {
    Wheels w(PositionSolver::FullNGS);
    for (int i = 0; i < 30; ++i) w.world.step(kDt);
    const float before = w.world.jointSeparation(w.gear);
    w.world.setGearJointRatio(w.gear, 4.0f);
    EXPECT_EQ(w.world.gearJointRatio(w.gear), 4.0f);
    EXPECT_NEAR(w.world.jointSeparation(w.gear), before, 1e-6f);
    for (int i = 0; i < 60; ++i) w.world.step(kDt);
    EXPECT_NEAR(w.world.bodyAngularVelocity(w.big), -w.world.bodyAngularVelocity(w.small) / 4,
                1e-3f);
}

TEST(GearJoint, DestroyingACoupledJointIsRefusedButDestroyingItsBodyTakesTheGearAlong) {
    Wheels w(PositionSolver::FullNGS);
    const std::uint64_t hash = w.world.stateHash();
    try {
        w.world.destroyJoint(w.pin1);
        ADD_FAILURE() << "destroyed a joint a gear is built on";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("gear joint(s) built on it; destroy them first"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(w.world.stateHash(), hash);

    // Destroying the gear first frees the joint.
    Wheels v(PositionSolver::FullNGS);
    v.world.destroyJoint(v.gear);
    v.world.destroyJoint(v.pin1);
    EXPECT_EQ(v.world.jointCount(), 1);

    // The big wheel's body goes, with its pin and the gear built on it; the other pin stays.
    w.world.destroyBody(w.big);
    EXPECT_FALSE(w.world.isValid(w.gear));
    EXPECT_FALSE(w.world.isValid(w.pin2));
    EXPECT_TRUE(w.world.isValid(w.pin1));
    w.world.destroyJoint(w.pin1);  // nothing is built on it any more
    EXPECT_EQ(w.world.jointCount(), 0);
    for (int i = 0; i < 10; ++i) w.world.step(kDt);

    // The base goes: both pins and the gear with them.
    Wheels u(PositionSolver::FullNGS);
    u.world.destroyBody(u.base);
    EXPECT_EQ(u.world.jointCount(), 0);
    for (int i = 0; i < 10; ++i) u.world.step(kDt);
}

TEST(GearJoint, ALetGoPinStillLeavesTheGearItsBodies) {
    // The gear reaches its bases itself: with its pins let go it still turns the wheels in its
    // ratio (they fall, but together).
    for (PositionSolver solver : kSolvers) {
        SCOPED_TRACE(positionSolverName(solver));
        Wheels w(solver);
        w.world.setJointLetGoSeparation(w.pin1, 1e-9f);
        w.world.setJointLetGoSeparation(w.pin2, 1e-9f);
        w.world.setBodyTransform(w.small, {-1, 0.5f}, 0);
        w.world.setBodyTransform(w.big, {2, 0.5f}, 0);
        w.world.setBodyAngularVelocity(w.small, 3.0f);
        for (int i = 0; i < 30; ++i) w.world.step(kDt);
        EXPECT_TRUE(w.world.isJointLetGo(w.pin1));
        EXPECT_TRUE(w.world.isJointLetGo(w.pin2));
        EXPECT_FALSE(w.world.isJointLetGo(w.gear));
        EXPECT_LT(w.world.jointSeparation(w.gear), 1e-3f);
        EXPECT_NEAR(w.world.bodyAngularVelocity(w.big), -w.world.bodyAngularVelocity(w.small) / 2,
                    1e-3f);
    }
}

TEST(GearJoint, ABaseOnlyALetGoJointConnectsIsStillInTheGearsIsland) {
    // The base of joint2 is a dynamic body created last, so the step starts its island search
    // there; with joint2 let go, only that joint still ties the base to the gear's island.
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId wheel1 = disc(world, {0, 0}, 1.0f);
    BodyId wheel2 = disc(world, {3, 0}, 2.0f);
    BodyDef plateDef;
    plateDef.type = BodyType::Dynamic;
    plateDef.position = {3, 0};
    BodyId plate = world.createBody(plateDef);
    ShapeDef apart;
    apart.filter.groupIndex = -1;  // the plate sits inside wheel2
    world.createShape(plate, apart, Polygon::box(0.5f, 0.5f));
    world.setShapeFilter(world.bodyShapes(wheel2)[0], apart.filter);
    JointId pin1 = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, wheel1, {0, 0}));
    RevoluteJointDef axle = RevoluteJointDef::atWorldAnchor(plate, wheel2, {3, 0});
    axle.letGoSeparation = 1e-9f;
    JointId pin2 = world.createJoint(axle);
    GearJointDef gd;
    gd.joint1 = pin1;
    gd.joint2 = pin2;
    gd.ratio = 2.0f;
    JointId gear = world.createJoint(gd);
    world.setBodyAngularVelocity(wheel1, 3.0f);
    world.setBodyTransform(wheel2, {3, 0.5f}, 0);  // the axle comes apart at the first step
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        ASSERT_TRUE(std::isfinite(world.jointSeparation(gear))) << "step " << i;
        for (const JointLetGoEvent& e : world.jointLetGoEvents()) {
            ASSERT_EQ(e.joint, pin2) << "step " << i;
            ASSERT_TRUE(std::isfinite(e.separation)) << "step " << i;
        }
    }
    EXPECT_TRUE(world.isJointLetGo(pin2));
    EXPECT_FALSE(world.isJointLetGo(gear));
    EXPECT_LT(world.jointSeparation(gear), 1e-3f);
    EXPECT_EQ(world.lastStepStats().islandCount, 1);
}

TEST(GearJoint, ABaseJoinedOnlyToAStaticBodyIsStillInTheGearsIsland) {
    // joint2 turns a static B about a dynamic base D, created last so that the island search
    // starts at D. D reaches joint2 and the static B, which joins nothing; only the gear, which
    // D's own joint list does not hold, ties D to wheel1's island. (The fuzz found D's slot
    // pointing into another island.)
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    BodyId wheel1 = disc(world, {0, 0}, 1.0f);
    BodyDef postDef;
    postDef.position = {3, 0};
    BodyId post = world.createBody(postDef);  // static: joint2's body B, the gear's B
    BodyId base = disc(world, {3, 0}, 0.5f);  // joint2's body A: the gear's D
    JointId pin1 = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, wheel1, {0, 0}));
    JointId pin2 = world.createJoint(RevoluteJointDef::atWorldAnchor(base, post, {3, 0}));
    GearJointDef gd;
    gd.joint1 = pin1;
    gd.joint2 = pin2;
    gd.ratio = 2.0f;
    JointId gear = world.createJoint(gd);
    world.setBodyAngularVelocity(wheel1, 3.0f);
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.lastStepStats().islandCount, 1) << "step " << i;
        ASSERT_TRUE(std::isfinite(world.jointSeparation(gear))) << "step " << i;
    }
    // The gear turns the base about the fixed post as wheel1 turns: joint2's angle is minus
    // its base's, so wheel1's angle + 2 (post - base angle) stays what it was, 0.
    EXPECT_LT(world.jointSeparation(gear), 1e-3f);
    EXPECT_GT(std::fabs(world.bodyAngle(base)), 0.1f);
}

TEST(GearJoint, BadInputIsRefusedAndChangesNothing) {
    RackAndPinion r(PositionSolver::FullNGS);
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
    GearJointDef def;
    def.joint1 = r.pin;
    def.joint2 = r.slide;
    for (float ratio : {0.0f, 1e-3f, -1e3f, std::nanf(""), INFINITY, 1e-40f}) {
        def.ratio = ratio;
        expectRefused([&] { world.createJoint(def); }, "def.ratio must be in [kMinGearRatio");
    }
    def.ratio = 1.0f;
    def.biasFactor = 2.0f;
    expectRefused([&] { world.createJoint(def); }, "def.biasFactor");
    def.biasFactor.reset();
    def.joint2 = r.pin;
    expectRefused([&] { world.createJoint(def); }, "the same joint");
    def.joint2 = r.gear;
    expectRefused([&] { world.createJoint(def); },
                  "def.joint2 is a gear joint; a gear couples revolute and prismatic joints");
    def.joint2 = JointId{};
    expectRefused([&] { world.createJoint(def); }, "def.joint2");
    World other{oneSubstepDef()};
    BodyId ground = other.createBody(BodyDef{});
    BodyId wheel = disc(other, {0, 0}, 1.0f);
    def.joint2 = other.createJoint(RevoluteJointDef::atWorldAnchor(ground, wheel, {0, 0}));
    expectRefused([&] { world.createJoint(def); }, "def.joint2");
    // Two joints that move one body.
    JointId second = world.createJoint(RevoluteJointDef::atWorldAnchor(r.ground, r.pinion, {0, 5}));
    const std::uint64_t withSecond = world.stateHash();
    def.joint2 = second;
    try {
        world.createJoint(def);
        ADD_FAILURE() << "accepted a gear joining a body to itself";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("move the same body"), std::string::npos);
    }
    EXPECT_EQ(world.stateHash(), withSecond);
    world.destroyJoint(second);
    // Two joints that move static bodies.
    {
        World statics{oneSubstepDef()};
        BodyId base = disc(statics, {0, 0}, 1.0f);
        BodyId s1 = statics.createBody(BodyDef{});
        BodyId s2 = statics.createBody(BodyDef{});
        GearJointDef both;
        both.joint1 = statics.createJoint(RevoluteJointDef::atWorldAnchor(base, s1, {0, 0}));
        both.joint2 = statics.createJoint(RevoluteJointDef::atWorldAnchor(base, s2, {0, 0}));
        try {
            statics.createJoint(both);
            ADD_FAILURE() << "accepted a gear between two static bodies";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("both move a static body"), std::string::npos);
        }
    }
    // The typed calls refuse other types, and other types' calls refuse a gear.
    const std::uint64_t after = world.stateHash();
    try {
        world.gearJointRatio(r.pin);
        ADD_FAILURE() << "accepted a revolute joint";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("this call is for gear joints"), std::string::npos);
    }
    try {
        world.setGearJointRatio(r.gear, 0.0f);
        ADD_FAILURE() << "accepted a zero ratio";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ratio must be in"), std::string::npos);
    }
    try {
        world.jointMotor(r.gear);
        ADD_FAILURE() << "accepted a gear";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is a gear joint"), std::string::npos);
    }
    EXPECT_EQ(world.stateHash(), after);
}
