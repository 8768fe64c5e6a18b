// GJK distances (src/collision/distance.h) against brute force: for two convex polygons apart,
// the smallest distance from a vertex of one to an edge of the other; overlap exactly when no
// edge normal of either separates them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "collision/distance.h"
#include "collision/geometry.h"

using namespace pivot;

namespace {

double pointSegment(Vec2 p, Vec2 a, Vec2 b) {
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    const double px = double(p.x) - a.x, py = double(p.y) - a.y;
    double t = (px * ex + py * ey) / (ex * ex + ey * ey);
    t = std::clamp(t, 0.0, 1.0);
    const double dx = px - t * ex, dy = py - t * ey;
    return std::sqrt(dx * dx + dy * dy);
}

std::vector<Vec2> worldVertices(const DistanceProxy& p, const Transform& xf) {
    std::vector<Vec2> out;
    for (int i = 0; i < p.count; ++i) out.push_back(transformPoint(xf, p.vertices[i]));
    return out;
}

// Whether some edge normal of `a` separates the two (counter-clockwise) polygons.
bool separatedByAnEdgeOf(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Vec2 p = a[i], q = a[(i + 1) % a.size()];
        const double nx = double(q.y) - p.y, ny = double(p.x) - q.x;  // outward for CCW
        double nearest = 1e30;
        for (Vec2 v : b)
            nearest = std::min(nearest, nx * (double(v.x) - p.x) + ny * (double(v.y) - p.y));
        if (nearest > 0.0) return true;
    }
    return false;
}

double bruteDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    double best = 1e30;
    for (std::size_t i = 0; i < b.size(); ++i) {
        for (Vec2 p : a) best = std::min(best, pointSegment(p, b[i], b[(i + 1) % b.size()]));
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (Vec2 p : b) best = std::min(best, pointSegment(p, a[i], a[(i + 1) % a.size()]));
    }
    return best;
}

DistanceProxy randomPolygon(std::mt19937& rng) {
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    Polygon p;
    p.count = 3 + static_cast<int>(uniform(0.0f, 5.99f));
    const float radius = uniform(0.2f, 2.0f);
    for (int k = 0; k < p.count; ++k) {
        const float angle = (k + uniform(0.1f, 0.6f)) * 2.0f * kPi / p.count;
        p.vertices[k] = {radius * std::cos(angle), radius * std::sin(angle)};
    }
    ConvexPolygon checked;
    DistanceProxy proxy;
    if (!makeConvexPolygon(p, checked).empty()) return proxy;  // count 0: skipped
    proxy.count = checked.count;
    for (int k = 0; k < checked.count; ++k) proxy.vertices[k] = checked.vertices[k];
    return proxy;
}

}  // namespace

TEST(ShapeDistance, AgreesWithBruteForceOnRandomPolygons) {
    std::mt19937 rng(11);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    int apart = 0, overlapping = 0, maxIterations = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const DistanceProxy a = randomPolygon(rng);
        const DistanceProxy b = randomPolygon(rng);
        if (a.count == 0 || b.count == 0) continue;
        const Transform xfA{{uniform(-50, 50), uniform(-50, 50)}, Rot(uniform(-kPi, kPi))};
        const Transform xfB{xfA.p + Vec2{uniform(-5, 5), uniform(-5, 5)}, Rot(uniform(-kPi, kPi))};
        const DistanceResult r = shapeDistance(a, xfA, b, xfB, false);
        maxIterations = std::max(maxIterations, r.iterations);
        const std::vector<Vec2> wa = worldVertices(a, xfA), wb = worldVertices(b, xfB);
        const bool separated = separatedByAnEdgeOf(wa, wb) || separatedByAnEdgeOf(wb, wa);
        if (!separated) {
            ++overlapping;
            EXPECT_TRUE(r.overlap) << trial;
            EXPECT_EQ(r.distance, 0.0f) << trial;
            continue;
        }
        ++apart;
        const double expected = bruteDistance(wa, wb);
        // Touching within round-off may read as overlap; anything else must agree.
        if (r.overlap) {
            EXPECT_LT(expected, 1e-4) << trial;
            continue;
        }
        EXPECT_NEAR(r.distance, expected, 1e-4 + 1e-5 * expected) << trial;
        // The witness points are on the shapes, as far apart as the distance says.
        EXPECT_NEAR(length(r.pointB - r.pointA), r.distance, 1e-4f) << trial;
    }
    EXPECT_GT(apart, 5000);
    EXPECT_GT(overlapping, 2000);
    EXPECT_LE(maxIterations, 20);
}

TEST(ShapeDistance, CountsRadiiWhenAsked) {
    DistanceProxy circle;  // a circle of radius 0.5 at its body's origin
    circle.count = 1;
    circle.radius = 0.5f;
    DistanceProxy segment;  // a segment from (-1, 0) to (1, 0) with a 0.01 m skin
    segment.count = 2;
    segment.vertices[0] = {-1.0f, 0.0f};
    segment.vertices[1] = {1.0f, 0.0f};
    segment.radius = 0.01f;
    const Transform at2{{0.3f, 2.0f}, Rot(0.0f)};
    const Transform identity{{0.0f, 0.0f}, Rot(0.0f)};
    const DistanceResult cores = shapeDistance(segment, identity, circle, at2, false);
    EXPECT_NEAR(cores.distance, 2.0f, 1e-6f);
    const DistanceResult rounded = shapeDistance(segment, identity, circle, at2, true);
    EXPECT_NEAR(rounded.distance, 2.0f - 0.51f, 1e-6f);
    EXPECT_NEAR(rounded.pointA.y, 0.01f, 1e-6f);
    EXPECT_NEAR(rounded.pointB.y, 1.5f, 1e-6f);
    const Transform close{{0.3f, 0.4f}, Rot(0.0f)};
    EXPECT_TRUE(shapeDistance(segment, identity, circle, close, true).overlap);
    EXPECT_FALSE(shapeDistance(segment, identity, circle, close, false).overlap);
}
