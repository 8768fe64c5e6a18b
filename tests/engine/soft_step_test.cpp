// The solvers the field uses now: soft step (PositionSolver::SoftStep, ContactCorrection::Soft),
// Box2D v3's, per joint and per world; and XPBD (PositionSolver::XPBD), per joint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

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
    World world{oneSubstepDef()};
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
        WorldDef def = oneSubstepDef();
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
    WorldDef def = oneSubstepDef();
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
    WorldDef def = oneSubstepDef();
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

namespace {

// A 2 kg box hung 1 m below a static anchor by a distance rod of compliance `compliance`:
// how far the rod is stretched once it hangs still.
float hangingStretch(float compliance, int substeps, int iterations) {
    WorldDef def = oneSubstepDef();
    def.substepCount = substeps;
    World world(def);
    const BodyId ceiling = world.createBody(BodyDef{});
    BodyDef boxDef;
    boxDef.type = BodyType::Dynamic;
    // Hung at the stretch the physics gives (20 N x compliance): a compliant rod is an undamped
    // spring, so one released elsewhere would bounce about that length.
    boxDef.position = {0.0f, -1.0f - 20.0f * compliance};
    boxDef.fixedRotation = true;
    const BodyId b = world.createBody(boxDef);
    ShapeDef shape;
    shape.density = 2.0f;  // 1 x 1 m: 2 kg
    world.createShape(b, shape, Polygon::box(0.5f, 0.5f));
    DistanceJointDef rod;
    rod.bodyA = ceiling;
    rod.bodyB = b;
    rod.length = 1.0f;
    rod.positionSolver = PositionSolver::XPBD;
    rod.softness.compliance = compliance;
    const JointId joint = world.createJoint(rod);
    for (int i = 0; i < 600; ++i) world.step(kDt, 1, iterations);
    EXPECT_LT(length(world.bodyLinearVelocity(b)), 1e-3f);
    // The rod's reaction is the weight it carries.
    EXPECT_NEAR(world.jointReactionForce(joint).y, 20.0f, 0.05f);
    return world.jointSeparation(joint);
}

}  // namespace

TEST(Xpbd, ACompliantRodStretchesAsItsComplianceSaysWhateverTheSubstepsAndIterations) {
    // XPBD's point: the rod holds the stretch physics gives it, weight x compliance (20 N x
    // 1e-3 m/N = 2 cm), however many iterations or substeps solve it (plain PBD's stiffness
    // depended on both), and reports the weight as its force.
    for (int substeps : {1, 4}) {
        for (int iterations : {1, 4}) {
            SCOPED_TRACE(std::to_string(substeps) + " substeps, " + std::to_string(iterations) +
                         " iterations");
            EXPECT_NEAR(hangingStretch(1e-3f, substeps, iterations), 0.02f, 2e-4f);
        }
    }
    // Compliance 0 is rigid.
    EXPECT_LT(hangingStretch(0.0f, 4, 1), 1e-4f);
}

TEST(Xpbd, TheCorrectionIsMotionThatTheNextSubstepStops) {
    // As position-based dynamics does, the velocities are derived from the moves: the box that
    // starts half a metre from its pin is pulled in, and leaves the step moving at the speed
    // of that move (30 m/s: 0.5 m in 1/60 s). In the next step the pin stops it (its pull
    // would carry the box past the pin, and the projection back takes that speed away): a
    // rigid XPBD joint absorbs the correction where a Baumgarte one would bounce.
    StretchedPin p(PositionSolver::XPBD, 1, 0.5f);
    p.world.step(kDt, 1, 3);
    EXPECT_LT(p.world.jointSeparation(p.pin), 0.01f);
    EXPECT_GT(length(p.world.bodyLinearVelocity(p.body)), 10.0f);
    p.world.step(kDt, 1, 3);
    EXPECT_LT(p.world.jointSeparation(p.pin), 0.01f);
    EXPECT_LT(length(p.world.bodyLinearVelocity(p.body)), 1.0f);
}

TEST(Xpbd, ARigidJointHoldsItsNeighboursUpAtOneSubstep) {
    // Three links strung between the ground and a static post, under gravity: the first pin is
    // XPBD, the others Baumgarte. A rigid XPBD joint keeps its rows (unbiased) in the velocity
    // iterations, so the Baumgarte pins see it carry its share of the load. Without that (its
    // rows left to the sweeps, as published), the links fell each step until the sweeps pulled
    // the first one back alone, and the Baumgarte pin beside it opened to 0.099 m.
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    BodyDef postDef;
    postDef.position = {3.0f, 8.0f};
    const BodyId post = world.createBody(postDef);
    BodyId previous = ground;
    std::vector<JointId> pins;
    for (int i = 0; i < 4; ++i) {
        const BodyId link = i < 3 ? box(world, {0.5f + float(i), 8.0f}, 0.45f, 0.1f) : post;
        RevoluteJointDef def = RevoluteJointDef::atWorldAnchor(previous, link, {float(i), 8.0f});
        def.positionSolver = i == 0 ? PositionSolver::XPBD : PositionSolver::Baumgarte;
        pins.push_back(world.createJoint(def));
        previous = link;
    }
    float widest = 0.0f;
    for (int s = 0; s < 120; ++s) {
        world.step(kDt);
        for (JointId pin : pins) widest = std::max(widest, world.jointSeparation(pin));
    }
    EXPECT_LT(widest, 0.01f);
}

TEST(Xpbd, ComplianceIsValidated) {
    StretchedPin p(PositionSolver::XPBD, 1, 0.0f);
    const std::uint64_t before = p.world.stateHash();
    for (float bad : {-1e-3f, std::numeric_limits<float>::quiet_NaN(),
                      std::numeric_limits<float>::infinity(), 2e10f}) {
        JointSoftness softness;
        softness.compliance = bad;
        EXPECT_THROW(p.world.setJointSoftness(p.pin, softness), Error) << bad;
    }
    EXPECT_EQ(p.world.stateHash(), before);
    JointSoftness soft;
    soft.compliance = 1e-4f;
    p.world.setJointSoftness(p.pin, soft);
    EXPECT_EQ(p.world.jointSoftness(p.pin).compliance, 1e-4f);
    EXPECT_NE(p.world.stateHash(), before);
}
