// A motor driving a wheel against gravity: a 2 m disc (density 1) with a heavy 0.4 m weight
// (density 20) fixed 0.7 m off its centre, pinned at the centre to the ground. The motor aims at
// 2 rad/s with at most 30 N m: enough to lift the weight (about 18 N m at worst), so the wheel
// turns steadily, slowing as it lifts and speeding up as it lowers.
#include "scene.h"

namespace pivot::scenes {

void buildMotorWheel(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 center{0.0f, 5.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = center;
    BodyId wheel = world.createBody(def);
    world.createShape(wheel, ShapeDef{}, Circle{{0.0f, 0.0f}, 1.0f});
    ShapeDef weight;
    weight.density = 20.0f;
    world.createShape(wheel, weight, Circle{{0.7f, 0.0f}, 0.2f});
    RevoluteJointDef jd = options.jointAt(ground, wheel, center);
    jd.motor = {true, 2.0f, 30.0f};
    scene.bodies.push_back(wheel);
    scene.joints.push_back(world.createJoint(jd));
}

}  // namespace pivot::scenes
