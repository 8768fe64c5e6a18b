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
    bool key;            // neck, shoulders, hips; the elbows and knees are secondary
};

void buildRagdollWith(Scene& scene, const SceneOptions& options, bool motorized) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    createGround(world, 0.6f);
    BodyId wall = world.createBody(BodyDef{});
    ShapeDef wallShape;
    wallShape.density = 0.0f;
    world.createShape(wall, wallShape, Polygon::box(0.5f, 5.0f, {5.5f, 5.0f}, 0.0f));
    addRagdoll(scene, options, {-2.0f, 2.0f}, {8.0f, 3.0f}, -3.0f, motorized, -1);
    scene.disturbanceEndStep = stepAt(options, 1.5f);  // hit the wall and the ground by then
    scene.restFromStep = stepAt(options, 5.0f);
}

}  // namespace

void addRagdoll(Scene& scene, const SceneOptions& options, Vec2 origin, Vec2 velocity, float spin,
                bool motorized, int group) {
    World& world = *scene.world;
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
        {kTorso, kHead, {0.0f, 1.63f}, -0.5f, 0.5f, true},
        {kTorso, kUpperArmL, {-0.26f, 1.55f}, -2.5f, 2.5f, true},
        {kUpperArmL, kLowerArmL, {-0.26f, 1.25f}, 0.0f, 2.5f, false},
        {kTorso, kUpperArmR, {0.26f, 1.55f}, -2.5f, 2.5f, true},
        {kUpperArmR, kLowerArmR, {0.26f, 1.25f}, 0.0f, 2.5f, false},
        {kTorso, kThighL, {-0.1f, 0.9f}, -1.5f, 0.5f, true},
        {kThighL, kShinL, {-0.1f, 0.5f}, -2.5f, 0.0f, false},
        {kTorso, kThighR, {0.1f, 0.9f}, -1.5f, 0.5f, true},
        {kThighR, kShinR, {0.1f, 0.5f}, -2.5f, 0.0f, false},
    };

    // Thrown as one rigid body: every part gets the velocity of its point of the whole.
    const Vec2 spinCenter = origin + Vec2{0.0f, 1.0f};
    ShapeDef shape;
    shape.density = 100.0f;
    shape.friction = 0.6f;
    shape.filter.groupIndex = group;
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
        const Vec2 anchor = origin + h.anchor;
        RevoluteJointDef jd = h.key ? options.jointAt(bodies[h.a], bodies[h.b], anchor)
                                    : options.secondaryJointAt(bodies[h.a], bodies[h.b], anchor);
        jd.limit = {true, h.lower, h.upper};
        if (motorized) jd.motor = {true, 0.0f, 20.0f};
        const JointId joint = world.createJoint(jd);
        scene.joints.push_back(joint);
        if (h.key) scene.keyJoints.push_back(joint);
    }
}

void buildRagdoll(Scene& scene, const SceneOptions& options) {
    buildRagdollWith(scene, options, false);
}

void buildMotorizedRagdoll(Scene& scene, const SceneOptions& options) {
    buildRagdollWith(scene, options, true);
}

}  // namespace pivot::scenes
