// A ragdoll, the seed note's suggested use of FullNGS ("especially motorized ragdolls where
// joint separation can be problematic"): ten bodies (head, torso, upper and lower arms, thighs,
// shins; density 100) joined by revolute joints with angle limits, thrown at 8.5 m/s and
// spinning against a wall (hit in flight, about 0.7 s after the throw) and onto the ground. Its
// parts never collide with each other (a shared negative filter group). The motorized variant adds
// to every joint a motor holding speed 0 with up to 20 N m, like muscles keeping a pose.
#include "ground.h"
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

namespace {

struct Part {
    Vec2 center;    // standing pose, feet at y = 0
    Vec2 halfSize;  // box half extents; zero for the head
};

struct Hinge {
    int a, b;  // parts
    Vec2 anchor;
    float lower, upper;  // rad
};

void buildRagdollWith(Scene& scene, const SceneOptions& options, bool motorized) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    createGround(world, 0.6f);
    BodyId wall = world.createBody(BodyDef{});
    ShapeDef wallShape;
    wallShape.density = 0.0f;
    world.createShape(wall, wallShape, Polygon::box(0.5f, 5.0f, {5.5f, 5.0f}, 0.0f));

    enum {
        kTorso,
        kHead,
        kUpperArmL,
        kLowerArmL,
        kUpperArmR,
        kLowerArmR,
        kThighL,
        kShinL,
        kThighR,
        kShinR,
        kParts
    };
    const Part parts[kParts] = {
        {{0.0f, 1.25f}, {0.2f, 0.35f}},   {{0.0f, 1.78f}, {0.0f, 0.0f}},
        {{-0.26f, 1.4f}, {0.06f, 0.15f}}, {{-0.26f, 1.1f}, {0.05f, 0.15f}},
        {{0.26f, 1.4f}, {0.06f, 0.15f}},  {{0.26f, 1.1f}, {0.05f, 0.15f}},
        {{-0.1f, 0.7f}, {0.08f, 0.2f}},   {{-0.1f, 0.28f}, {0.07f, 0.22f}},
        {{0.1f, 0.7f}, {0.08f, 0.2f}},    {{0.1f, 0.28f}, {0.07f, 0.22f}},
    };
    const Hinge hinges[] = {
        {kTorso, kHead, {0.0f, 1.63f}, -0.5f, 0.5f},
        {kTorso, kUpperArmL, {-0.26f, 1.55f}, -2.5f, 2.5f},
        {kUpperArmL, kLowerArmL, {-0.26f, 1.25f}, 0.0f, 2.5f},
        {kTorso, kUpperArmR, {0.26f, 1.55f}, -2.5f, 2.5f},
        {kUpperArmR, kLowerArmR, {0.26f, 1.25f}, 0.0f, 2.5f},
        {kTorso, kThighL, {-0.1f, 0.9f}, -1.5f, 0.5f},
        {kThighL, kShinL, {-0.1f, 0.5f}, -2.5f, 0.0f},
        {kTorso, kThighR, {0.1f, 0.9f}, -1.5f, 0.5f},
        {kThighR, kShinR, {0.1f, 0.5f}, -2.5f, 0.0f},
    };

    // Thrown as one rigid body: every part gets the velocity of its point of the whole.
    const Vec2 origin{-2.0f, 2.0f};
    const Vec2 velocity{8.0f, 3.0f};
    const float spin = -3.0f;
    const Vec2 spinCenter = origin + Vec2{0.0f, 1.0f};

    ShapeDef shape;
    shape.density = 100.0f;
    shape.friction = 0.6f;
    shape.filter.groupIndex = -1;
    BodyId bodies[kParts];
    for (int i = 0; i < kParts; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = origin + parts[i].center;
        def.angularVelocity = spin;
        def.linearVelocity = velocity + cross(spin, def.position - spinCenter);
        bodies[i] = world.createBody(def);
        if (i == kHead) {
            world.createShape(bodies[i], shape, Circle{{0.0f, 0.0f}, 0.15f});
        } else {
            world.createShape(bodies[i], shape,
                              Polygon::box(parts[i].halfSize.x, parts[i].halfSize.y));
        }
        scene.bodies.push_back(bodies[i]);
    }
    for (const Hinge& h : hinges) {
        RevoluteJointDef jd = options.jointAt(bodies[h.a], bodies[h.b], origin + h.anchor);
        jd.limit = {true, h.lower, h.upper};
        if (motorized) jd.motor = {true, 0.0f, 20.0f};
        scene.joints.push_back(world.createJoint(jd));
    }
    scene.disturbanceEndStep = stepAt(options, 1.5f);  // hit the wall and the ground by then
    scene.restFromStep = stepAt(options, 5.0f);
}

}  // namespace

void buildRagdoll(Scene& scene, const SceneOptions& options) {
    buildRagdollWith(scene, options, false);
}

void buildMotorizedRagdoll(Scene& scene, const SceneOptions& options) {
    buildRagdollWith(scene, options, true);
}

}  // namespace pivot::scenes
