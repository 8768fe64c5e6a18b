// pivot2d's segments and chain segments against Box2D 2.4.1's edges (b2EdgeShape, two-sided
// and one-sided with ghost vertices; b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon), bit for
// bit: over random configurations with fixed seeds, the two manifolds have the same type, point
// count, local normal, local point, and per point the same local point and feature id. The
// algorithms are the same (collision/collide_segments.cpp), so nothing is allowed to differ,
// but for the one case pivot2d adds: where Box2D reports nothing because a rounded polygon is
// past an end of the segment, pivot2d lets its rounding reach the segment; those cases are
// checked against Box2D's own GJK distance instead.
//
// The cases: an edge up to 4 m long at a random pose; for a chain segment, ghosts that turn
// the chain left or right at each end by up to about 80 degrees (convex and concave joins) or
// continue it straight; a circle or polygon (boxes, random hulls, some rounded) placed near the
// edge's line and ends, overlapping, touching and just apart, in front and behind.
#include <box2d/b2_distance.h>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "box2d_conversions.h"
#include "collision/geometry.h"
#include "collision/manifold.h"

using namespace pivot;

namespace {

using reference::toPivot;

float randomIn(std::mt19937& rng, float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
}

// The random cases, one draw per statement: the order in which function arguments are evaluated
// is unspecified, and a seed must give the same cases with any compiler.

struct EdgeCase {
    b2EdgeShape edge;
    EdgeSegment segment;
    float length = 0.0f;
};

// A point `distance` from `from` in the direction of `direction` turned by `turn` (rad).
b2Vec2 turned(b2Vec2 from, b2Vec2 direction, float turn, float distance) {
    const float c = std::cos(turn), s = std::sin(turn);
    b2Vec2 d(c * direction.x - s * direction.y, s * direction.x + c * direction.y);
    d.Normalize();
    return from + distance * d;
}

/// A segment up to 4 m long, its ends up to 0.3 m off its body's x axis; one-sided with ghosts,
/// or two-sided.
EdgeCase randomEdge(std::mt19937& rng, bool oneSided) {
    EdgeCase c;
    c.length = randomIn(rng, 0.2f, 4.0f);
    const float y1 = randomIn(rng, -0.3f, 0.3f);
    const float y2 = randomIn(rng, -0.3f, 0.3f);
    const b2Vec2 v1(-0.5f * c.length, y1), v2(0.5f * c.length, y2);
    if (!oneSided) {
        c.edge.SetTwoSided(v1, v2);
    } else {
        // A straight continuation now and then: the flat join is where catching would show.
        const float turn1 = randomIn(rng, 0.0f, 1.0f) < 0.2f ? 0.0f : randomIn(rng, -1.4f, 1.4f);
        const float turn2 = randomIn(rng, 0.0f, 1.0f) < 0.2f ? 0.0f : randomIn(rng, -1.4f, 1.4f);
        const float reach1 = randomIn(rng, 0.2f, 3.0f);
        const float reach2 = randomIn(rng, 0.2f, 3.0f);
        const b2Vec2 v0 = turned(v1, v1 - v2, turn1, reach1);
        const b2Vec2 v3 = turned(v2, v2 - v1, turn2, reach2);
        c.edge.SetOneSided(v0, v1, v2, v3);
    }
    c.segment.ghost1 = toPivot(c.edge.m_vertex0);
    c.segment.v1 = toPivot(c.edge.m_vertex1);
    c.segment.v2 = toPivot(c.edge.m_vertex2);
    c.segment.ghost2 = toPivot(c.edge.m_vertex3);
    c.segment.oneSided = oneSided;
    return c;
}

b2Transform randomPose(std::mt19937& rng) {
    const float x = randomIn(rng, -5, 5);
    const float y = randomIn(rng, -5, 5);
    const float angle = randomIn(rng, -kPi, kPi);
    b2Transform xf;
    xf.Set(b2Vec2(x, y), angle);
    return xf;
}

/// Around the edge at xfA, near its line and its ends (and past them), within `reach` of it.
b2Transform poseNearEdge(std::mt19937& rng, const b2Transform& xfA, float length, float reach) {
    const float along = randomIn(rng, -0.7f, 0.7f) * length;
    const float across = randomIn(rng, -1.0f, 1.0f) * reach;
    const float angle = randomIn(rng, -kPi, kPi);
    b2Transform xf;
    xf.Set(b2Mul(xfA, b2Vec2(along, across)), angle);
    return xf;
}

/// A box, or a hull of up to 8 points around a circle; a quarter of them rounded.
b2PolygonShape randomPolygon(std::mt19937& rng, float& rounding, float& size, bool& hull) {
    b2PolygonShape shape;
    hull = randomIn(rng, 0.0f, 1.0f) >= 0.5f;
    if (!hull) {
        const float hx = randomIn(rng, 0.1f, 1.5f);
        const float hy = randomIn(rng, 0.1f, 1.5f);
        shape.SetAsBox(hx, hy);
        size = std::max(hx, hy);
    } else {
        const int n = 3 + static_cast<int>(randomIn(rng, 0.0f, 5.99f));
        const float scale = randomIn(rng, 0.2f, 1.5f);
        const float start = randomIn(rng, -kPi, kPi);
        b2Vec2 points[b2_maxPolygonVertices];
        for (int i = 0; i < n; ++i) {
            const float jitter = randomIn(rng, -0.3f, 0.3f);
            const float r = scale * randomIn(rng, 0.5f, 1.0f);
            const float angle = start + 2.0f * kPi / static_cast<float>(n) * (i + jitter);
            points[i].Set(r * std::cos(angle), r * std::sin(angle));
        }
        shape.Set(points, n);
        size = scale;
    }
    rounding = randomIn(rng, 0.0f, 1.0f) < 0.25f ? randomIn(rng, 0.01f, 0.3f) : 0.0f;
    shape.m_radius = kPolygonRadius + rounding;
    size += rounding;
    return shape;
}

ManifoldType typeOf(const b2Manifold& m) {
    switch (m.type) {
        case b2Manifold::e_circles: return ManifoldType::Circles;
        case b2Manifold::e_faceA: return ManifoldType::FaceA;
        case b2Manifold::e_faceB: return ManifoldType::FaceB;
    }
    return ManifoldType::Circles;
}

bool same(Vec2 a, b2Vec2 b) {
    return a.x == b.x && a.y == b.y;
}

struct Counts {
    int cases = 0, touching = 0, twoPoints = 0, faceB = 0, circles = 0;
};

// Everything the contact solver reads, compared bit for bit.
void expectSameManifold(const Manifold& ours, const b2Manifold& theirs, Counts& counts,
                        const char* what, int c) {
    ++counts.cases;
    ASSERT_EQ(ours.pointCount, theirs.pointCount) << what << " case " << c;
    if (ours.pointCount == 0) return;
    ++counts.touching;
    counts.twoPoints += ours.pointCount == 2;
    counts.faceB += theirs.type == b2Manifold::e_faceB;
    counts.circles += theirs.type == b2Manifold::e_circles;
    EXPECT_EQ(ours.type, typeOf(theirs)) << what << " case " << c;
    if (theirs.type != b2Manifold::e_circles) {
        EXPECT_TRUE(same(ours.localNormal, theirs.localNormal)) << what << " case " << c;
    }
    EXPECT_TRUE(same(ours.localPoint, theirs.localPoint)) << what << " case " << c;
    for (int i = 0; i < ours.pointCount; ++i) {
        EXPECT_TRUE(same(ours.points[i].localPoint, theirs.points[i].localPoint))
            << what << " case " << c << " point " << i;
        EXPECT_EQ(ours.points[i].id, theirs.points[i].id.key)
            << what << " case " << c << " point " << i;
    }
}

void report(const char* what, const Counts& counts) {
    std::printf(
        "%s: %d cases, %d touching (%d with two points, %d on the polygon's face, %d at "
        "an end of the segment)\n",
        what, counts.cases, counts.touching, counts.twoPoints, counts.faceB, counts.circles);
}

void circleCases(unsigned seed, bool oneSided, const char* what) {
    std::mt19937 rng(seed);
    Counts counts;
    for (int c = 0; c < 20000; ++c) {
        const EdgeCase e = randomEdge(rng, oneSided);
        b2CircleShape circle;
        circle.m_radius = randomIn(rng, 0.05f, 1.0f);
        circle.m_p.Set(randomIn(rng, -0.5f, 0.5f), 0.0f);
        const b2Transform bxfA = randomPose(rng);
        const b2Transform bxfB = poseNearEdge(rng, bxfA, e.length, circle.m_radius + 0.5f);
        b2Manifold theirs;
        b2CollideEdgeAndCircle(&theirs, &e.edge, bxfA, &circle, bxfB);
        Manifold ours;
        collideSegmentAndCircle(ours, e.segment, toPivot(bxfA), toPivot(circle), toPivot(bxfB));
        expectSameManifold(ours, theirs, counts, what, c);
        if (::testing::Test::HasFatalFailure()) return;
    }
    report(what, counts);
    // A one-sided segment turns away the half of the cases behind it.
    EXPECT_GT(counts.touching, counts.cases / (oneSided ? 8 : 5));
    EXPECT_GT(counts.circles, counts.touching / 20);
}

void polygonCases(unsigned seed, bool oneSided, const char* what) {
    std::mt19937 rng(seed);
    Counts counts;
    int roundedPastEnd = 0;
    for (int c = 0; c < 20000; ++c) {
        const EdgeCase e = randomEdge(rng, oneSided);
        float rounding = 0.0f, size = 0.0f;
        bool hull = false;
        const b2PolygonShape polygon = randomPolygon(rng, rounding, size, hull);
        const b2Transform bxfA = randomPose(rng);
        const b2Transform bxfB = poseNearEdge(rng, bxfA, e.length, size + 0.05f);
        b2Manifold theirs;
        b2CollideEdgeAndPolygon(&theirs, &e.edge, bxfA, &polygon, bxfB);
        ConvexPolygon shapeB = toPivot(polygon);
        shapeB.radius = rounding;
        // A hull's centroid as pivot2d computes it for its own polygons (SetAsBox instead
        // writes the box's centre).
        if (hull) {
            EXPECT_TRUE(
                same(polygonCentroid(shapeB.vertices.data(), shapeB.count), polygon.m_centroid))
                << what << " case " << c;
        }
        Manifold ours;
        collideSegmentAndPolygon(ours, e.segment, toPivot(bxfA), shapeB, toPivot(bxfB));
        if (rounding > 0.0f && theirs.pointCount == 0 && ours.pointCount == 1) {
            // The one case pivot2d adds: a rounded polygon past an end of the segment that its
            // rounding still reaches (Box2D's clip stops at the end). One point, at the cores'
            // closest points: its separation must be Box2D's GJK distance of the cores less the
            // two radii.
            ++roundedPastEnd;
            b2DistanceInput input;
            input.proxyA.Set(&e.edge, 0);
            input.proxyB.Set(&polygon, 0);
            input.transformA = bxfA;
            input.transformB = bxfB;
            input.useRadii = false;
            b2SimplexCache cache;
            cache.count = 0;
            b2DistanceOutput output;
            b2Distance(&output, &cache, &input);
            const WorldManifold w = computeWorldManifold(ours, toPivot(bxfA), kPolygonRadius,
                                                         toPivot(bxfB), polygon.m_radius);
            EXPECT_NEAR(w.separations[0], output.distance - (polygon.m_radius + kPolygonRadius),
                        1e-5f)
                << what << " case " << c;
            continue;
        }
        expectSameManifold(ours, theirs, counts, what, c);
        if (::testing::Test::HasFatalFailure()) return;
    }
    report(what, counts);
    std::printf("%s: %d more where a rounded polygon past an end reaches it (not in Box2D)\n", what,
                roundedPastEnd);
    EXPECT_GT(roundedPastEnd, 0);
    EXPECT_GT(counts.touching, counts.cases / (oneSided ? 8 : 5));
    EXPECT_GT(counts.twoPoints, counts.touching / 10);
    EXPECT_GT(counts.faceB, counts.touching / 20);
}

}  // namespace

TEST(SegmentReference, TwoSidedAgainstACircleMatchesBox2dBitForBit) {
    circleCases(41, false, "segment-circle");
}

TEST(SegmentReference, TwoSidedAgainstAPolygonMatchesBox2dBitForBit) {
    polygonCases(43, false, "segment-polygon");
}

TEST(SegmentReference, ChainSegmentAgainstACircleMatchesBox2dBitForBit) {
    circleCases(47, true, "chain segment-circle");
}

TEST(SegmentReference, ChainSegmentAgainstAPolygonMatchesBox2dBitForBit) {
    polygonCases(53, true, "chain segment-polygon");
}
