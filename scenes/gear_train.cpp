// A gear train on a moving carrier, for the Box2D reference comparison (not a table scene: it
// shows the gear joint's arithmetic agreeing with Box2D 2.4.1's, where pulley_gear cannot; see
// docs/reference-agreement.md). A kinematic plate sliding right at 0.5 m/s carries a motorised
// wheel of radius 1, a wheel of radius 2 it meshes with (a gear joint, ratio 2) and a 4 m rack
// on a vertical prismatic joint limited to [-1.5, 1.5] m, driven by the big wheel (a second
// gear, ratio 0.5 rad/m) against its weight. The motor (1 rad/s, at most 100 N m) reverses
// every 4 s, so the rack runs into both limits and is held there through both gears.
//
// The bodies and joints are created in an order for which Box2D's island search meets the
// joints pins first, then the slide, then the gears: the order in which pivot2d groups them,
// so that the two engines solve them in the same sequence.
#include "scene.h"

namespace pivot::scenes {

namespace {
constexpr int kStepsPerReversal = 240;
}

void buildGearTrain(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {-3.0f, 8.0f};
    BodyId small = world.createBody(def);
    world.createShape(small, ShapeDef{}, Circle{{0.0f, 0.0f}, 1.0f});
    def.position = {0.0f, 8.0f};
    BodyId big = world.createBody(def);
    world.createShape(big, ShapeDef{}, Circle{{0.0f, 0.0f}, 2.0f});
    def.position = {2.3f, 8.0f};
    BodyId rack = world.createBody(def);
    world.createShape(rack, ShapeDef{}, Polygon::box(0.2f, 2.0f));
    BodyDef carrierDef;
    carrierDef.type = BodyType::Kinematic;
    carrierDef.position = {0.0f, 8.0f};
    carrierDef.linearVelocity = {0.5f, 0.0f};
    BodyId carrier = world.createBody(carrierDef);

    const auto strategy = [&](auto& jointDef) {
        jointDef.positionSolver = options.solver;
        jointDef.biasFactor = options.biasFactor;
    };
    PrismaticJointDef slide =
        PrismaticJointDef::atWorldAnchor(carrier, rack, {2.3f, 8.0f}, {0.0f, 1.0f});
    slide.limit = {true, -1.5f, 1.5f};
    strategy(slide);
    const JointId shaft = world.createJoint(slide);
    RevoluteJointDef drive = RevoluteJointDef::atWorldAnchor(carrier, small, {-3.0f, 8.0f});
    drive.motor = {true, 1.0f, 100.0f};
    strategy(drive);
    const JointId pin1 = world.createJoint(drive);
    RevoluteJointDef idler = RevoluteJointDef::atWorldAnchor(carrier, big, {0.0f, 8.0f});
    strategy(idler);
    const JointId pin2 = world.createJoint(idler);
    const JointId gear1 = world.createJoint(options.gear(pin1, pin2, 2.0f));
    const JointId gear2 = world.createJoint(options.gear(pin2, shaft, 0.5f));

    scene.bodies = {small, big, rack};
    scene.joints = {shaft, pin1, pin2, gear1, gear2};
    scene.beforeStep = reverseMotorEvery(pin1, kStepsPerReversal);
}

}  // namespace pivot::scenes
