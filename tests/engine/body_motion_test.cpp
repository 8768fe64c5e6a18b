// Integration of single bodies: semi-implicit Euler, damping, gravity scale, body types,
// forces and impulses, and the per-step motion clamps; a lone body's shortcut through the step.
#include <gtest/gtest.h>

#include <memory>

#include "pivot/pivot.h"
#include "same_step_stats.h"
#include "scoped_switch.h"
#include "solver/island_solver.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;

BodyId ball(World& world, BodyDef def) {
    BodyId id = world.createBody(def);
    world.createShape(id, ShapeDef{}, Circle{{0, 0}, 0.5f});
    return id;
}
BodyDef dynamicAt(Vec2 p) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = p;
    return def;
}
}  // namespace

TEST(BodyMotion, FreeFallIsSemiImplicitEuler) {
    // v_n = n g h and y_n = y0 + g h^2 n (n + 1) / 2: velocity first, then position.
    World world{oneSubstepDef()};
    BodyId b = ball(world, dynamicAt({0, 100}));
    const int n = 60;
    for (int i = 0; i < n; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyLinearVelocity(b).y, -10.0f * kDt * n, 1e-4f);
    EXPECT_NEAR(world.bodyPosition(b).y, 100.0f - 10.0f * kDt * kDt * n * (n + 1) / 2.0f, 1e-3f);
    EXPECT_EQ(world.bodyPosition(b).x, 0.0f);
}

TEST(BodyMotion, DampingScalesVelocityByOneOverOnePlusHc) {
    World world(oneSubstepDef({0, 0}));
    BodyDef def = dynamicAt({0, 0});
    def.linearVelocity = {4, 0};
    def.angularVelocity = 2;
    def.linearDamping = 3;
    def.angularDamping = 6;
    BodyId b = ball(world, def);
    world.step(kDt);
    EXPECT_FLOAT_EQ(world.bodyLinearVelocity(b).x, 4.0f / (1.0f + kDt * 3.0f));
    EXPECT_FLOAT_EQ(world.bodyAngularVelocity(b), 2.0f / (1.0f + kDt * 6.0f));
}

TEST(BodyMotion, GravityScale) {
    World world{oneSubstepDef()};
    BodyDef def = dynamicAt({0, 0});
    def.gravityScale = 0.0f;
    BodyId floating = ball(world, def);
    def.gravityScale = -1.0f;
    BodyId rising = ball(world, def);
    world.step(kDt);
    EXPECT_EQ(world.bodyLinearVelocity(floating).y, 0.0f);
    EXPECT_GT(world.bodyLinearVelocity(rising).y, 0.0f);
}

TEST(BodyMotion, KinematicBodiesMoveByVelocityAndIgnoreGravityAndForces) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Kinematic;
    def.linearVelocity = {1, 0};
    def.angularVelocity = 0.5f;
    BodyId k = ball(world, def);
    // A force could not move it (infinite mass), so the call is refused rather than dropped.
    EXPECT_THROW(world.applyForceToCenter(k, {0, 1000}), Error);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(k).x, 1.0f, 1e-5f);
    EXPECT_EQ(world.bodyPosition(k).y, 0.0f);
    EXPECT_NEAR(world.bodyAngle(k), 0.5f, 1e-5f);
    EXPECT_EQ(world.bodyLinearVelocity(k), (Vec2{1, 0}));
}

TEST(BodyMotion, StaticBodiesNeverMove) {
    World world{oneSubstepDef()};
    BodyId s = ball(world, BodyDef{});
    for (int i = 0; i < 10; ++i) world.step(kDt);
    EXPECT_EQ(world.bodyPosition(s), (Vec2{0, 0}));
    EXPECT_EQ(world.lastStepStats().bodyCount, 0);
}

TEST(BodyMotion, ForcesLastOneStepAndImpulsesActAtOnce) {
    World world(oneSubstepDef({0, 0}));
    BodyId b = ball(world, dynamicAt({0, 0}));
    float mass = world.bodyMass(b);
    world.applyForceToCenter(b, {mass * 60.0f, 0});  // a = 60 m/s^2 for one step: dv = 1 m/s
    world.step(kDt);
    EXPECT_NEAR(world.bodyLinearVelocity(b).x, 1.0f, 1e-5f);
    world.step(kDt);
    EXPECT_NEAR(world.bodyLinearVelocity(b).x, 1.0f, 1e-5f);  // cleared after its step

    world.applyLinearImpulse(b, {0, mass * 2.0f}, world.bodyWorldCenter(b));
    EXPECT_NEAR(world.bodyLinearVelocity(b).y, 2.0f, 1e-5f);
    EXPECT_EQ(world.bodyAngularVelocity(b), 0.0f);  // through the centre: no spin
    // Off-centre: spin by r x P / I.
    world.applyLinearImpulse(b, {0, 1}, world.bodyWorldCenter(b) + Vec2{0.5f, 0});
    EXPECT_NEAR(world.bodyAngularVelocity(b), 0.5f / world.bodyRotationalInertia(b), 1e-4f);
    // A torque about the centre, for one step.
    float w0 = world.bodyAngularVelocity(b);
    world.applyTorque(b, world.bodyRotationalInertia(b) * 60.0f);
    world.step(kDt);
    EXPECT_NEAR(world.bodyAngularVelocity(b) - w0, 1.0f, 1e-4f);
}

TEST(BodyMotion, TranslationAndRotationAreClampedPerStep) {
    World world(oneSubstepDef({0, 0}));
    BodyDef def = dynamicAt({0, 0});
    def.linearVelocity = {600, 0};  // 10 m per step at 60 Hz
    def.angularVelocity = 300;      // 5 rad per step
    BodyId b = ball(world, def);
    world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(b).x, kMaxTranslation, 1e-5f);
    EXPECT_NEAR(world.bodyAngle(b), kMaxRotation, 1e-5f);
    // The clamp scales the velocity itself.
    EXPECT_NEAR(world.bodyLinearVelocity(b).x, kMaxTranslation / kDt, 1e-2f);
    EXPECT_EQ(world.lastStepStats().translationClamps, 1);
    EXPECT_EQ(world.lastStepStats().rotationClamps, 1);
    world.step(kDt);  // now exactly at the limit: not clamped again
    EXPECT_EQ(world.lastStepStats().translationClamps, 0);
}

TEST(BodyMotion, SetTransformTeleportsTheOriginAndKeepsTheCentreOffset) {
    World world{oneSubstepDef()};
    BodyId b = world.createBody(dynamicAt({0, 0}));
    world.createShape(b, ShapeDef{}, Circle{{1, 0}, 0.5f});
    world.setBodyTransform(b, {3, 4}, kPi / 2);
    EXPECT_EQ(world.bodyPosition(b), (Vec2{3, 4}));
    Vec2 c = world.bodyWorldCenter(b);
    EXPECT_NEAR(c.x, 3.0f, 1e-6f);
    EXPECT_NEAR(c.y, 5.0f, 1e-6f);
    Vec2 local = world.bodyLocalPoint(b, world.bodyWorldPoint(b, {0.25f, -2}));
    EXPECT_NEAR(local.x, 0.25f, 1e-5f);
    EXPECT_NEAR(local.y, -2.0f, 1e-5f);
}

namespace {

using LoneBodyShortcut = ScopedSwitch<&setLoneBodyShortcut>;

// Bodies that each stay alone in their island (far apart, no joint) and between them take every
// branch of a lone body's step: forces, torque and damping; both clamps; a kinematic body; the
// world's edge; falling asleep.
std::unique_ptr<World> loneBodies(int substeps, int workers) {
    WorldDef def = oneSubstepDef();
    def.substepCount = substeps;
    def.workerCount = workers;
    auto world = std::make_unique<World>(def);
    BodyDef damped;
    damped.type = BodyType::Dynamic;
    damped.position = {0, 0};
    damped.angularVelocity = 3.0f;
    damped.linearDamping = 0.3f;
    damped.angularDamping = 0.7f;
    damped.gravityScale = 0.5f;
    ball(*world, damped);
    BodyDef fast = damped;
    fast.position = {100, 0};
    fast.linearVelocity = {400, -300};
    fast.angularVelocity = 500.0f;
    fast.linearDamping = fast.angularDamping = 0.0f;
    ball(*world, fast);
    BodyDef kinematic;
    kinematic.type = BodyType::Kinematic;
    kinematic.position = {-100, 0};
    kinematic.linearVelocity = {1, 2};
    kinematic.angularVelocity = -2.0f;
    ball(*world, kinematic);
    BodyDef edge;
    edge.type = BodyType::Dynamic;
    edge.position = {kMaxCoordinate - 3.0f, 0};
    edge.linearVelocity = {90, 0};
    edge.gravityScale = 0.0f;
    ball(*world, edge);
    BodyDef resting;
    resting.type = BodyType::Dynamic;
    resting.position = {0, 200};
    resting.gravityScale = 0.0f;
    resting.linearVelocity = {0.001f, 0};
    resting.fixedRotation = true;
    ball(*world, resting);
    return world;
}

}  // namespace

TEST(LoneBody, TheShortcutStepsToTheSameBitsAsAnIsland) {
    for (int substeps : {1, 4}) {
        for (int workers : {1, 2}) {
            auto shortcut = loneBodies(substeps, workers);
            auto island = loneBodies(substeps, workers);
            int clamps = 0, edges = 0;
            for (int i = 0; i < 120; ++i) {
                const BodyId damped = shortcut->bodyIds()[0];
                shortcut->applyForceToCenter(damped, {3.0f, 1.0f});
                shortcut->applyTorque(damped, 0.25f);
                island->applyForceToCenter(island->bodyIds()[0], {3.0f, 1.0f});
                island->applyTorque(island->bodyIds()[0], 0.25f);
                {
                    LoneBodyShortcut on(true);
                    shortcut->step(kDt);
                }
                {
                    LoneBodyShortcut off(false);
                    island->step(kDt);
                }
                ASSERT_EQ(shortcut->stateHash(), island->stateHash())
                    << substeps << " substeps, " << workers << " workers, step " << i;
                const StepStats& a = shortcut->lastStepStats();
                ASSERT_TRUE(test_support::sameSolverStats(a, island->lastStepStats()))
                    << substeps << " substeps, " << workers << " workers, step " << i;
                clamps += a.translationClamps + a.rotationClamps;
                edges += a.edgeBodyCount;
            }
            // Every branch was taken: clamps, the edge, and sleep (the resting body).
            EXPECT_GT(clamps, 0);
            EXPECT_GT(edges, 0);
            EXPECT_GE(shortcut->lastStepStats().sleepingBodyCount, 1);
        }
    }
}
