// Every World call that changes the world, each made with valid arguments on a world that holds
// one of everything: what the tests of who may change a world, and when, go through
// (access_test.cpp). WorldAccess.EveryChangingCallIsListed checks this list against
// include/pivot/world.h, so a new setter cannot be left out of those tests.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::test_support {

/// The ids of one of everything, in a world built by buildEverything.
struct Everything {
    BodyId ground, resting, a, b, c, d, spare, kinematic;
    ShapeId groundShape, shapeA, shapeB;
    JointId revolute, prismatic, gear, distance, pulley, friction, motor, weld, wheel;
    MouseJointId mouse;
    std::vector<std::uint8_t> snapshot;  // of the world as built
};

inline BodyId dynamicCircleAt(World& world, Vec2 position, float radius) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Circle{{}, radius});
    return body;
}

/// A ground box whose top is y = 0 that asks pre-solve about its contacts, with a ball resting
/// on it (so that the step callbacks run from the second step); bodies a, b, c, d; a spare dynamic
/// body with nothing on it; a kinematic box; a joint of every type, the gear on the revolute and
/// prismatic ones; a mouse joint on c.
inline Everything buildEverything(World& world) {
    Everything e;
    e.ground = world.createBody(BodyDef{});
    ShapeDef asking;
    asking.enablePreSolve = true;
    e.groundShape =
        world.createShape(e.ground, asking, Polygon::box(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    e.resting = dynamicCircleAt(world, {-3.0f, 0.25f}, 0.25f);
    e.a = dynamicCircleAt(world, {0.0f, 1.5f}, 0.5f);
    e.shapeA = world.bodyShapes(e.a)[0];
    e.b = dynamicCircleAt(world, {3.0f, 2.0f}, 0.25f);
    e.shapeB = world.bodyShapes(e.b)[0];
    e.c = dynamicCircleAt(world, {6.0f, 3.0f}, 0.25f);
    e.d = dynamicCircleAt(world, {9.0f, 3.0f}, 0.25f);
    BodyDef spare;
    spare.type = BodyType::Dynamic;
    spare.position = {-6.0f, 5.0f};
    e.spare = world.createBody(spare);
    BodyDef kinematic;
    kinematic.type = BodyType::Kinematic;
    kinematic.position = {-10.0f, 4.0f};
    e.kinematic = world.createBody(kinematic);
    world.createShape(e.kinematic, ShapeDef{}, Polygon::box(0.5f, 0.5f));

    e.revolute = world.createJoint(RevoluteJointDef::atWorldAnchor(e.ground, e.a, {0.0f, 1.0f}));
    e.prismatic = world.createJoint(
        PrismaticJointDef::atWorldAnchor(e.ground, e.b, {3.0f, 2.0f}, {0.0f, 1.0f}));
    GearJointDef gear;
    gear.joint1 = e.revolute;
    gear.joint2 = e.prismatic;
    e.gear = world.createJoint(gear);
    DistanceJointDef distance;
    distance.bodyA = e.b;
    distance.bodyB = e.c;
    e.distance = world.createJoint(distance);
    PulleyJointDef pulley;
    pulley.bodyA = e.c;
    pulley.bodyB = e.d;
    pulley.groundAnchorA = {6.0f, 6.0f};
    pulley.groundAnchorB = {9.0f, 6.0f};
    e.pulley = world.createJoint(pulley);
    FrictionJointDef friction;
    friction.bodyA = e.ground;
    friction.bodyB = e.c;
    e.friction = world.createJoint(friction);
    MotorJointDef motor;
    motor.bodyA = e.ground;
    motor.bodyB = e.d;
    e.motor = world.createJoint(motor);
    e.weld = world.createJoint(WeldJointDef::atWorldAnchor(e.c, e.d, {7.5f, 3.0f}));
    e.wheel = world.createJoint(WheelJointDef::atWorldAnchor(e.b, e.d, {9.0f, 3.0f}, {0.0f, 1.0f}));
    MouseJointDef mouse;
    mouse.body = e.c;
    mouse.target = {6.0f, 3.0f};
    e.mouse = world.createMouseJoint(mouse);
    e.snapshot = world.snapshot();
    return e;
}

/// A call that changes the world: its name in world.h, whether it changes the world's structure
/// (WorldAccess::Change::Structure in src/world/world_access.h: refused during a query's callback
/// too), and the call with valid arguments.
struct ChangingCall {
    std::string name;
    bool structure;
    std::function<void(World&, const Everything&)> make;
};

inline const std::vector<ChangingCall>& everyChangingCall() {
    using W = World;
    using E = Everything;
    static const std::vector<ChangingCall> calls = {
        // The world.
        {"step", true, [](W& w, const E&) { w.step(1.0f / 60.0f); }},
        {"restore", true, [](W& w, const E& e) { w.restore(e.snapshot); }},
        {"setGravity", false, [](W& w, const E&) { w.setGravity({0.0f, -5.0f}); }},
        {"setSubstepCount", false, [](W& w, const E&) { w.setSubstepCount(2); }},
        {"setIterations", false, [](W& w, const E&) { w.setIterations(4, 2); }},
        {"setContactCorrection", false,
         [](W& w, const E&) { w.setContactCorrection(ContactCorrection::Baumgarte); }},
        {"setSleepEnabled", false, [](W& w, const E&) { w.setSleepEnabled(false); }},
        {"setContinuousEnabled", false, [](W& w, const E&) { w.setContinuousEnabled(false); }},
        {"setContinuousCollision", false,
         [](W& w, const E&) { w.setContinuousCollision(ContinuousCollision::FastBodies); }},
        {"setHitEventThreshold", false, [](W& w, const E&) { w.setHitEventThreshold(2.0f); }},
        {"setPreSolveCallback", false, [](W& w, const E&) { w.setPreSolveCallback(nullptr); }},
        {"setCustomFilterCallback", false,
         [](W& w, const E&) { w.setCustomFilterCallback(nullptr); }},
        // Bodies.
        {"createBody", true, [](W& w, const E&) { w.createBody(BodyDef{}); }},
        {"destroyBody", true, [](W& w, const E& e) { w.destroyBody(e.spare); }},
        {"setBodyType", true, [](W& w, const E& e) { w.setBodyType(e.a, BodyType::Kinematic); }},
        {"setBodyTransform", true,
         [](W& w, const E& e) { w.setBodyTransform(e.spare, {-6.0f, 6.0f}, 0.5f); }},
        {"setBodyAwake", false, [](W& w, const E& e) { w.setBodyAwake(e.b, false); }},
        {"setBodySleepAllowed", false, [](W& w, const E& e) { w.setBodySleepAllowed(e.b, false); }},
        {"setBodyLinearDamping", false,
         [](W& w, const E& e) { w.setBodyLinearDamping(e.b, 0.5f); }},
        {"setBodyAngularDamping", false,
         [](W& w, const E& e) { w.setBodyAngularDamping(e.b, 0.5f); }},
        {"setBodyGravityScale", false, [](W& w, const E& e) { w.setBodyGravityScale(e.b, 0.5f); }},
        {"setBodyFixedRotation", false,
         [](W& w, const E& e) { w.setBodyFixedRotation(e.b, true); }},
        {"setBodyContinuous", false, [](W& w, const E& e) { w.setBodyContinuous(e.b, false); }},
        {"setBodyBullet", false, [](W& w, const E& e) { w.setBodyBullet(e.b, true); }},
        {"setBodyUserData", false, [](W& w, const E& e) { w.setBodyUserData(e.b, 7); }},
        {"setBodyLinearVelocity", false,
         [](W& w, const E& e) { w.setBodyLinearVelocity(e.b, {1.0f, 0.0f}); }},
        {"setBodyAngularVelocity", false,
         [](W& w, const E& e) { w.setBodyAngularVelocity(e.b, 1.0f); }},
        {"applyForce", false,
         [](W& w, const E& e) { w.applyForce(e.b, {1.0f, 0.0f}, {3.0f, 2.5f}); }},
        {"applyForceToCenter", false,
         [](W& w, const E& e) { w.applyForceToCenter(e.b, {1.0f, 0.0f}); }},
        {"applyTorque", false, [](W& w, const E& e) { w.applyTorque(e.b, 1.0f); }},
        {"applyLinearImpulse", false,
         [](W& w, const E& e) { w.applyLinearImpulse(e.b, {1.0f, 0.0f}, {3.0f, 2.5f}); }},
        {"applyAngularImpulse", false, [](W& w, const E& e) { w.applyAngularImpulse(e.b, 0.1f); }},
        // Shapes.
        {"createShape", true,
         [](W& w, const E& e) { w.createShape(e.b, ShapeDef{}, Circle{{0.5f, 0.0f}, 0.1f}); }},
        {"createShape(Polygon)", true,
         [](W& w, const E& e) { w.createShape(e.b, ShapeDef{}, Polygon::box(0.1f, 0.1f)); }},
        {"createShape(Capsule)", true,
         [](W& w, const E& e) {
             w.createShape(e.b, ShapeDef{}, Capsule{{0.0f, 0.0f}, {0.2f, 0.0f}, 0.1f});
         }},
        {"createShape(Segment)", true,
         [](W& w, const E& e) {
             w.createShape(e.ground, ShapeDef{}, Segment{{-5.0f, 1.0f}, {-4.0f, 1.0f}});
         }},
        {"createShape(ChainSegment)", true,
         [](W& w, const E& e) {
             w.createShape(e.ground, ShapeDef{},
                           ChainSegment{{-6.0f, 1.0f}, {{-5.0f, 1.0f}, {-4.0f, 1.0f}}, {-3.0f, 1.0f}});
         }},
        {"createChain", true,
         [](W& w, const E& e) {
             w.createChain(e.ground, ShapeDef{},
                           Chain{{{-6.0f, 1.0f}, {-5.0f, 1.0f}, {-4.0f, 1.0f}, {-3.0f, 1.0f}}});
         }},
        {"destroyShape", true, [](W& w, const E& e) { w.destroyShape(e.shapeB); }},
        {"setShapeSensor", true, [](W& w, const E& e) { w.setShapeSensor(e.shapeB, true); }},
        {"setShapeDensity", false, [](W& w, const E& e) { w.setShapeDensity(e.shapeB, 2.0f); }},
        {"setShapeFriction", false, [](W& w, const E& e) { w.setShapeFriction(e.shapeB, 0.3f); }},
        {"setShapeRestitution", false,
         [](W& w, const E& e) { w.setShapeRestitution(e.shapeB, 0.2f); }},
        {"setShapeFilter", false,
         [](W& w, const E& e) { w.setShapeFilter(e.shapeB, Filter{0x0002, 0xFFFF, 0}); }},
        {"setShapeHitEventsEnabled", false,
         [](W& w, const E& e) { w.setShapeHitEventsEnabled(e.shapeB, true); }},
        {"setShapePreSolveEnabled", false,
         [](W& w, const E& e) { w.setShapePreSolveEnabled(e.shapeB, true); }},
        {"setShapeUserData", false, [](W& w, const E& e) { w.setShapeUserData(e.shapeB, 9); }},
        // Joints.
        {"createJoint", true,
         [](W& w, const E& e) {
             w.createJoint(RevoluteJointDef::atWorldAnchor(e.c, e.spare, {-6.0f, 5.0f}));
         }},
        {"createJoint(Distance)", true,
         [](W& w, const E& e) {
             DistanceJointDef def;
             def.bodyA = e.a;
             def.bodyB = e.spare;
             w.createJoint(def);
         }},
        {"createJoint(Pulley)", true,
         [](W& w, const E& e) {
             PulleyJointDef def;
             def.bodyA = e.a;
             def.bodyB = e.spare;
             def.groundAnchorA = {0.0f, 8.0f};
             def.groundAnchorB = {-6.0f, 8.0f};
             w.createJoint(def);
         }},
        {"createJoint(Friction)", true,
         [](W& w, const E& e) {
             FrictionJointDef def;
             def.bodyA = e.a;
             def.bodyB = e.spare;
             w.createJoint(def);
         }},
        {"createJoint(Motor)", true,
         [](W& w, const E& e) {
             MotorJointDef def;
             def.bodyA = e.a;
             def.bodyB = e.spare;
             w.createJoint(def);
         }},
        {"createJoint(Prismatic)", true,
         [](W& w, const E& e) {
             w.createJoint(
                 PrismaticJointDef::atWorldAnchor(e.a, e.spare, {-6.0f, 5.0f}, {1.0f, 0.0f}));
         }},
        {"createJoint(Weld)", true,
         [](W& w, const E& e) {
             w.createJoint(WeldJointDef::atWorldAnchor(e.a, e.spare, {-6.0f, 5.0f}));
         }},
        {"createJoint(Wheel)", true,
         [](W& w, const E& e) {
             w.createJoint(WheelJointDef::atWorldAnchor(e.a, e.spare, {-6.0f, 5.0f}, {0.0f, 1.0f}));
         }},
        {"createJoint(Gear)", true,
         [](W& w, const E& e) {
             GearJointDef def;
             def.joint1 = e.revolute;
             def.joint2 = e.prismatic;
             def.ratio = 2.0f;
             w.createJoint(def);
         }},
        {"destroyJoint", true, [](W& w, const E& e) { w.destroyJoint(e.distance); }},
        {"rearmJoint", false, [](W& w, const E& e) { w.rearmJoint(e.distance); }},
        {"setJointCollideConnected", false,
         [](W& w, const E& e) { w.setJointCollideConnected(e.distance, true); }},
        {"setJointLetGoSeparation", false,
         [](W& w, const E& e) { w.setJointLetGoSeparation(e.distance, 1.0f); }},
        {"setJointBreakForce", false,
         [](W& w, const E& e) { w.setJointBreakForce(e.distance, 100.0f); }},
        {"setJointBreakTorque", false,
         [](W& w, const E& e) { w.setJointBreakTorque(e.distance, 100.0f); }},
        {"setJointPositionSolver", false,
         [](W& w, const E& e) { w.setJointPositionSolver(e.distance, PositionSolver::Baumgarte); }},
        {"setJointBiasFactor", false,
         [](W& w, const E& e) { w.setJointBiasFactor(e.distance, 0.5f); }},
        {"setJointExtraPositionIterations", false,
         [](W& w, const E& e) { w.setJointExtraPositionIterations(e.distance, 2); }},
        {"setJointSoftness", false,
         [](W& w, const E& e) { w.setJointSoftness(e.distance, JointSoftness{30.0f, 1.0f, 0.0f}); }},
        {"setJointUserData", false, [](W& w, const E& e) { w.setJointUserData(e.distance, 3); }},
        {"setJointLimit", false,
         [](W& w, const E& e) { w.setJointLimit(e.revolute, JointLimit{true, -1.0f, 1.0f}); }},
        {"setJointMotor", false,
         [](W& w, const E& e) { w.setJointMotor(e.revolute, JointMotor{true, 1.0f, 10.0f}); }},
        {"setDistanceJointRestLength", false,
         [](W& w, const E& e) { w.setDistanceJointRestLength(e.distance, 1.5f); }},
        {"setDistanceJointLimit", false,
         [](W& w, const E& e) {
             w.setDistanceJointLimit(e.distance, LengthLimit{true, 0.5f, 5.0f});
         }},
        {"setDistanceJointSpring", false,
         [](W& w, const E& e) {
             w.setDistanceJointSpring(e.distance, JointSpring{true, 2.0f, 0.5f});
         }},
        {"setPrismaticJointLimit", false,
         [](W& w, const E& e) {
             w.setPrismaticJointLimit(e.prismatic, TranslationLimit{true, -1.0f, 1.0f});
         }},
        {"setPrismaticJointMotor", false,
         [](W& w, const E& e) {
             w.setPrismaticJointMotor(e.prismatic, LinearMotor{true, 1.0f, 10.0f});
         }},
        {"setPrismaticJointSpring", false,
         [](W& w, const E& e) {
             w.setPrismaticJointSpring(e.prismatic, JointSpring{true, 2.0f, 0.5f});
         }},
        {"setWheelJointSpring", false,
         [](W& w, const E& e) { w.setWheelJointSpring(e.wheel, JointSpring{true, 2.0f, 0.5f}); }},
        {"setWheelJointLimit", false,
         [](W& w, const E& e) {
             w.setWheelJointLimit(e.wheel, TranslationLimit{true, -1.0f, 1.0f});
         }},
        {"setGearJointRatio", false, [](W& w, const E& e) { w.setGearJointRatio(e.gear, 2.0f); }},
        {"setWeldJointLinearSpring", false,
         [](W& w, const E& e) {
             w.setWeldJointLinearSpring(e.weld, JointSpring{true, 2.0f, 0.5f});
         }},
        {"setWeldJointAngularSpring", false,
         [](W& w, const E& e) {
             w.setWeldJointAngularSpring(e.weld, JointSpring{true, 2.0f, 0.5f});
         }},
        {"setJointMaxForce", false, [](W& w, const E& e) { w.setJointMaxForce(e.friction, 1.0f); }},
        {"setJointMaxTorque", false,
         [](W& w, const E& e) { w.setJointMaxTorque(e.friction, 1.0f); }},
        {"setMotorJointLinearOffset", false,
         [](W& w, const E& e) { w.setMotorJointLinearOffset(e.motor, {1.0f, 0.0f}); }},
        {"setMotorJointAngularOffset", false,
         [](W& w, const E& e) { w.setMotorJointAngularOffset(e.motor, 0.5f); }},
        {"setMotorJointCorrectionFactor", false,
         [](W& w, const E& e) { w.setMotorJointCorrectionFactor(e.motor, 0.5f); }},
        // Mouse joints.
        {"createMouseJoint", true,
         [](W& w, const E& e) {
             MouseJointDef def;
             def.body = e.b;
             def.target = {3.0f, 2.0f};
             w.createMouseJoint(def);
         }},
        {"destroyMouseJoint", true, [](W& w, const E& e) { w.destroyMouseJoint(e.mouse); }},
        {"setMouseTarget", false, [](W& w, const E& e) { w.setMouseTarget(e.mouse, {6.0f, 4.0f}); }},
        {"setMouseJointMaxForce", false,
         [](W& w, const E& e) { w.setMouseJointMaxForce(e.mouse, 10.0f); }},
        {"setMouseJointSpring", false,
         [](W& w, const E& e) { w.setMouseJointSpring(e.mouse, 3.0f, 0.5f); }},
    };
    return calls;
}

}  // namespace pivot::test_support
