// A tumbler, after Box2D's testbed: a 20 m square box of four walls (density 5) pinned at its
// centre to the ground by a revolute joint with the scene's position solver, turned at
// 0.05 pi rad/s by a drive torque, with 200 small boxes (0.5 m, density 1) tumbling inside.
// The pin carries the box and its load while hundreds of contacts come and go.
#include <cmath>

#include "scene.h"

namespace pivot::scenes {

void buildTumbler(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 center{0.0f, 10.0f};
    const float turnRate = 0.05f * kPi;

    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = center;
    def.allowSleep = false;
    BodyId drum = world.createBody(def);
    ShapeDef wall;
    wall.density = 5.0f;
    world.createShape(drum, wall, Polygon::box(0.5f, 10.0f, {10.0f, 0.0f}, 0.0f));
    world.createShape(drum, wall, Polygon::box(0.5f, 10.0f, {-10.0f, 0.0f}, 0.0f));
    world.createShape(drum, wall, Polygon::box(10.0f, 0.5f, {0.0f, 10.0f}, 0.0f));
    world.createShape(drum, wall, Polygon::box(10.0f, 0.5f, {0.0f, -10.0f}, 0.0f));
    scene.bodies.push_back(drum);
    scene.joints.push_back(world.createJoint(options.jointAt(ground, drum, center)));

    ShapeDef small;
    small.density = 1.0f;
    const Polygon box = Polygon::box(0.25f, 0.25f);
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 20; ++j) {
            BodyDef bd;
            bd.type = BodyType::Dynamic;
            bd.position = center + Vec2{-7.0f + 0.7f * static_cast<float>(j),
                                        -8.0f + 0.7f * static_cast<float>(i)};
            BodyId body = world.createBody(bd);
            world.createShape(body, small, box);
            scene.bodies.push_back(body);
        }
    }

    // A drive standing in for a motor: the torque that reaches the turn rate in one step,
    // whatever the load, up to the largest torque the API takes (a drum knocked to a wild spin,
    // as a strategy that diverges can, is brought back over several steps).
    const float hz = options.hz;
    scene.beforeStep = [drum, turnRate, hz](Scene& s, int) {
        World& w = *s.world;
        float inertia = w.bodyRotationalInertia(drum);
        float torque = inertia * (turnRate - w.bodyAngularVelocity(drum)) * hz;
        w.applyTorque(drum, std::fmax(-kMaxMagnitude, std::fmin(torque, kMaxMagnitude)));
    };
}

}  // namespace pivot::scenes
