// Soft step (PositionSolver::SoftStep, ContactCorrection::Soft): Box2D v3's solver, per joint
// and per world.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pivot/pivot.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

BodyId box(World& world, Vec2 at, float halfWidth, float halfHeight) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Polygon::box(halfWidth, halfHeight));
    return body;
}

// A 1 kg-ish box pinned to the static ground at the origin, created `gap` metres to the right
// of its anchor, in a world without gravity: the joint has only its own error to close.
struct StretchedPin {
    World world;
    BodyId body;
    JointId pin;

    StretchedPin(PositionSolver solver, int substeps, float gap) : world(makeDef(substeps)) {
        const BodyId ground = world.createBody(BodyDef{});
        body = box(world, {1.0f + gap, 0.0f}, 0.5f, 0.5f);
        RevoluteJointDef def;
        def.bodyA = ground;
        def.bodyB = body;
        def.localAnchorB = {-1.0f, 0.0f};
        def.positionSolver = solver;
        pin = world.createJoint(def);
    }
    static WorldDef makeDef(int substeps) {
        WorldDef def;
        def.gravity = {0.0f, 0.0f};
        def.substepCount = substeps;
        return def;
    }
};

}  // namespace

TEST(SoftStep, ClosesAnOpenJointAndTheRelaxLeavesNoMomentum) {
    // Half a metre apart at the start. The bias closes it within each substep's integration;
    // the relax iterations then take the bias's velocity back, so the correction moves the box
    // without leaving it moving. Without relax (no position iterations) it keeps that velocity.
    StretchedPin relaxed(PositionSolver::SoftStep, 4, 0.5f);
    StretchedPin unrelaxed(PositionSolver::SoftStep, 4, 0.5f);
    float fastestRelaxed = 0.0f, fastestUnrelaxed = 0.0f;
    for (int i = 0; i < 60; ++i) {
        relaxed.world.step(kDt, 1, 1);
        unrelaxed.world.step(kDt, 1, 0);
        fastestRelaxed =
            std::max(fastestRelaxed, length(relaxed.world.bodyLinearVelocity(relaxed.body)));
        fastestUnrelaxed =
            std::max(fastestUnrelaxed, length(unrelaxed.world.bodyLinearVelocity(unrelaxed.body)));
    }
    // 0.5 m closes to 5 mm in four steps, 0.1 mm in seven, either way; the box that relaxed
    // ends every step at rest (1e-6 m/s), the other leaves the first at 13 m/s.
    EXPECT_LT(relaxed.world.jointSeparation(relaxed.pin), 1e-4f);
    EXPECT_LT(fastestRelaxed, 0.01f);
    EXPECT_GT(fastestUnrelaxed, 1.0f);
}

TEST(SoftStep, TheJointsSoftnessSetsHowFastItCloses) {
    // A stiffer joint closes the same gap sooner; the softness is read back as set.
    auto separationAfter = [](float hertz, int steps) {
        StretchedPin p(PositionSolver::SoftStep, 4, 0.5f);
        p.world.setJointSoftness(p.pin, {hertz, 2.0f});
        EXPECT_EQ(p.world.jointSoftness(p.pin).hertz, hertz);
        for (int i = 0; i < steps; ++i) p.world.step(kDt, 1, 1);
        return p.world.jointSeparation(p.pin);
    };
    EXPECT_LT(separationAfter(60.0f, 10), 0.5f * separationAfter(5.0f, 10));
}

TEST(SoftStep, SettingTheSoftnessWakesTheJointsBodies) {
    StretchedPin p(PositionSolver::SoftStep, 1, 0.0f);
    p.world.setBodyAwake(p.body, false);
    p.world.setJointSoftness(p.pin, {10.0f, 1.0f});
    EXPECT_TRUE(p.world.isBodyAwake(p.body));
    EXPECT_EQ(p.world.jointSoftness(p.pin), (JointSoftness{10.0f, 1.0f}));
}

TEST(SoftContacts, ABoxRestsOnTheGroundWithinTheSlop) {
    WorldDef def;
    def.contactCorrection = ContactCorrection::Soft;
    def.substepCount = 4;
    World world(def);
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(5.0f, 0.5f));
    const BodyId b = box(world, {0.0f, 1.0f}, 0.5f, 0.5f);
    for (int i = 0; i < 120; ++i) world.step(kDt, 1, 1);
    // Resting polygons keep their skin apart (kPolygonRadius each): the centre sits at 1 m
    // plus two skins, less what the contact lets sink (kLinearSlop).
    const float rest = 1.0f + 2.0f * kPolygonRadius;
    EXPECT_NEAR(world.bodyPosition(b).y, rest, 1.5f * kLinearSlop);
    EXPECT_LT(length(world.bodyLinearVelocity(b)), 1e-3f);
}

TEST(SoftContacts, ADeepOverlapIsPushedOutNoFasterThanThePushSpeed) {
    WorldDef def;
    def.contactCorrection = ContactCorrection::Soft;
    def.gravity = {0.0f, 0.0f};
    def.substepCount = 4;
    def.contactPushSpeed = 2.0f;
    World world(def);
    const BodyId a = box(world, {0.0f, 0.0f}, 0.5f, 0.5f);
    const BodyId b = box(world, {0.0f, 0.4f}, 0.5f, 0.5f);  // 0.6 m into each other
    // The spring pushes at up to the push speed within each substep (its target is capped
    // there); the relax sweeps then take that velocity back, as for a joint. So the gap grows
    // by at most push speed x dt per step.
    float gap = world.bodyPosition(b).y - world.bodyPosition(a).y;
    float fastest = 0.0f;
    for (int i = 0; i < 60; ++i) {
        world.step(kDt, 1, 1);
        const float now = world.bodyPosition(b).y - world.bodyPosition(a).y;
        fastest = std::max(fastest, (now - gap) / kDt);
        gap = now;
    }
    EXPECT_GT(fastest, 0.5f * def.contactPushSpeed);  // it does push
    EXPECT_LE(fastest, def.contactPushSpeed * 1.001f);
    EXPECT_GT(world.bodyPosition(b).y - world.bodyPosition(a).y, 0.99f);
}
