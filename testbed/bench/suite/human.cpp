#include "bench/suite/human.h"

#include "pivot/constants.h"

namespace pivot::bench {

namespace {

// One bone, at scale 1, heights measured up from the feet. Each bone after the hip is pinned to
// its parent at pivotY, bent within [lower, upper] (fractions of pi) from referenceAngle.
struct Bone {
    int parent;
    float y;           // the body's origin
    float capsuleLow;  // the capsule's centres, relative to the body's origin
    float capsuleHigh;
    float capsuleRadius;
    bool foot;  // a foot under the shin
    float pivotY;
    float lower, upper;    // x pi
    float referenceAngle;  // x pi
    float frictionScale;   // of the hip's joint friction
    float linearDamping;
};

enum : int {
    kHip,
    kTorso,
    kHead,
    kUpperLeg1,
    kLowerLeg1,
    kUpperLeg2,
    kLowerLeg2,
    kUpperArm1,
    kLowerArm1,
    kUpperArm2,
    kLowerArm2,
};

// In Box2D v3's creation order: hip, torso, head, then each leg and each arm, upper bone first.
constexpr Bone kBones[Human::kBones] = {
    {-1, 0.95f, -0.02f, 0.02f, 0.095f, false, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f},
    {kHip, 1.2f, -0.135f, 0.135f, 0.09f, false, 1.0f, -0.25f, 0.0f, 0.0f, 0.5f, 0.0f},
    {kTorso, 1.475f, -0.038f, 0.039f, 0.075f, false, 1.4f, -0.3f, 0.1f, 0.0f, 0.25f, 0.1f},
    {kHip, 0.775f, -0.125f, 0.125f, 0.06f, false, 0.9f, -0.05f, 0.4f, 0.0f, 1.0f, 0.0f},
    {kUpperLeg1, 0.475f, -0.155f, 0.125f, 0.045f, true, 0.625f, -0.5f, -0.02f, 0.0f, 0.5f, 0.0f},
    {kHip, 0.775f, -0.125f, 0.125f, 0.06f, false, 0.9f, -0.05f, 0.4f, 0.0f, 1.0f, 0.0f},
    {kUpperLeg2, 0.475f, -0.155f, 0.125f, 0.045f, true, 0.625f, -0.5f, -0.02f, 0.0f, 0.5f, 0.0f},
    {kTorso, 1.225f, -0.125f, 0.125f, 0.035f, false, 1.35f, -0.1f, 0.8f, 0.0f, 0.5f, 0.0f},
    {kUpperArm1, 0.975f, -0.125f, 0.125f, 0.03f, false, 1.1f, -0.2f, 0.3f, 0.25f, 0.1f, 0.1f},
    {kTorso, 1.225f, -0.125f, 0.125f, 0.035f, false, 1.35f, -0.1f, 0.8f, 0.0f, 0.5f, 0.0f},
    {kUpperArm2, 0.975f, -0.125f, 0.125f, 0.03f, false, 1.1f, -0.2f, 0.3f, 0.25f, 0.1f, 0.1f},
};

constexpr std::uint16_t kGround = 0x0001;
constexpr std::uint16_t kRagdoll = 0x0002;

}  // namespace

Human spawnHuman(Builder& builder, Vec2 feet, float frictionTorque, std::int16_t group) {
    Material flesh;
    flesh.friction = 0.2f;
    flesh.category = kRagdoll;
    flesh.mask = kGround | kRagdoll;
    flesh.group = group;
    Material sole = flesh;  // feet slide, and step over other ragdolls
    sole.friction = 0.05f;
    sole.mask = kGround;
    const std::vector<Vec2> footOutline = {
        {-0.03f, -0.185f}, {0.11f, -0.185f}, {0.11f, -0.16f}, {-0.03f, -0.14f}};

    Human human;
    for (int i = 0; i < Human::kBones; ++i) {
        const Bone& bone = kBones[i];
        BodySpec body;
        body.position = feet + Vec2{0.0f, bone.y};
        body.linearDamping = bone.linearDamping;
        const int id = builder.body(body);
        human.bodies[static_cast<std::size_t>(i)] = id;
        builder.capsule(id, {0.0f, bone.capsuleLow}, {0.0f, bone.capsuleHigh}, bone.capsuleRadius,
                        flesh);
        if (bone.foot) builder.polygon(id, footOutline, 0.015f, sole);
        if (bone.parent < 0) continue;
        PinSpec pin;
        pin.bodyA = human.bodies[static_cast<std::size_t>(bone.parent)];
        pin.bodyB = id;
        pin.pivot = feet + Vec2{0.0f, bone.pivotY};
        pin.referenceAngle = bone.referenceAngle * kPi;
        pin.limit = true;
        pin.lower = bone.lower * kPi;
        pin.upper = bone.upper * kPi;
        pin.motor = true;  // at speed 0: joint friction
        pin.maxMotorTorque = bone.frictionScale * frictionTorque;
        builder.pin(pin);
    }
    human.spawned = true;
    return human;
}

void removeHuman(Builder& builder, Human& human) {
    if (!human.spawned) return;
    for (int body : human.bodies) builder.destroyBody(body);
    human.spawned = false;
}

}  // namespace pivot::bench
