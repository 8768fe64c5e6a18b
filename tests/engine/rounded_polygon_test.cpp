// Rounded polygons (Polygon::radius): mass against numerical integration, resting heights, the
// ray cast and point query against brute force, and validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "collision/manifold.h"
#include "grid_mass.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;
using pivot::testing::coreDistance;
using pivot::testing::integrate;

namespace {

constexpr float kDt = 1.0f / 60.0f;

}  // namespace

TEST(RoundedPolygon, MassIncludesTheRounding) {
    // A rounded box has the core's area, a band of the radius along the perimeter and a disc.
    const Polygon box = Polygon::roundedBox(1.0f, 0.5f, 0.2f);
    const MassData m = computeMass(box, 2.0f);
    const double area = 1.6 * 0.6 + 2.0 * (1.6 + 0.6) * 0.2 + 3.14159265358979 * 0.04;
    EXPECT_NEAR(m.mass, 2.0 * area, 1e-5);
    EXPECT_NEAR(m.center.x, 0.0f, 1e-6);
    EXPECT_NEAR(m.center.y, 0.0f, 1e-6);
    // Against integration, an off-centre irregular triangle and the box.
    Polygon triangle = Polygon::fromPoints({{0.5f, 0.2f}, {2.0f, 0.4f}, {0.9f, 1.7f}});
    triangle.radius = 0.3f;
    for (const Polygon& p : {box, triangle}) {
        const MassData exact = computeMass(p, 1.0f);
        const MassData grid = integrate(p);
        EXPECT_NEAR(exact.mass, grid.mass, 2e-3 * grid.mass);
        EXPECT_NEAR(exact.center.x, grid.center.x, 2e-3);
        EXPECT_NEAR(exact.center.y, grid.center.y, 2e-3);
        EXPECT_NEAR(exact.rotationalInertia, grid.rotationalInertia, 3e-3 * grid.rotationalInertia);
    }
}

TEST(RoundedPolygon, CornersMeetAtTheirTrueDistance) {
    // Two rounded boxes corner to corner along the diagonal: their core corners are
    // sqrt(2) (d - 0.4) apart for a centre offset of (d, d); they touch within 0.62 m (both
    // roundings and skins). Measured along a face normal the gap would be only d - 0.4.
    const Polygon rounded = Polygon::roundedBox(0.5f, 0.5f, 0.3f);
    ConvexPolygon box;
    ASSERT_TRUE(makeConvexPolygon(rounded, box).empty());
    const float reach = 2.0f * (0.3f + kPolygonRadius);
    const Transform xfA{{0.0f, 0.0f}, Rot(0.0f)};
    for (float gap : {0.05f, -0.05f}) {
        const float d = 0.4f + (reach + gap) / std::sqrt(2.0f);
        const Transform xfB{{d, d}, Rot(0.0f)};
        Manifold m;
        collidePolygons(m, box, xfA, box, xfB);
        if (gap > 0.0f) {
            EXPECT_EQ(m.pointCount, 0) << "apart by " << gap << " m, yet touching";
        } else {
            ASSERT_EQ(m.pointCount, 1);
            EXPECT_EQ(m.type, ManifoldType::Circles);
            const WorldManifold wm =
                computeWorldManifold(m, xfA, 0.3f + kPolygonRadius, xfB, 0.3f + kPolygonRadius);
            EXPECT_NEAR(wm.separations[0], gap, 1e-4f);
            EXPECT_NEAR(wm.normal.x, std::sqrt(0.5f), 1e-4f);
            EXPECT_NEAR(wm.normal.y, std::sqrt(0.5f), 1e-4f);
        }
    }
}

TEST(RoundedPolygon, ARoundedBoxRestsOnItsRoundedFaceAndStaysPut) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef slab;
    slab.density = 0.0f;
    world.createShape(ground, slab, Polygon::box(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 2.0f};
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Polygon::roundedBox(0.5f, 0.5f, 0.2f));
    for (int i = 0; i < 180; ++i) world.step(kDt);
    // Its flat bottom is 0.5 m below its centre; at rest the two skins (kPolygonRadius each)
    // overlap by the slop.
    EXPECT_NEAR(world.bodyPosition(body).y, 0.5f + 2.0f * kPolygonRadius - kLinearSlop,
                0.5f * kLinearSlop);
    EXPECT_NEAR(world.bodyAngle(body), 0.0f, 1e-3f);
    EXPECT_LT(std::fabs(world.bodyLinearVelocity(body).x), 1e-3f);
}

TEST(RoundedPolygon, ACircleRestsOnTheRounding) {
    World world{oneSubstepDef()};
    const BodyId table = world.createBody(BodyDef{});
    ShapeDef solid;
    solid.density = 0.0f;
    world.createShape(table, solid, Polygon::roundedBox(2.0f, 0.5f, 0.25f));
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 2.0f};
    const BodyId ball = world.createBody(def);
    world.createShape(ball, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.3f});
    for (int i = 0; i < 180; ++i) world.step(kDt);
    // The table's rounded top is at 0.5 m; its skin overlaps the ball by the slop at rest.
    EXPECT_NEAR(world.bodyPosition(ball).y, 0.5f + 0.3f + kPolygonRadius - kLinearSlop,
                0.5f * kLinearSlop);
}

TEST(RoundedPolygon, RayCastsAndPointQueriesAgreeWithBruteForce) {
    std::mt19937 rng(2024);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    Polygon polygon =
        Polygon::fromPoints({{-1.0f, -0.6f}, {1.2f, -0.4f}, {0.8f, 0.9f}, {-0.7f, 0.7f}});
    polygon.radius = 0.35f;
    const float angle = 0.7f;
    const Transform xf{{0.4f, -0.3f}, Rot(angle)};
    int hits = 0, misses = 0, inside = 0;
    for (int k = 0; k < 2000; ++k) {
        const float ox = uniform(-4.0f, 4.0f);
        const float oy = uniform(-4.0f, 4.0f);
        const float tx = uniform(-8.0f, 8.0f);
        const float ty = uniform(-8.0f, 8.0f);
        const Vec2 origin{ox, oy};
        const Vec2 translation{tx, ty};
        // Brute force: march along the ray in the polygon's frame.
        auto distanceAt = [&](double t) {
            const Vec2 p = inverseTransformPoint(xf, origin + static_cast<float>(t) * translation);
            return coreDistance(polygon, p.x, p.y) - polygon.radius;
        };
        const bool startsInside = distanceAt(0.0) <= 0.0;
        EXPECT_EQ(testPoint(polygon, xf, origin), startsInside) << k;
        double firstInside = -1.0;
        const int samples = 2000;
        for (int s = 0; s <= samples && !startsInside; ++s) {
            if (distanceAt(double(s) / samples) < -1e-4) {
                firstInside = double(s) / samples;
                break;
            }
        }
        const std::optional<RayHit> hit = rayCast(polygon, xf, origin, translation);
        if (startsInside) {
            ++inside;
            EXPECT_FALSE(hit.has_value()) << k;
            continue;
        }
        if (firstInside < 0.0) {
            // No sample went in: at most a graze.
            if (hit) {
                EXPECT_NEAR(distanceAt(hit->fraction), 0.0, 1e-4) << k;
            }
            ++misses;
            continue;
        }
        ASSERT_TRUE(hit.has_value()) << k;
        ++hits;
        EXPECT_NEAR(distanceAt(hit->fraction), 0.0, 1e-4) << k;  // on the surface
        EXPECT_LE(hit->fraction, firstInside + 1e-6) << k;       // before any inside sample
        // The normal points out of the surface: stepping along it leaves the shape.
        const Vec2 out = hit->point + 0.01f * hit->normal;
        const Vec2 local = inverseTransformPoint(xf, out);
        EXPECT_GT(coreDistance(polygon, local.x, local.y), polygon.radius) << k;
    }
    EXPECT_GT(hits, 250);
    EXPECT_GT(misses, 250);
    EXPECT_GT(inside, 25);
}

TEST(RoundedPolygon, ABadRadiusIsRefusedAndChangesNothing) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.createBody(def);
    const std::uint64_t before = world.stateHash();
    for (float radius : {-0.1f, std::numeric_limits<float>::quiet_NaN(),
                         std::numeric_limits<float>::infinity(), 2.0f * kMaxCoordinate, 1e-40f}) {
        Polygon p = Polygon::box(1.0f, 1.0f);
        p.radius = radius;
        EXPECT_THROW(world.createShape(body, ShapeDef{}, p), Error) << radius;
        EXPECT_THROW(computeMass(p, 1.0f), Error) << radius;
    }
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_THROW(Polygon::roundedBox(0.5f, 0.5f, 0.5f), Error);  // no core left
    EXPECT_THROW(Polygon::roundedBox(0.5f, 0.5f, -0.1f), Error);
    const ShapeId shape =
        world.createShape(body, ShapeDef{}, Polygon::roundedBox(0.5f, 0.4f, 0.1f));
    EXPECT_FLOAT_EQ(world.shapePolygon(shape).radius, 0.1f);
}
