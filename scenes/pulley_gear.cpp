// A pulley and a gear train: a motorised wheel of radius 1 meshes (a gear joint, ratio 2) with a
// wheel of radius 2, which drives (a second gear, ratio 0.5 rad/m) a 4 m rack on a vertical
// prismatic joint limited to [-1.5, 1.5] m; a pulley hangs a counterweight of three times the
// rack's mass from the rack's top, half a metre to the side of its wheel so that it swings. The
// motor (1 rad/s, at most 200 N m) reverses every 4 s: the rack runs into each limit and is
// pressed against it through both gears for a second or more, while the counterweight pulls
// on the rack through the rope. Every joint (pins, slide, gears, pulley) uses the scene's
// position solver.
#include "scene.h"

namespace pivot::scenes {

namespace {
constexpr int kStepsPerReversal = 240;
}

void buildPulleyGear(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyId ground = world.createBody(BodyDef{});
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
    def.position = {6.5f, 5.0f};
    BodyId counterweight = world.createBody(def);
    ShapeDef heavy;
    heavy.density = 4.8f;  // 4.8 kg: three times the rack's 1.6 kg
    world.createShape(counterweight, heavy, Polygon::box(0.5f, 0.5f));

    const auto strategy = [&](auto& jointDef) {
        jointDef.positionSolver = options.solver;
        jointDef.biasFactor = options.biasFactor;
    };
    RevoluteJointDef drive = RevoluteJointDef::atWorldAnchor(ground, small, {-3.0f, 8.0f});
    drive.motor = {true, 1.0f, 200.0f};
    strategy(drive);
    const JointId pin1 = world.createJoint(drive);
    RevoluteJointDef idler = RevoluteJointDef::atWorldAnchor(ground, big, {0.0f, 8.0f});
    strategy(idler);
    const JointId pin2 = world.createJoint(idler);
    PrismaticJointDef slide =
        PrismaticJointDef::atWorldAnchor(ground, rack, {2.3f, 8.0f}, {0.0f, 1.0f});
    slide.limit = {true, -1.5f, 1.5f};
    strategy(slide);
    const JointId shaft = world.createJoint(slide);
    const JointId gear1 = world.createJoint(options.gear(pin1, pin2, 2.0f));
    const JointId gear2 = world.createJoint(options.gear(pin2, shaft, 0.5f));
    PulleyJointDef rope;
    rope.bodyA = rack;
    rope.bodyB = counterweight;
    rope.groundAnchorA = {2.3f, 13.0f};
    rope.groundAnchorB = {6.0f, 13.0f};
    rope.localAnchorA = {0.0f, 2.0f};
    rope.localAnchorB = {0.0f, 0.5f};
    strategy(rope);
    const JointId pulley = world.createJoint(rope);

    scene.bodies = {small, big, rack, counterweight};
    scene.joints = {pin1, pin2, shaft, gear1, gear2, pulley};
    scene.beforeStep = reverseMotorEvery(pin1, kStepsPerReversal);
}

}  // namespace pivot::scenes
