// Chain shapes: polylines of one-sided segments with ghost vertices (World::createChain), for
// terrain. A body slides across their joins without catching, passes through them from behind,
// is held inside a clockwise loop, and does not tunnel through them when fast.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId dynamicBody(World& world, Vec2 at, Vec2 velocity = {}) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    def.linearVelocity = velocity;
    return world.createBody(def);
}

void steps(World& world, int n) {
    for (int i = 0; i < n; ++i) world.step(kDt);
}

// A flat floor at y = 0 from x = 20 down to x = -20 in pieces of `piece` m, listed right to left
// so it is solid from above; ghosts continue it flat.
Chain flatFloor(float piece) {
    Chain chain;
    chain.points.push_back({20.0f + piece, 0.0f});
    for (float x = 20.0f; x >= -20.0f - 0.5f * piece; x -= piece) chain.points.push_back({x, 0.0f});
    chain.points.push_back({chain.points.back().x - piece, 0.0f});
    return chain;
}

}  // namespace

TEST(Chain, MakesOneSegmentShapePerSegmentWithItsNeighboursAsGhosts) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    const std::vector<Vec2> points{{3, 0}, {2, 0}, {1, 0.5f}, {0, 0}, {-1, 0}};
    const std::vector<ShapeId> open = world.createChain(ground, ShapeDef{}, Chain{points, false});
    ASSERT_EQ(open.size(), 2u);  // the first and last points are ghosts only
    const ChainSegment first = world.shapeChainSegment(open[0]);
    EXPECT_EQ(world.shapeType(open[0]), ShapeType::ChainSegment);
    EXPECT_EQ(first.ghost1, (Vec2{3, 0}));
    EXPECT_EQ(first.segment.point1, (Vec2{2, 0}));
    EXPECT_EQ(first.segment.point2, (Vec2{1, 0.5f}));
    EXPECT_EQ(first.ghost2, (Vec2{0, 0}));
    EXPECT_EQ(world.shapeChainSegment(open[1]).ghost2, (Vec2{-1, 0}));
    EXPECT_THROW(world.shapeSegment(open[0]), Error);

    const std::vector<ShapeId> loop =
        world.createChain(ground, ShapeDef{}, Chain{{{0, 0}, {1, 0}, {1, 1}}, true});
    ASSERT_EQ(loop.size(), 3u);
    const ChainSegment closing = world.shapeChainSegment(loop[2]);
    EXPECT_EQ(closing.ghost1, (Vec2{1, 0}));
    EXPECT_EQ(closing.segment.point1, (Vec2{1, 1}));
    EXPECT_EQ(closing.segment.point2, (Vec2{0, 0}));
    EXPECT_EQ(closing.ghost2, (Vec2{1, 0}));
    EXPECT_EQ(world.shapeChainSegment(loop[0]).ghost1, (Vec2{1, 1}));
    // Segments have no mass: the body's stays what a static body's is.
    EXPECT_EQ(world.bodyMass(ground), 0.0f);
}

TEST(Chain, BadChainsAreRefusedAndNothingIsMade) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    const BodyId dynamic = dynamicBody(world, {0, 5});
    world.createShape(dynamic, ShapeDef{}, Circle{{0, 0}, 0.5f});
    const int shapes = world.shapeCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float denormal = std::numeric_limits<float>::denorm_min();
    const std::vector<Chain> bad{
        Chain{{{0, 0}, {1, 0}, {2, 0}}, false},                 // too few for an open chain
        Chain{{{0, 0}, {1, 0}}, true},                          // too few for a loop
        Chain{{{0, 0}, {1, 0}, {1, 0}, {2, 0}}, false},         // a repeated point
        Chain{{{0, 0}, {1, 0}, {1.001f, 0}, {2, 0}}, false},    // closer than the slop
        Chain{{{0, 0}, {1, 0}, {1, 1}, {0.001f, 0}}, true},     // closing step too short
        Chain{{{0, 0}, {1, 0}, {nan, 1}, {2, 0}}, false},       // not finite
        Chain{{{0, 0}, {1, 0}, {inf, 1}, {2, 0}}, false},       // not finite
        Chain{{{0, 0}, {1, denormal}, {2, 1}, {3, 0}}, false},  // a denormal
        Chain{{{0, 0}, {1, 0}, {2 * kMaxCoordinate, 1}, {3, 0}}, false},  // out of range
    };
    for (const Chain& chain : bad) {
        EXPECT_THROW(world.createChain(ground, ShapeDef{}, chain), Error);
        EXPECT_EQ(world.shapeCount(), shapes);
    }
    // No mass: not on a dynamic body.
    EXPECT_THROW(world.createChain(dynamic, ShapeDef{}, flatFloor(1.0f)), Error);
    EXPECT_THROW(
        world.createShape(dynamic, ShapeDef{}, ChainSegment{{-2, 0}, {{-1, 0}, {1, 0}}, {2, 0}}),
        Error);
    // A ghost on top of its point gives the join no direction.
    EXPECT_THROW(
        world.createShape(ground, ShapeDef{}, ChainSegment{{-1, 0}, {{-1, 0}, {1, 0}}, {2, 0}}),
        Error);
    EXPECT_EQ(world.shapeCount(), shapes);
    // And a body carrying one cannot become dynamic.
    BodyDef kinematicDef;
    kinematicDef.type = BodyType::Kinematic;
    const BodyId kinematic = world.createBody(kinematicDef);
    world.createChain(kinematic, ShapeDef{}, flatFloor(2.0f));
    EXPECT_THROW(world.setBodyType(kinematic, BodyType::Dynamic), Error);
}

// Sliding without friction across the joins of a flat chain: the box keeps its speed and does not
// hop or tip. (A contact takes its normal from a join only where the ghosts allow it; on this
// flat floor, two-sided segments hold the box too, Box2D's hysteresis favouring the segment's
// own face: the bit-for-bit reference tests cover the join decisions themselves.)
TEST(Chain, ABoxSlidesAcrossTheJoinsWithoutCatching) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef slippery;
    slippery.friction = 0.0f;
    world.createChain(ground, slippery, flatFloor(1.0f));
    const BodyId box = dynamicBody(world, {15.0f, 0.5f + kPolygonRadius}, {-6.0f, 0.0f});
    world.createShape(box, slippery, Polygon::box(0.5f, 0.5f));
    float lowestSpeed = 6.0f, highest = 0.0f, mostTurn = 0.0f;
    for (int i = 0; i < 240; ++i) {  // 4 s: 24 m, across 24 joins
        world.step(kDt);
        lowestSpeed = std::min(lowestSpeed, -world.bodyLinearVelocity(box).x);
        highest = std::max(highest, world.bodyPosition(box).y);
        mostTurn = std::max(mostTurn, std::fabs(world.bodyAngle(box)));
    }
    EXPECT_LT(world.bodyPosition(box).x, -8.0f);
    EXPECT_GT(lowestSpeed, 5.9f);
    EXPECT_LT(highest, 0.5f + 0.02f);
    EXPECT_LT(mostTurn, 0.01f);
}

TEST(Chain, IsSolidFromItsRightOnlyAndRaysSeeTheSameSide) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId ground = world.createBody(BodyDef{});
    world.createChain(ground, ShapeDef{}, flatFloor(2.0f));
    // From above: lands and rests.
    const BodyId above = dynamicBody(world, {0.0f, 2.0f});
    world.createShape(above, ShapeDef{}, Circle{{0, 0}, 0.5f});
    // From below, thrown upwards: passes through and lands on top.
    const BodyId below = dynamicBody(world, {5.0f, -2.0f}, {0.0f, 12.0f});
    world.createShape(below, ShapeDef{}, Polygon::box(0.3f, 0.3f));
    steps(world, 180);
    EXPECT_NEAR(world.bodyPosition(above).y, 0.5f, 0.02f);
    EXPECT_NEAR(world.bodyPosition(below).y, 0.3f + kPolygonRadius, 0.02f);

    QueryFilter all;
    const auto down = world.castRayClosest({-3.0f, 5.0f}, {0.0f, -10.0f}, all);
    ASSERT_TRUE(down.has_value());
    EXPECT_NEAR(down->point.y, 0.0f, 1e-6f);
    EXPECT_EQ(down->normal, (Vec2{0.0f, 1.0f}));
    EXPECT_FALSE(world.castRayClosest({-3.0f, -5.0f}, {0.0f, 10.0f}, all).has_value());
    // The same for one segment on its own.
    const ChainSegment lone{{2, 0}, {{1, 0}, {-1, 0}}, {-2, 0}};
    EXPECT_TRUE(rayCast(lone, Transform{}, {0, 1}, {0, -2}).has_value());
    EXPECT_FALSE(rayCast(lone, Transform{}, {0, -1}, {0, 2}).has_value());
    EXPECT_THROW(
        rayCast(ChainSegment{{1, 0}, {{1, 0}, {-1, 0}}, {-2, 0}}, Transform{}, {0, 1}, {0, -2}),
        Error);
}

// A closed loop wound clockwise keeps bodies in: balls and boxes bouncing in a box-shaped loop
// stay inside it.
TEST(Chain, AClockwiseLoopHoldsBodiesInside) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef bouncy;
    bouncy.restitution = 0.8f;
    world.createChain(ground, bouncy, Chain{{{-5, 0}, {-5, 10}, {5, 10}, {5, 0}}, true});
    std::vector<BodyId> bodies;
    for (int i = 0; i < 8; ++i) {
        const BodyId body =
            dynamicBody(world, {-4.0f + float(i), 5.0f}, {15.0f * std::cos(float(i)), 15.0f});
        if (i % 2 == 0) {
            world.createShape(body, bouncy, Circle{{0, 0}, 0.3f});
        } else {
            world.createShape(body, bouncy, Polygon::box(0.3f, 0.2f));
        }
        bodies.push_back(body);
    }
    for (int i = 0; i < 600; ++i) {
        world.step(kDt);
        for (BodyId body : bodies) {
            const Vec2 p = world.bodyPosition(body);
            ASSERT_TRUE(p.x > -5.0f && p.x < 5.0f && p.y > 0.0f && p.y < 10.0f)
                << "step " << i << " at " << p.x << ", " << p.y;
        }
    }
}

// A fast body onto a chain floor: continuous collision stops it at the chain (it has no
// thickness to be caught in otherwise). With it off, the same body (its step's move capped at
// kMaxTranslation, 2 m, and starting 1 m up) is behind the floor after one step and falls on.
TEST(Chain, AFastBodyDoesNotTunnelThroughAChainFloor) {
    for (bool continuous : {true, false}) {
        World world{oneSubstepDef()};
        world.setContinuousEnabled(continuous);
        const BodyId ground = world.createBody(BodyDef{});
        world.createChain(ground, ShapeDef{}, flatFloor(1.0f));
        const BodyId ball = dynamicBody(world, {0.3f, 1.0f}, {20.0f, -400.0f});
        world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.1f});
        const BodyId box = dynamicBody(world, {-5.3f, 1.0f}, {-10.0f, -300.0f});
        world.createShape(box, ShapeDef{}, Polygon::box(0.1f, 0.05f));
        steps(world, 30);
        if (continuous) {
            EXPECT_GT(world.bodyPosition(ball).y, 0.0f);
            EXPECT_GT(world.bodyPosition(box).y, 0.0f);
        } else {
            EXPECT_LT(world.bodyPosition(ball).y, -1.0f);
            EXPECT_LT(world.bodyPosition(box).y, -1.0f);
        }
    }
}
