// Continuous collision (world/continuous_solver.h): the tunnelling cases of issue 14, each run
// with continuous collision on (nothing passes through) and off (the same case tunnels, so the
// check could fail), the per-world and per-body switches, and bullets.
#include <gtest/gtest.h>

#include <cmath>

#include "continuous_parts.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;
using pivot::test::ball;
using pivot::test::follow;
using pivot::test::Shot;
using pivot::test::staticBox;

namespace {

constexpr float kDt = 1.0f / 60.0f;

WorldDef weightless() {
    WorldDef def = oneSubstepDef();
    def.gravity = {0.0f, 0.0f};
    return def;
}

// Fires a ball of radius 0.1 m from x = -3 at 500 m/s (towards a wall 0.05 m thick in the
// callers) and steps 30 times: the largest x its centre reaches, and the impacts solved.
Shot fireBall(World& world, bool bodyContinuous = true) {
    const BodyId shot = ball(world, {-3.0f, 0.0f}, {500.0f, 0.0f}, 0.1f);
    if (!bodyContinuous) world.setBodyContinuous(shot, false);
    return follow(world, shot, 30);
}

Shot shootAtThinWall(bool worldContinuous, bool bodyContinuous,
                     BroadPhaseBoxes boxes = BroadPhaseBoxes::Predictive) {
    WorldDef def = weightless();
    def.enableContinuous = worldContinuous;
    def.broadPhaseBoxes = boxes;
    World world(def);
    staticBox(world, {0.0f, 0.0f}, 0.025f, 2.0f);
    return fireBall(world, bodyContinuous);
}

}  // namespace

TEST(Continuous, AFastBallStopsAtAThinWall) {
    const Shot on = shootAtThinWall(true, true);
    EXPECT_LT(on.furthest, -0.025f) << "the ball's centre passed the wall's near face";
    EXPECT_GE(on.impacts, 1);
    // Without continuous collision the same shot goes through: the check above can fail.
    const Shot off = shootAtThinWall(false, true);
    EXPECT_GT(off.furthest, 0.5f);
    EXPECT_EQ(off.impacts, 0);
}

TEST(Continuous, CompactBroadPhaseBoxesStillPairTheWholeStep) {
    // Compact boxes hold only where the shape ended the step, but a fast shape's sweep is paired
    // with what it passed, so the contact with the wall exists when the impact is sought.
    const Shot on = shootAtThinWall(true, true, BroadPhaseBoxes::Compact);
    EXPECT_LT(on.furthest, -0.025f) << "the ball's centre passed the wall's near face";
    EXPECT_GE(on.impacts, 1);
    const Shot off = shootAtThinWall(false, true, BroadPhaseBoxes::Compact);
    EXPECT_GT(off.furthest, 0.5f);
}

namespace {
// The ball of shootAtThinWall at a thin kinematic wall, under Compact boxes (which pair a fast
// shape's sweep with kinematic shapes only while there are any): made kinematic at creation,
// or created static and made kinematic (then static again, and kinematic again) before the shot.
Shot shootAtThinKinematicWall(bool worldContinuous, bool madeKinematicLater) {
    WorldDef def = weightless();
    def.enableContinuous = worldContinuous;
    def.broadPhaseBoxes = BroadPhaseBoxes::Compact;
    World world(def);
    BodyId wall;
    if (madeKinematicLater) {
        wall = staticBox(world, {0.0f, 0.0f}, 0.025f, 2.0f);
        world.setBodyType(wall, BodyType::Kinematic);
        world.setBodyType(wall, BodyType::Static);
        world.setBodyType(wall, BodyType::Kinematic);
    } else {
        BodyDef wallDef;
        wallDef.type = BodyType::Kinematic;
        wall = world.createBody(wallDef);
        world.createShape(wall, ShapeDef{}, Polygon::box(0.025f, 2.0f));
    }
    return fireBall(world);
}
}  // namespace

TEST(Continuous, AFastBallStopsAtAThinKinematicWallUnderCompactBoxes) {
    for (bool later : {false, true}) {
        const Shot on = shootAtThinKinematicWall(true, later);
        EXPECT_LT(on.furthest, -0.025f)
            << "the ball passed the wall; made kinematic later: " << later;
        EXPECT_GE(on.impacts, 1);
        const Shot off = shootAtThinKinematicWall(false, later);
        EXPECT_GT(off.furthest, 0.5f);
    }
}

TEST(Continuous, IsSwitchedPerBody) {
    const Shot optedOut = shootAtThinWall(true, false);
    EXPECT_GT(optedOut.furthest, 0.5f);
    EXPECT_EQ(optedOut.impacts, 0);
}

TEST(Continuous, IsSwitchedPerWorldBetweenSteps) {
    World world(weightless());
    EXPECT_TRUE(world.isContinuousEnabled());
    world.setContinuousEnabled(false);
    EXPECT_FALSE(world.isContinuousEnabled());
    staticBox(world, {0.0f, 0.0f}, 0.025f, 2.0f);
    const BodyId shot = ball(world, {-3.0f, 0.0f}, {500.0f, 0.0f}, 0.1f);
    EXPECT_TRUE(world.isBodyContinuous(shot));
    for (int i = 0; i < 5; ++i) world.step(kDt);
    EXPECT_GT(world.bodyPosition(shot).x, 0.5f);
}

// The seed's pendulum spun at 100 rad/s (its 0.25 m ball 5 m from the pivot moves 8 m a step at
// 60 Hz) with a wall 0.05 m thick standing in the ball's path above the pivot. Returns the
// ball's furthest angle about the pivot, unwrapped, from 0 (to the right of the pivot).
float pendulumIntoThinWall(bool continuous, int* impacts) {
    WorldDef def = oneSubstepDef();
    def.enableContinuous = continuous;
    World world(def);
    const Vec2 pivot{0.0f, 10.0f};
    staticBox(world, {0.0f, 15.0f}, 0.025f, 1.0f);  // the wall: not the joint's body, which
                                                    // the ball may not collide with
    const BodyId ground = world.createBody(BodyDef{});
    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = pivot + Vec2{5.0f, 0.0f};
    ballDef.linearVelocity = {0.0f, 500.0f};  // 100 rad/s about the pivot, counter-clockwise
    ballDef.angularVelocity = 100.0f;
    const BodyId bob = world.createBody(ballDef);
    world.createShape(bob, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.25f});
    RevoluteJointDef joint;
    joint.bodyA = ground;
    joint.bodyB = bob;
    joint.localAnchorA = pivot;
    joint.localAnchorB = pivot - ballDef.position;
    world.createJoint(joint);

    float previous = 0.0f, unwrapped = 0.0f, furthest = 0.0f;
    *impacts = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        *impacts += world.lastStepStats().impactCount;
        const Vec2 r = world.bodyPosition(bob) - pivot;
        const float angle = std::atan2(r.y, r.x);
        float change = angle - previous;
        if (change > kPi) change -= 2.0f * kPi;
        if (change < -kPi) change += 2.0f * kPi;
        unwrapped += change;
        previous = angle;
        furthest = std::max(furthest, unwrapped);
    }
    return furthest;
}

TEST(Continuous, TheHundredRadianPendulumStopsAtAThinWall) {
    int impacts = 0;
    // The wall's near face is at x = -0.025: the ball's centre touches it at about 87 degrees.
    EXPECT_LT(pendulumIntoThinWall(true, &impacts), 0.5f * kPi);
    EXPECT_GE(impacts, 1);
    EXPECT_GT(pendulumIntoThinWall(false, &impacts), 0.5f * kPi);
}

// A small fast body fired along x through five thin dynamic boxes.
struct Volley {
    float furthest = -1e9f;  // the projectile's largest x
    float firstBoxSpeed = 0.0f;
    float lastBoxSpeed = 0.0f;
};
Volley fireThroughThinBoxes(bool bullet) {
    World world(weightless());
    BodyId boxes[5];
    for (int i = 0; i < 5; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {1.0f + static_cast<float>(i), 0.0f};
        boxes[i] = world.createBody(def);
        world.createShape(boxes[i], ShapeDef{}, Polygon::box(0.02f, 0.5f));
    }
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {-2.0f, 0.0f};
    def.linearVelocity = {300.0f, 0.0f};
    def.bullet = bullet;
    const BodyId projectile = world.createBody(def);
    world.createShape(projectile, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.05f});
    EXPECT_EQ(world.isBodyBullet(projectile), bullet);
    Volley v;
    for (int i = 0; i < 20; ++i) {
        world.step(kDt);
        v.furthest = std::max(v.furthest, world.bodyPosition(projectile).x);
    }
    v.firstBoxSpeed = world.bodyLinearVelocity(boxes[0]).x;
    v.lastBoxSpeed = world.bodyLinearVelocity(boxes[4]).x;
    return v;
}

TEST(Continuous, ABulletStopsAtTheFirstThinBoxAndPushesIt) {
    const Volley bullet = fireThroughThinBoxes(true);
    EXPECT_GT(bullet.firstBoxSpeed, 1.0f);
    // It pushes the first box ahead of it, so it may end further than x = 1, but it never passes
    // the boxes: it would then be beyond the last one, untouched.
    EXPECT_LT(bullet.furthest, 5.0f);
    EXPECT_EQ(bullet.lastBoxSpeed, 0.0f);
    // An ordinary dynamic body is not kept from tunnelling through dynamic bodies.
    const Volley plain = fireThroughThinBoxes(false);
    EXPECT_GT(plain.furthest, 6.0f);
    EXPECT_EQ(plain.firstBoxSpeed, 0.0f);
}

TEST(Continuous, AFastBoxLandsOnASegmentFloor) {
    for (bool continuous : {true, false}) {
        WorldDef def = oneSubstepDef();
        def.enableContinuous = continuous;
        World world(def);
        const BodyId floor = world.createBody(BodyDef{});
        ShapeDef flat;
        flat.density = 0.0f;
        world.createShape(floor, flat, Segment{{-20.0f, 0.0f}, {20.0f, 0.0f}});
        BodyDef boxDef;
        boxDef.type = BodyType::Dynamic;
        boxDef.position = {0.0f, 3.0f};
        boxDef.linearVelocity = {40.0f, -200.0f};
        const BodyId box = world.createBody(boxDef);
        world.createShape(box, ShapeDef{}, Polygon::box(0.2f, 0.2f));
        float lowest = 1e9f;
        for (int i = 0; i < 60; ++i) {
            world.step(kDt);
            lowest = std::min(lowest, world.bodyPosition(box).y);
        }
        if (continuous) {
            EXPECT_GT(lowest, 0.0f) << "the box's centre went below the floor";
            EXPECT_GT(world.bodyPosition(box).y, 0.1f);
        } else {
            EXPECT_LT(lowest, -1.0f);
        }
    }
}

TEST(Continuous, BulletAndContinuousFlagsAreKeptAndChanged) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.createBody(def);
    EXPECT_TRUE(world.isBodyContinuous(body));
    EXPECT_FALSE(world.isBodyBullet(body));
    world.setBodyBullet(body, true);
    world.setBodyContinuous(body, false);
    EXPECT_TRUE(world.isBodyBullet(body));
    EXPECT_FALSE(world.isBodyContinuous(body));
    world.destroyBody(body);
    EXPECT_THROW(world.setBodyBullet(body, true), Error);
    EXPECT_THROW((void)world.isBodyContinuous(body), Error);
}

TEST(Continuous, ImpactsReportTouchingBeginsAsEvents) {
    World world(weightless());
    const BodyId wall = staticBox(world, {0.0f, 0.0f}, 0.025f, 2.0f);
    ball(world, {-3.0f, 0.0f}, {500.0f, 0.0f}, 0.1f);
    bool began = false;
    for (int i = 0; i < 5 && !began; ++i) {
        world.step(kDt);
        for (const ContactEvent& e : world.contactBeginEvents()) {
            began = began || world.shapeBody(e.shapeA) == wall || world.shapeBody(e.shapeB) == wall;
        }
    }
    EXPECT_TRUE(began);
}
