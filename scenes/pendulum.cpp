// The seed note's simple pendulum: "1m diameter sphere on a massless 5m stick with an initial
// angular velocity of 100 rad/s". The stick is the joint itself: a revolute joint to the
// static ground whose anchor is 5 m from the ball's centre. The ball hangs below the pivot and
// moves as a rigid body turning about it, so v = w x r = 500 m/s; at 60 Hz that is 8.3 m per
// step, beyond kMaxTranslation (2 m), so the first steps are clamped.
#include "scene.h"

namespace pivot::scenes {

void buildPendulum(Scene& scene, const SceneOptions& options) {
    buildSpinningPendulum(scene, options, 100.0f);
}

// Spun at 20 rad/s the ball moves 100 m/s, 1.7 m and a third of a radian per step at 60 Hz:
// inside kMaxTranslation (2 m) and kMaxRotation (a quarter turn), so no clamp acts and what the
// joint does is the solver's alone.
void buildSlowPendulum(Scene& scene, const SceneOptions& options) {
    buildSpinningPendulum(scene, options, 20.0f);
}

namespace {
// The ball: 1 m across, hanging 5 m below `pivot` and turning about it at `spin`.
BodyId spinningBall(World& world, Vec2 pivot, float spin) {
    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = pivot + Vec2{0.0f, -5.0f};
    ballDef.angularVelocity = spin;
    ballDef.linearVelocity = cross(spin, ballDef.position - pivot);
    BodyId ball = world.createBody(ballDef);
    ShapeDef shape;
    shape.density = 1.0f;
    world.createShape(ball, shape, Circle{{0.0f, 0.0f}, 0.5f});
    return ball;
}
}  // namespace

void buildSpinningPendulum(Scene& scene, const SceneOptions& options, float spin) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyId ball = spinningBall(world, pivot, spin);
    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(options.jointAt(ground, ball, pivot)));
}

namespace {
// The ball spun at 100 rad/s on a 5 m distance joint from the pivot to `anchorOnBall`.
void buildRodPendulum(Scene& scene, const SceneOptions& options, Vec2 anchorOnBall) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyId ball = spinningBall(world, pivot, 100.0f);
    DistanceJointDef jd = options.distanceJoint(ground, ball);
    jd.localAnchorA = pivot;
    jd.localAnchorB = anchorOnBall;
    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(jd));
}
}  // namespace

// The pendulum with the stick made a distance joint: the ball's centre is held 5 m from the
// pivot. Where the revolute joint's pin is a 2x2 block, the rod is one scalar row along the
// stick, the shape of constraint for which the note wonders whether Modified NGS is viable.
void buildDistancePendulum(Scene& scene, const SceneOptions& options) {
    buildRodPendulum(scene, options, {0.0f, 0.0f});
}

// The rod tied to the ball's rim, a quarter turn round from the pivot's side: the row's lever arm
// on the ball (rB x u) is half a metre at the start and changes as the ball turns against the rod,
// so its effective mass changes with the pose, which the centred rod's never does.
void buildOffsetDistancePendulum(Scene& scene, const SceneOptions& options) {
    buildRodPendulum(scene, options, {0.5f, 0.0f});
}

}  // namespace pivot::scenes

// The pendulum with an angle limit: the ball starts level with the pivot, at rest, and swings
// down into the joint's lower limit at -60 degrees, where it stops and rests against it.
namespace pivot::scenes {

void buildLimitedPendulum(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = pivot + Vec2{5.0f, 0.0f};
    BodyId ball = world.createBody(ballDef);
    world.createShape(ball, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
    RevoluteJointDef jd = options.jointAt(ground, ball, pivot);
    jd.limit = {true, -kPi / 3.0f, kPi / 3.0f};
    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(jd));
}

// Two 1 m balls on massless 2.5 m sticks, one hanging from the other, released level from rest:
// the classic chaotic double pendulum.
void buildDoublePendulum(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyId previous = ground;
    Vec2 anchor = pivot;
    for (int i = 1; i <= 2; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = pivot + Vec2{2.5f * static_cast<float>(i), 0.0f};
        BodyId ball = world.createBody(def);
        world.createShape(ball, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
        scene.joints.push_back(world.createJoint(options.jointAt(previous, ball, anchor)));
        scene.bodies.push_back(ball);
        previous = ball;
        anchor = def.position;
    }
}

}  // namespace pivot::scenes
