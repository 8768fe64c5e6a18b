// Capsules: mass against numerical integration, validation, manifolds against the exact
// distance of the cores (with every other shape type), resting and rolling in a world, and the
// per-shape queries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "collision/distance.h"
#include "collision/geometry.h"
#include "collision/manifold.h"
#include "grid_mass.h"
#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A capsule's mass by brute force: the rounded polygon of two vertices it is.
MassData integrate(const Capsule& c) {
    Polygon core;
    core.count = 2;
    core.vertices[0] = c.center1;
    core.vertices[1] = c.center2;
    core.radius = c.radius;
    return pivot::testing::integrate(core);
}

ConvexPolygon checkedCapsule(const Capsule& capsule) {
    ConvexPolygon out;
    EXPECT_TRUE(makeCapsulePolygon(capsule, out).empty());
    return out;
}

DistanceProxy proxyOf(const ConvexPolygon& p) {
    DistanceProxy proxy;
    proxy.count = p.count;
    for (int i = 0; i < p.count; ++i) proxy.vertices[i] = p.vertices[i];
    return proxy;
}

}  // namespace

TEST(Capsule, MassMatchesIntegration) {
    const Capsule level{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    const MassData m = computeMass(level, 2.0f);
    EXPECT_NEAR(m.mass, 2.0 * (2.0 * 1.0 + 3.14159265358979 * 0.25), 1e-5);
    EXPECT_NEAR(m.center.x, 0.0f, 1e-7);
    for (const Capsule& c : {level, Capsule{{0.3f, -0.2f}, {1.8f, 0.9f}, 0.4f}}) {
        const MassData exact = computeMass(c, 1.0f);
        const MassData grid = integrate(c);
        EXPECT_NEAR(exact.mass, grid.mass, 2e-3 * grid.mass);
        EXPECT_NEAR(exact.center.x, grid.center.x, 2e-3);
        EXPECT_NEAR(exact.center.y, grid.center.y, 2e-3);
        EXPECT_NEAR(exact.rotationalInertia, grid.rotationalInertia, 3e-3 * grid.rotationalInertia);
    }
    // A body's mass from a capsule shape is the same.
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.createBody(def);
    ShapeDef shape;
    shape.density = 2.0f;
    world.createShape(body, shape, level);
    EXPECT_FLOAT_EQ(world.bodyMass(body), m.mass);
    EXPECT_FLOAT_EQ(world.bodyRotationalInertia(body), m.rotationalInertia);
}

TEST(Capsule, BadCapsulesAreRefusedAndNothingChanges) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.createBody(def);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::uint64_t hash = world.stateHash();
    for (const Capsule& bad : {
             Capsule{{0, 0}, {0.001f, 0}, 0.5f},              // centres closer than the slop
             Capsule{{0, 0}, {0, 0}, 0.5f},                   // one point: a circle
             Capsule{{0, 0}, {1, 0}, 0.0f},                   // no radius
             Capsule{{0, 0}, {1, 0}, -0.5f},                  // negative radius
             Capsule{{0, 0}, {1, 0}, nan},                    // not a number
             Capsule{{nan, 0}, {1, 0}, 0.5f},                 // nor a point
             Capsule{{0, 0}, {1, 0}, 2.0f * kMaxCoordinate},  // too big
         }) {
        EXPECT_THROW(world.createShape(body, ShapeDef{}, bad), Error);
        EXPECT_THROW(computeMass(bad, 1.0f), Error);
        EXPECT_THROW(rayCast(bad, Transform{}, {-5, 0}, {10, 0}), Error);
    }
    EXPECT_EQ(world.stateHash(), hash);
    EXPECT_EQ(world.shapeCount(), 0);
    const Capsule good{{-1, 0.5f}, {1, -0.5f}, 0.3f};
    const ShapeId shape = world.createShape(body, ShapeDef{}, good);
    EXPECT_EQ(world.shapeType(shape), ShapeType::Capsule);
    EXPECT_EQ(world.shapeCapsule(shape).center1, good.center1);
    EXPECT_EQ(world.shapeCapsule(shape).center2, good.center2);
    EXPECT_EQ(world.shapeCapsule(shape).radius, good.radius);
    EXPECT_THROW(world.shapePolygon(shape), Error);
}

// Random capsules against each shape type, each manifold against the exact distance between
// the two cores: a contact exactly when the rounded shapes touch, and where the cores are apart
// its deepest point at their true distance less the radii (within 0.5% of the distance: a
// capsule lying nearly parallel on another is measured along the lower one's normal, the cosine
// of up to 6 degrees).
TEST(Capsule, ManifoldsAgreeWithTheDistanceOfTheCores) {
    std::mt19937 rng(99);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    const char* names[] = {"capsule", "polygon", "circle", "segment", "chain segment"};
    for (int kind = 0; kind < 5; ++kind) {
        int touching = 0, apart = 0, measured = 0;
        double largest = 0.0;
        for (int c = 0; c < 4000; ++c) {
            const float lengthB = uniform(0.1f, 2.0f);
            const float radiusB = uniform(0.05f, 0.6f);
            const ConvexPolygon capsule =
                checkedCapsule(Capsule{{-0.5f * lengthB, 0}, {0.5f * lengthB, 0}, radiusB});
            // Shape A: the other shape, at the origin turned; the capsule B nearby.
            const float angleA = uniform(-kPi, kPi);
            const Transform xfA{{0, 0}, Rot(angleA)};
            const float bx = uniform(-2.5f, 2.5f);
            const float by = uniform(-2.5f, 2.5f);
            // Now and then nearly parallel to A's x axis, where the two-point cases live.
            const float angleB =
                uniform(0.0f, 1.0f) < 0.3f ? angleA + uniform(-0.12f, 0.12f) : uniform(-kPi, kPi);
            const Transform xfB{{bx, by}, Rot(angleB)};
            Manifold m;
            ConvexPolygon a;
            float radiusA = 0.0f;
            if (kind == 0) {
                const float lengthA = uniform(0.1f, 3.0f);
                const float r = uniform(0.05f, 0.6f);
                a = checkedCapsule(Capsule{{-0.5f * lengthA, 0}, {0.5f * lengthA, 0}, r});
                collideCapsules(m, a, xfA, capsule, xfB);
            } else if (kind == 1) {
                const float hx = uniform(0.1f, 1.5f);
                const float hy = uniform(0.1f, 1.5f);
                EXPECT_TRUE(makeConvexPolygon(Polygon::box(hx, hy), a).empty());
                collidePolygons(m, a, xfA, capsule, xfB);
            } else if (kind == 2) {
                // The circle as a one-vertex core; the capsule is shape A of that pair.
                const float r = uniform(0.05f, 1.0f);
                a.count = 1;
                a.radius = r - kPolygonRadius;  // so collision radius = r below
                collidePolygonAndCircle(m, capsule, xfB, Circle{{0, 0}, r}, xfA);
            } else {
                const float half = uniform(0.2f, 3.0f);
                EdgeSegment e;
                e.v1 = {half, 0};
                e.v2 = {-half, 0};  // solid above (its right, looking from v1 to v2)
                e.ghost1 = {half + 1.0f, uniform(-0.5f, 0.5f)};
                e.ghost2 = {-half - 1.0f, uniform(-0.5f, 0.5f)};
                e.oneSided = kind == 4;
                EXPECT_TRUE(makeSegmentPolygon(Segment{e.v1, e.v2}, a).empty());
                collideSegmentAndCapsule(m, e, xfA, capsule, xfB);
                // A one-sided segment ignores a capsule whose centre is behind it, and a capsule
                // past an end is the neighbours' business: leave those out.
                if (kind == 4) {
                    const Vec2 local = inverseTransformPoint(xfA, xfB.p);
                    if (local.y < 0.0f || std::fabs(local.x) > half) continue;
                }
            }
            radiusA = kPolygonRadius + a.radius;
            const float total = radiusA + (kPolygonRadius + radiusB);
            const DistanceResult d =
                kind == 2 ? shapeDistance(DistanceProxy{{Vec2{0, 0}}, 1, 0.0f}, xfA,
                                          proxyOf(capsule), xfB, false)
                          : shapeDistance(proxyOf(a), xfA, proxyOf(capsule), xfB, false);
            const double cores = d.overlap ? 0.0 : d.distance;
            if (kind == 4 && !d.overlap) {
                // Closest at an end of the chain segment: whether it is this segment's or the
                // neighbour's depends on the ghost; left out here.
                const Vec2 onSegment = inverseTransformPoint(xfA, d.pointA);
                if (std::fabs(std::fabs(onSegment.x) - (a.vertices[0].x)) < 1e-4f) continue;
            }
            if (std::fabs(cores - total) < 1e-4) continue;  // on the edge: either is right
            const bool shouldTouch = cores < total;
            ASSERT_EQ(m.pointCount > 0, shouldTouch)
                << names[kind] << " case " << c << ": cores " << cores << " apart, radii " << total;
            if (!shouldTouch) {
                ++apart;
                continue;
            }
            ++touching;
            if (cores < 1e-3) continue;  // overlapping cores: depth is the solver's business
            const WorldManifold w =
                kind == 2 ? computeWorldManifold(m, xfB, kPolygonRadius + radiusB, xfA, radiusA)
                          : computeWorldManifold(m, xfA, radiusA, xfB, kPolygonRadius + radiusB);
            double deepest = 1e9;
            for (int i = 0; i < m.pointCount; ++i) {
                deepest = std::min(deepest, double(w.separations[i]));
            }
            const double error = std::fabs(deepest - (cores - total));
            largest = std::max(largest, error);
            ++measured;
            EXPECT_LE(error, 5e-3 * cores + 1e-5)
                << names[kind] << " case " << c << ": " << deepest << " against " << cores - total;
        }
        std::printf("capsule-%s: %d touching (%d measured), %d apart, largest error %.3g m\n",
                    names[kind], touching, measured, apart, largest);
        // A chain segment turns away half the cases (those behind it or at its ends).
        EXPECT_GT(touching, kind == 4 ? 150 : 300);
        EXPECT_GT(apart, 300);
    }
}

TEST(Capsule, EndToEndCapsulesTouchOnlyWhenTheirEndsDo) {
    const ConvexPolygon a = checkedCapsule(Capsule{{-1, 0}, {1, 0}, 0.2f});
    const ConvexPolygon b = checkedCapsule(Capsule{{-1, 0}, {1, 0}, 0.2f});
    const float reach = 2.0f * (0.2f + kPolygonRadius);
    Manifold m;
    // On one line, 0.1 m further apart than the two radii: no contact (every face axis of a
    // two-vertex polygon would say they overlap).
    collideCapsules(m, a, Transform{}, b, Transform{{2.0f + reach + 0.1f, 0}, Rot(0.0f)});
    EXPECT_EQ(m.pointCount, 0);
    collideCapsules(m, a, Transform{}, b, Transform{{2.0f + reach - 0.05f, 0}, Rot(0.0f)});
    ASSERT_EQ(m.pointCount, 1);
    const WorldManifold w = computeWorldManifold(m, Transform{}, 0.2f + kPolygonRadius,
                                                 Transform{{2.0f + reach - 0.05f, 0}, Rot(0.0f)},
                                                 0.2f + kPolygonRadius);
    EXPECT_NEAR(w.normal.x, 1.0f, 1e-6f);
    EXPECT_NEAR(w.separations[0], -0.05f, 1e-5f);
}

// Two capsules stacked crosswise on a floor, and one lying along another: they come to rest
// at the heights of their radii, the parallel pair on two points and without rocking.
TEST(Capsule, CapsulesRestOnEachOtherAndOnTheFloor) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(20.0f, 0.5f, {0, -0.5f}, 0.0f));
    auto capsuleBody = [&](Vec2 at, float angle, float radius) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = at;
        def.angle = angle;
        const BodyId body = world.createBody(def);
        world.createShape(body, ShapeDef{}, Capsule{{-1.0f, 0}, {1.0f, 0}, radius});
        return body;
    };
    const BodyId lower = capsuleBody({0, 0.3f}, 0.0f, 0.25f);
    const BodyId upper = capsuleBody({0.3f, 1.0f}, 0.0f, 0.25f);
    for (int i = 0; i < 180; ++i) world.step(kDt);
    const float skin = kPolygonRadius;
    // Resting contacts keep about the slop of overlap: within a centimetre of the touching
    // heights.
    EXPECT_NEAR(world.bodyPosition(lower).y, 0.25f + 2.0f * skin, 0.01f);
    EXPECT_NEAR(world.bodyPosition(upper).y, 0.75f + 4.0f * skin, 0.015f);
    EXPECT_LT(std::fabs(world.bodyAngle(upper)), 0.01f);
    EXPECT_LT(std::fabs(world.bodyAngularVelocity(upper)), 0.01f);
    bool twoPoints = false;
    for (const ContactData& c : world.contacts()) {
        const bool pair =
            (world.shapeBody(c.shapeA) == upper && world.shapeBody(c.shapeB) == lower) ||
            (world.shapeBody(c.shapeA) == lower && world.shapeBody(c.shapeB) == upper);
        if (pair) twoPoints = c.pointCount == 2;
    }
    EXPECT_TRUE(twoPoints);
}

TEST(Capsule, RaysAndPointsMeetItsOutline) {
    const Capsule c{{-1, 0}, {1, 0}, 0.5f};
    const Transform xf{{2, 1}, Rot(0.0f)};
    // Through the side, and into an end cap.
    const auto side = rayCast(c, xf, {2.5f, 5.0f}, {0, -10});
    ASSERT_TRUE(side.has_value());
    EXPECT_NEAR(side->point.y, 1.5f, 1e-5f);
    EXPECT_NEAR(side->normal.y, 1.0f, 1e-5f);
    const auto cap = rayCast(c, xf, {-5.0f, 1.3f}, {10, 0});
    ASSERT_TRUE(cap.has_value());
    EXPECT_NEAR(cap->point.x, 1.0f - std::sqrt(0.25f - 0.09f), 1e-5f);
    EXPECT_FALSE(rayCast(c, xf, {-5.0f, 1.6f}, {10, 0}).has_value());
    EXPECT_TRUE(testPoint(c, xf, {3.4f, 1.2f}));    // in the right cap
    EXPECT_FALSE(testPoint(c, xf, {3.45f, 1.4f}));  // just outside it
    EXPECT_TRUE(testPoint(c, xf, {2.0f, 1.49f}));
}
