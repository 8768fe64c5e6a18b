// Capsule against capsule, and segment against capsule (a segment being a capsule of no radius).
// A capsule is a segment (its core) rounded by its radius; two capsules touch where their cores
// come within the sum of their collision radii (each capsule's radius plus the skin
// kPolygonRadius). Against polygons and circles a capsule goes through those routines as a
// rounded polygon of two vertices: there the polygon's own faces supply the separating axes.
// Between two capsules they do not, since a two-vertex polygon has faces along one line only:
// two capsules end to end on one line would overlap on every axis the polygon routine tries.
// (And Box2D's segment routine clips to the segment's ends, which misses or misplaces a thick
// capsule's contact near an end.) So this routine works from the cores' closest points:
//  - nearly parallel cores (the angle's sine below 0.1) whose extents overlap by more than the
//    slop: two points, as a box on a box would have: B's core clipped to A's extent, each point
//    measured along A's normal (so a capsule lying on another rests on two points, not rocking
//    on one);
//  - ends of both closest (a corner of each): one point between them, as two discs meet
//    (ManifoldType::Circles, the normal following the ends as the bodies turn);
//  - otherwise: one point at the closest points, the normal along the line between them (or A's
//    normal, towards B, when the cores cross).
// A chain segment adds its one-sidedness (a capsule whose middle is behind it touches nothing)
// and its ghosts (a point at its end is left to the neighbour when the capsule is in the
// neighbour's face region, as a circle would be).
#include <cmath>
#include <utility>

#include "collision/clipping.h"
#include "collision/manifold.h"

namespace pivot {

namespace {

constexpr float kParallelSine = 0.1f;

// A feature of a capsule's core for a point at fraction f along it: an end, or the core itself.
void featureAt(float f, std::uint8_t& index, FeatureType& type) {
    if (f == 0.0f || f == 1.0f) {
        index = f == 0.0f ? 0 : 1;
        type = FeatureType::Vertex;
    } else {
        index = 0;
        type = FeatureType::Face;
    }
}

// The two-point manifold of nearly parallel cores, if they overlap along A by more than the
// slop and B's clipped core lies on one side of A's. p2, q2 (B's core) and towardB are in A's
// frame.
bool parallelCores(Manifold& manifold, const ConvexPolygon& capsuleA, const ConvexPolygon& capsuleB,
                   Vec2 p2, Vec2 q2, Vec2 towardB, float totalRadius) {
    const Vec2 p1 = capsuleA.vertices[0];
    const Vec2 axisA = capsuleA.vertices[1] - p1;
    const float lengthA = length(axisA);
    const Vec2 u = (1.0f / lengthA) * axisA;
    const Vec2 dB = q2 - p2;
    const float lengthB = length(dB);
    if (std::fabs(cross(u, dB)) > kParallelSine * lengthB) return false;
    // B's core as u runs from p2 to q2 projects onto A's axis from a0 to a1; keep the part
    // over A's extent [0, lengthA].
    const float a0 = dot(p2 - p1, u);
    const float a1 = dot(q2 - p1, u);
    const float span = a1 - a0;
    float lo = (0.0f - a0) / span;
    float hi = (lengthA - a0) / span;
    if (lo > hi) std::swap(lo, hi);
    lo = std::fmax(lo, 0.0f);
    hi = std::fmin(hi, 1.0f);
    if (!((hi - lo) * lengthB > kLinearSlop)) return false;
    Vec2 normal = cross(u, 1.0f);  // A's right-hand normal
    if (dot(normal, towardB) < 0.0f) normal = -normal;
    const float fractions[2] = {lo, hi};
    const Vec2 localB0 = capsuleB.vertices[0];
    const Vec2 localB1 = capsuleB.vertices[1];
    int count = 0;
    for (int i = 0; i < 2; ++i) {
        const Vec2 point = p2 + fractions[i] * dB;
        const float separation = dot(point - p1, normal);
        if (separation < 0.0f) return false;  // B's core crosses A's line: not a resting pair
        if (separation > totalRadius) continue;
        ManifoldPoint& mp = manifold.points[count++];
        mp = ManifoldPoint{};
        mp.localPoint = localB0 + fractions[i] * (localB1 - localB0);
        mp.id =
            makeFeatureId(0, static_cast<std::uint8_t>(i), FeatureType::Face, FeatureType::Vertex);
    }
    if (count == 0) return false;
    manifold.type = ManifoldType::FaceA;
    manifold.localNormal = normal;
    manifold.localPoint = p1;
    manifold.pointCount = count;
    return true;
}

}  // namespace

void collideCapsules(Manifold& manifold, const ConvexPolygon& capsuleA, const Transform& xfA,
                     const ConvexPolygon& capsuleB, const Transform& xfB) {
    manifold = Manifold{};
    const float totalRadius =
        (kPolygonRadius + capsuleA.radius) + (kPolygonRadius + capsuleB.radius);
    const Transform xf = relativeTransform(xfA, xfB);  // B's frame in A's
    const Vec2 p1 = capsuleA.vertices[0];
    const Vec2 q1 = capsuleA.vertices[1];
    const Vec2 p2 = transformPoint(xf, capsuleB.vertices[0]);
    const Vec2 q2 = transformPoint(xf, capsuleB.vertices[1]);

    float s = 0.0f, t = 0.0f;
    closestFractions(p1, q1, p2, q2, s, t);
    const Vec2 closestA = p1 + s * (q1 - p1);
    const Vec2 closestB = p2 + t * (q2 - p2);
    const Vec2 d = closestB - closestA;
    if (dot(d, d) > totalRadius * totalRadius) return;

    // Which way B lies from A: along the closest points, or, where the cores cross (or nearly:
    // the line between the closest points then has no reliable direction), along A's normal
    // towards B's middle.
    const float distance = length(d);
    const bool crossing = distance < 0.1f * kLinearSlop;
    const Vec2 towardB = crossing ? 0.5f * (p2 + q2) - 0.5f * (p1 + q1) : d;
    if (parallelCores(manifold, capsuleA, capsuleB, p2, q2, towardB, totalRadius)) return;

    std::uint8_t indexA = 0, indexB = 0;
    FeatureType typeA = FeatureType::Face, typeB = FeatureType::Face;
    featureAt(s, indexA, typeA);
    featureAt(t, indexB, typeB);
    manifold.points[0] = ManifoldPoint{};
    manifold.points[0].id = makeFeatureId(indexA, indexB, typeA, typeB);
    manifold.pointCount = 1;
    if (typeA == FeatureType::Vertex && typeB == FeatureType::Vertex && !crossing) {
        manifold.type = ManifoldType::Circles;
        manifold.localPoint = capsuleA.vertices[indexA];
        manifold.points[0].localPoint = capsuleB.vertices[indexB];
        return;
    }
    Vec2 normal;
    if (crossing) {
        normal = cross((1.0f / length(q1 - p1)) * (q1 - p1), 1.0f);
        if (dot(normal, towardB) < 0.0f) normal = -normal;
    } else {
        normal = (1.0f / distance) * d;
    }
    manifold.type = ManifoldType::FaceA;
    manifold.localNormal = normal;
    manifold.localPoint = closestA;
    manifold.points[0].localPoint = inverseTransformPoint(xf, closestB);
}

void collideSegmentAndCapsule(Manifold& manifold, const EdgeSegment& segmentA, const Transform& xfA,
                              const ConvexPolygon& capsuleB, const Transform& xfB) {
    manifold = Manifold{};
    const Transform xf = relativeTransform(xfA, xfB);
    const Vec2 v1 = segmentA.v1;
    const Vec2 v2 = segmentA.v2;
    if (segmentA.oneSided) {
        const Vec2 middle =
            transformPoint(xf, 0.5f * (capsuleB.vertices[0] + capsuleB.vertices[1]));
        if (cross(v2 - v1, middle - v1) > 0.0f) return;  // behind (left of v1 -> v2)
    }
    ConvexPolygon core;  // the segment as a capsule of no radius (its skin is added as usual)
    core.count = 2;
    core.vertices[0] = v1;
    core.vertices[1] = v2;
    collideCapsules(manifold, core, xfA, capsuleB, xfB);
    if (!segmentA.oneSided || manifold.pointCount != 1) return;
    // One point at an end of a chain segment: the neighbour's, as for a circle, when the
    // capsule's closest point is in the neighbour's face region.
    const std::uint32_t id = manifold.points[0].id;
    const bool atEnd = (id >> 16 & 0xFF) == std::uint32_t(FeatureType::Vertex);
    if (!atEnd) return;
    const Vec2 q = transformPoint(xf, manifold.points[0].localPoint);
    const bool first = (id & 0xFF) == 0;
    if ((first && dot(v1 - segmentA.ghost1, v1 - q) > 0.0f) ||
        (!first && dot(segmentA.ghost2 - v2, q - v2) > 0.0f)) {
        manifold = Manifold{};
    }
}

}  // namespace pivot
