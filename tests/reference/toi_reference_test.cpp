// GJK (collision/distance.h) and the time of impact (collision/time_of_impact.h) against Box2D
// 2.4.1's b2Distance and b2TimeOfImpact on random polygons and circles in random poses and
// sweeps: the same algorithm in the same float operations, so the results must be identical to
// the bit (continuous collision agrees with Box2D's bit for bit only if they are).
#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "box2d_conversions.h"
#include "collision/distance.h"
#include "collision/time_of_impact.h"

using namespace pivot;
using reference::toPivot;

namespace {

float randomIn(std::mt19937& rng, float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// A shape in both engines: a polygon of 3 to 8 vertices (or a box) up to 1.5 m across, or a
// circle up to 0.5 m, with Box2D's radius (its skin, or the circle's own).
struct BothShapes {
    b2DistanceProxy box2d;
    b2PolygonShape polygon;
    b2CircleShape circle;
    DistanceProxy pivot;
};

void randomShape(std::mt19937& rng, BothShapes& out) {
    const float kind = randomIn(rng, 0.0f, 1.0f);
    if (kind < 0.25f) {
        out.circle.m_p.Set(randomIn(rng, -0.2f, 0.2f), randomIn(rng, -0.2f, 0.2f));
        out.circle.m_radius = randomIn(rng, 0.02f, 0.5f);
        out.box2d.Set(&out.circle, 0);
    } else if (kind < 0.5f) {
        const float hx = randomIn(rng, 0.01f, 1.5f);
        const float hy = randomIn(rng, 0.01f, 1.5f);
        out.polygon.SetAsBox(hx, hy);
        out.box2d.Set(&out.polygon, 0);
    } else {
        b2Vec2 points[b2_maxPolygonVertices];
        const int count = 3 + static_cast<int>(randomIn(rng, 0.0f, 5.99f));
        const float radius = randomIn(rng, 0.05f, 1.5f);
        for (int k = 0; k < count; ++k) {
            const float angle = (k + randomIn(rng, 0.1f, 0.6f)) * 2.0f * b2_pi / count;
            points[k].Set(radius * std::cos(angle), radius * std::sin(angle));
        }
        out.polygon.Set(points, count);
        out.box2d.Set(&out.polygon, 0);
    }
    out.pivot.count = out.box2d.m_count;
    out.pivot.radius = out.box2d.m_radius;
    for (int k = 0; k < out.box2d.m_count; ++k)
        out.pivot.vertices[k] = toPivot(out.box2d.m_vertices[k]);
}

b2Transform randomTransform(std::mt19937& rng, float extent) {
    const float x = randomIn(rng, -extent, extent);
    const float y = randomIn(rng, -extent, extent);
    const float angle = randomIn(rng, -4.0f, 4.0f);
    return b2Transform(b2Vec2(x, y), b2Rot(angle));
}

// A sweep that may cover metres and turn by a few radians, starting part-way into the step.
void randomSweep(std::mt19937& rng, b2Sweep& box2d, Sweep& pivot) {
    box2d.localCenter.Set(randomIn(rng, -0.3f, 0.3f), randomIn(rng, -0.3f, 0.3f));
    const float x0 = randomIn(rng, -3.0f, 3.0f);
    const float y0 = randomIn(rng, -3.0f, 3.0f);
    box2d.c0.Set(x0, y0);
    const float dx = randomIn(rng, -8.0f, 8.0f);
    const float dy = randomIn(rng, -8.0f, 8.0f);
    box2d.c.Set(x0 + dx, y0 + dy);
    box2d.a0 = randomIn(rng, -20.0f, 20.0f);
    box2d.a = box2d.a0 + randomIn(rng, -3.0f, 3.0f);
    box2d.alpha0 = randomIn(rng, 0.0f, 1.0f) < 0.7f ? 0.0f : randomIn(rng, 0.0f, 0.9f);
    pivot.localCenter = toPivot(box2d.localCenter);
    pivot.c0 = toPivot(box2d.c0);
    pivot.c = toPivot(box2d.c);
    pivot.a0 = box2d.a0;
    pivot.a = box2d.a;
    pivot.alpha0 = box2d.alpha0;
}

}  // namespace

TEST(DistanceReference, GjkIsBox2dsBitForBitWithAndWithoutACache) {
    std::mt19937 rng(71);
    int withCache = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        BothShapes a, b;
        randomShape(rng, a);
        randomShape(rng, b);
        b2DistanceInput input;
        input.proxyA = a.box2d;
        input.proxyB = b.box2d;
        input.useRadii = false;
        b2SimplexCache box2dCache;
        box2dCache.count = 0;
        SimplexCache cache;
        // Three calls on poses a little apart, each starting from the last one's simplex.
        input.transformA = randomTransform(rng, 2.0f);
        input.transformB = randomTransform(rng, 2.0f);
        for (int call = 0; call < 3; ++call) {
            b2DistanceOutput expected;
            b2Distance(&expected, &box2dCache, &input);
            const DistanceResult got = coreDistance(a.pivot, toPivot(input.transformA), b.pivot,
                                                    toPivot(input.transformB), cache);
            ASSERT_TRUE(sameBits(got.distance, expected.distance))
                << "trial " << trial << " call " << call << ": " << got.distance << " vs "
                << expected.distance;
            ASSERT_TRUE(sameBits(got.pointA.x, expected.pointA.x) &&
                        sameBits(got.pointA.y, expected.pointA.y) &&
                        sameBits(got.pointB.x, expected.pointB.x) &&
                        sameBits(got.pointB.y, expected.pointB.y))
                << "trial " << trial << " call " << call;
            ASSERT_EQ(got.iterations, expected.iterations) << "trial " << trial;
            ASSERT_EQ(cache.count, box2dCache.count) << "trial " << trial;
            ASSERT_TRUE(sameBits(cache.metric, box2dCache.metric)) << "trial " << trial;
            for (int i = 0; i < cache.count; ++i) {
                ASSERT_EQ(cache.indexA[i], box2dCache.indexA[i]);
                ASSERT_EQ(cache.indexB[i], box2dCache.indexB[i]);
            }
            if (call > 0 && cache.count > 1) ++withCache;
            const float nudge = randomIn(rng, -0.05f, 0.05f);
            input.transformA.p.x += nudge;
            input.transformB.q = b2Rot(input.transformB.q.GetAngle() + nudge);
        }
    }
    EXPECT_GT(withCache, 1000);  // the cached path was exercised
}

TEST(TimeOfImpactReference, IsBox2dsBitForBit) {
    std::mt19937 rng(72);
    int touching = 0, separated = 0, overlapped = 0, failed = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        BothShapes a, b;
        randomShape(rng, a);
        randomShape(rng, b);
        b2TOIInput input;
        input.proxyA = a.box2d;
        input.proxyB = b.box2d;
        Sweep sweepA, sweepB;
        randomSweep(rng, input.sweepA, sweepA);
        randomSweep(rng, input.sweepB, sweepB);
        input.tMax = randomIn(rng, 0.0f, 1.0f) < 0.8f ? 1.0f : randomIn(rng, 0.1f, 1.0f);
        b2TOIOutput expected;
        b2TimeOfImpact(&expected, &input);
        const ImpactResult got = timeOfImpact(a.pivot, sweepA, b.pivot, sweepB, input.tMax);
        ImpactState expectedState = ImpactState::Failed;
        switch (expected.state) {
            case b2TOIOutput::e_overlapped: expectedState = ImpactState::Overlapped; break;
            case b2TOIOutput::e_touching: expectedState = ImpactState::Touching; break;
            case b2TOIOutput::e_separated: expectedState = ImpactState::Separated; break;
            default: expectedState = ImpactState::Failed; break;
        }
        ASSERT_EQ(got.state, expectedState) << "trial " << trial;
        ASSERT_TRUE(sameBits(got.t, expected.t))
            << "trial " << trial << ": " << got.t << " vs " << expected.t;
        switch (got.state) {
            case ImpactState::Touching: ++touching; break;
            case ImpactState::Separated: ++separated; break;
            case ImpactState::Overlapped: ++overlapped; break;
            case ImpactState::Failed: ++failed; break;
        }
    }
    // Every outcome was met, so every branch was compared.
    EXPECT_GT(touching, 1000);
    EXPECT_GT(separated, 1000);
    EXPECT_GT(overlapped, 100);
    std::printf("touching %d, separated %d, overlapped %d, failed %d\n", touching, separated,
                overlapped, failed);
}

TEST(TimeOfImpactReference, SweepsAdvanceAndTransformAsBox2ds) {
    std::mt19937 rng(73);
    for (int trial = 0; trial < 10000; ++trial) {
        b2Sweep expected;
        Sweep got;
        randomSweep(rng, expected, got);
        const float beta = randomIn(rng, 0.0f, 1.0f);
        b2Transform xfExpected;
        expected.GetTransform(&xfExpected, beta);
        const Transform xf = got.transformAt(beta);
        ASSERT_TRUE(sameBits(xf.p.x, xfExpected.p.x) && sameBits(xf.p.y, xfExpected.p.y) &&
                    sameBits(xf.q.s, xfExpected.q.s) && sameBits(xf.q.c, xfExpected.q.c));
        const float alpha = got.alpha0 + (1.0f - got.alpha0) * randomIn(rng, 0.0f, 0.99f);
        expected.Advance(alpha);
        got.advance(alpha);
        ASSERT_TRUE(sameBits(got.c0.x, expected.c0.x) && sameBits(got.c0.y, expected.c0.y) &&
                    sameBits(got.a0, expected.a0));
    }
}
