// The seed note's simple pendulum: "1m diameter sphere on a massless 5m stick with an initial
// angular velocity of 100 rad/s". The stick is the joint itself: a revolute joint to the
// static ground whose anchor is 5 m from the ball's centre. The ball hangs below the pivot and
// moves as a rigid body turning about it, so v = w x r = 500 m/s; at 60 Hz that is 8.3 m per
// step, beyond kMaxTranslation (2 m), so the first steps are clamped.
#include "scene.h"

namespace pivot::scenes {

void buildPendulum(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    const float stickLength = 5.0f;
    const float spin = 100.0f;  // rad/s about the pivot

    BodyId ground = world.createBody(BodyDef{});

    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = pivot + Vec2{0.0f, -stickLength};
    ballDef.angularVelocity = spin;
    ballDef.linearVelocity = cross(spin, ballDef.position - pivot);
    BodyId ball = world.createBody(ballDef);
    ShapeDef shape;
    shape.density = 1.0f;
    world.createShape(ball, shape, Circle{{0.0f, 0.0f}, 0.5f});

    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(options.jointAt(ground, ball, pivot)));
}

}  // namespace pivot::scenes
