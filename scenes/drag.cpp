// The seed note's disturbances: "Drag the simple pendulum in a circle quickly and the joint will
// separate", and a chain's free end yanked about. A mouse joint pulls the body point along a
// scripted path, then lets go; the joints' recovery is timed from the release.
#include <cmath>
#include <memory>
#include <stdexcept>

#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

namespace {

// A hand of the given stiffness (Hz) whose force is capped at forcePerKg times the body's mass,
// taking hold of the dynamic body under `point` as a pointer would (the scripted point is on
// the body the scene means; pickedAs checks that the query found it).
MouseJointId grab(World& world, Vec2 point, BodyId pickedAs, float hertz, float forcePerKg) {
    const BodyId body = dynamicBodyAt(world, point);
    if (body != pickedAs) throw std::logic_error("drag: the hand picked another body");
    MouseJointDef def;
    def.body = body;
    def.target = point;
    def.maxForce = forcePerKg * world.bodyMass(body);
    def.hertz = hertz;
    def.dampingRatio = 0.7f;
    return world.createMouseJoint(def);
}

// A circular path whose rate rises linearly from 0 to `finalRate` (rad/s) over `duration`
// seconds: angle(t) = finalRate t^2 / (2 duration).
Vec2 whirl(Vec2 center, float radius, float finalRate, float duration, float t) {
    float angle = 0.5f * finalRate * t * t / duration;
    return center + radius * Vec2{std::sin(angle), -std::cos(angle)};
}

}  // namespace

// The pendulum hangs at rest; from t = 0 the ball is pulled round a 3 m circle about the pivot,
// the rate rising to 4 revolutions per second at t = 3 s, when it is let go. The hand is stiff
// (30 Hz, up to 50000 times the ball's mass in newtons) so the ball really follows: a testbed's
// usual 5 Hz hand loses the target beyond about 1.5 rev/s. Pulled towards a point 3 m from the
// pivot while its joint holds it at 5 m, the ball loads the joint radially as well.
void buildPendulumDrag(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = pivot + Vec2{0.0f, -5.0f};
    BodyId ball = world.createBody(def);
    world.createShape(ball, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(options.jointAt(ground, ball, pivot)));

    const float duration = 3.0f;
    const int release = stepAt(options, duration);
    const float hz = options.hz;
    scene.disturbanceEndStep = release;
    auto mouse = std::make_shared<MouseJointId>();
    scene.beforeStep = [=](Scene& s, int step) {
        World& w = *s.world;
        if (step == 0) *mouse = grab(w, w.bodyWorldCenter(ball), ball, 30.0f, 50000.0f);
        if (step < release) {
            float t = static_cast<float>(step + 1) / hz;
            w.setMouseTarget(*mouse, whirl(pivot, 3.0f, 4.0f * 2.0f * kPi, duration, t));
        } else if (step == release) {
            w.destroyMouseJoint(*mouse);
        }
    };
}

// The chain falls for a second; then its free end is grabbed 0.1 m from its tip (inside the link:
// a point on its outline may test either side of it) by a testbed-like hand (5 Hz, up to 1000
// times the link's mass in newtons), yanked to a 5 m circle about (12, 15) and whirled round
// it at a rate rising to 3 revolutions per second, and let go at t = 4 s.
void buildChainDrag(Scene& scene, const SceneOptions& options) {
    buildChain(scene, options);
    const int grabStep = stepAt(options, 1.0f);
    const int release = stepAt(options, 4.0f);
    const float hz = options.hz;
    const BodyId end = scene.bodies.back();
    scene.disturbanceEndStep = release;
    auto mouse = std::make_shared<MouseJointId>();
    scene.beforeStep = [=](Scene& s, int step) {
        World& w = *s.world;
        if (step == grabStep) {
            *mouse = grab(w, w.bodyWorldPoint(end, {0.5f, 0.0f}), end, 5.0f, 1000.0f);
        }
        if (step >= grabStep && step < release) {
            float t = static_cast<float>(step + 1 - grabStep) / hz;
            w.setMouseTarget(*mouse, whirl({12.0f, 15.0f}, 5.0f, 3.0f * 2.0f * kPi, 3.0f, t));
        } else if (step == release) {
            w.destroyMouseJoint(*mouse);
        }
    };
}

}  // namespace pivot::scenes
