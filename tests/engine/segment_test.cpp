// Segment shapes: static or kinematic line segments, solid from both sides, colliding with
// circles and polygons, seen by the queries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId dynamicBody(World& world, Vec2 at) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    return world.createBody(def);
}

void steps(World& world, int n) {
    for (int i = 0; i < n; ++i) world.step(kDt);
}

}  // namespace

TEST(Segment, IsCreatedOnStaticAndKinematicBodiesOnly) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    const ShapeId floor = world.createShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    EXPECT_EQ(world.shapeType(floor), ShapeType::Segment);
    EXPECT_EQ(world.shapeSegment(floor).point1, (Vec2{-5, 0}));
    EXPECT_EQ(world.shapeSegment(floor).point2, (Vec2{5, 0}));
    EXPECT_THROW(world.shapePolygon(floor), Error);
    EXPECT_THROW(world.shapeCircle(floor), Error);

    BodyDef platformDef;
    platformDef.type = BodyType::Kinematic;
    const BodyId platform = world.createBody(platformDef);
    world.createShape(platform, ShapeDef{}, Segment{{0, 1}, {2, 1}});
    EXPECT_EQ(world.bodyMass(platform), 0.0f);

    const BodyId box = dynamicBody(world, {0, 3});
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(world.createShape(box, ShapeDef{}, Segment{{0, 0}, {1, 0}}), Error);
    EXPECT_THROW(world.setBodyType(platform, BodyType::Dynamic), Error);
    EXPECT_THROW(world.setBodyType(ground, BodyType::Dynamic), Error);
    EXPECT_EQ(world.stateHash(), before);
}

TEST(Segment, BadPointsAreRefused) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::uint64_t before = world.stateHash();
    for (const Segment& bad :
         {Segment{{nan, 0}, {1, 0}}, Segment{{0, 0}, {0.001f, 0}}, Segment{{0, 0}, {0, 0}},
          Segment{{0, 0}, {2e5f, 0}}, Segment{{1e-40f, 0}, {1, 0}},
          Segment{{0, std::numeric_limits<float>::infinity()}, {1, 0}}}) {
        EXPECT_THROW(world.createShape(ground, ShapeDef{}, bad), Error);
    }
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_EQ(world.shapeCount(), 0);
}

TEST(Segment, HoldsABoxAndABallFromEitherSide) {
    // A floor segment with a box and a ball dropped on it, and a ceiling segment a ball is
    // thrown up against: both sides are solid.
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Segment{{-10, 0}, {10, 0}});
    world.createShape(ground, ShapeDef{}, Segment{{20, 5}, {30, 5}});
    const BodyId box = dynamicBody(world, {-3, 2});
    world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    const BodyId ball = dynamicBody(world, {3, 2});
    world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.5f});
    const BodyId thrown = dynamicBody(world, {25, 2});
    world.createShape(thrown, ShapeDef{}, Circle{{0, 0}, 0.5f});
    world.setBodyLinearVelocity(thrown, {0, 12});
    float highest = 0.0f;
    for (int i = 0; i < 180; ++i) {
        world.step(kDt);
        highest = std::max(highest, world.bodyPosition(thrown).y);
    }
    // Resting in the skins (the segment's kPolygonRadius, and the box's), as deep as the
    // contacts' slop allows, as on a polygon.
    EXPECT_NEAR(world.bodyPosition(box).y, 0.5f + 2.0f * kPolygonRadius - kLinearSlop, 1e-3f);
    EXPECT_NEAR(world.bodyPosition(ball).y, 0.5f + kPolygonRadius - kLinearSlop, 1e-3f);
    EXPECT_LT(std::fabs(world.bodyLinearVelocity(box).y), 0.01f);
    // The thrown ball stopped at the ceiling (its top at y = 5: the ball's centre at 4.5), sank
    // less than 2 cm into it on the impact (at 9.7 m/s, 16 cm a step), and fell back.
    EXPECT_GT(highest, 4.4f);
    EXPECT_LT(highest, 4.52f);
    EXPECT_LT(world.bodyPosition(thrown).y, 3.0f);
}

TEST(Segment, ABallRollsDownARampAndOffItsEnd) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Segment{{0, 5}, {10, 0}});
    const BodyId ball = dynamicBody(world, {0.5f, 6.2f});
    world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.5f});
    float furthestBelowTheRamp = 0.0f;
    for (int i = 0; i < 240; ++i) {
        world.step(kDt);
        const Vec2 p = world.bodyPosition(ball);
        if (p.x > 0.0f && p.x < 10.0f) {
            // Distance from the ramp's line, positive above it: the ball stays on top.
            const float above = (0.5f * p.x + p.y - 5.0f) / std::sqrt(1.25f);
            furthestBelowTheRamp = std::min(furthestBelowTheRamp, above - 0.5f);
        }
    }
    EXPECT_GT(furthestBelowTheRamp, -0.02f);
    EXPECT_GT(world.bodyPosition(ball).x, 10.0f);  // rolled off the low end
    EXPECT_LT(world.bodyPosition(ball).y, 0.0f);   // and fell past it
    EXPECT_LT(std::fabs(world.bodyAngularVelocity(ball)), 100.0f);
}

TEST(Segment, AKinematicSegmentCarriesABox) {
    World world{oneSubstepDef()};
    BodyDef liftDef;
    liftDef.type = BodyType::Kinematic;
    const BodyId lift = world.createBody(liftDef);
    world.createShape(lift, ShapeDef{}, Segment{{-2, 0}, {2, 0}});
    world.setBodyLinearVelocity(lift, {0, 1});
    const BodyId box = dynamicBody(world, {0, 0.5f + kPolygonRadius});
    world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    steps(world, 120);  // 2 s up at 1 m/s
    EXPECT_NEAR(world.bodyPosition(box).y, 2.0f + 0.5f + kPolygonRadius, 0.02f);
    EXPECT_NEAR(world.bodyLinearVelocity(box).y, 1.0f, 0.02f);
}

TEST(Segment, RayCastsHitEitherSideBetweenTheEnds) {
    const Segment s{{0, 0}, {4, 0}};
    const Transform xf{{1, 1}, Rot(0.0f)};
    const auto fromAbove = rayCast(s, xf, {2, 3}, {0, -4});
    ASSERT_TRUE(fromAbove);
    EXPECT_NEAR(fromAbove->fraction, 0.5f, 1e-6f);
    EXPECT_NEAR(fromAbove->normal.y, 1.0f, 1e-6f);
    const auto fromBelow = rayCast(s, xf, {2, -1}, {0, 4});
    ASSERT_TRUE(fromBelow);
    EXPECT_NEAR(fromBelow->fraction, 0.5f, 1e-6f);
    EXPECT_NEAR(fromBelow->normal.y, -1.0f, 1e-6f);
    EXPECT_FALSE(rayCast(s, xf, {6, 3}, {0, -4}));   // past the end
    EXPECT_FALSE(rayCast(s, xf, {-2, 1}, {10, 0}));  // along the line
    EXPECT_FALSE(rayCast(s, xf, {2, 3}, {0, -1}));   // stops short
    EXPECT_THROW(rayCast(Segment{{0, 0}, {0, 0}}, xf, {2, 3}, {0, -4}), Error);

    // In a world: the ray finds the segment, the point query never does.
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    const ShapeId shape = world.createShape(ground, ShapeDef{}, s);
    const auto hit = world.castRayClosest({2, 3}, {0, -4});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shape, shape);
    int found = 0;
    world.queryPoint({2, 0}, {}, [&](ShapeId) { return ++found, true; });
    EXPECT_EQ(found, 0);
    world.queryAABB(AABB{{1, -1}, {2, 1}}, {}, [&](ShapeId) { return ++found, true; });
    EXPECT_EQ(found, 1);
}
