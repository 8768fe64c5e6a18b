// Polygon against polygon: the contact manifold of two convex polygons, each with the skin
// kPolygonRadius.
//
// Algorithm (separating axes, then clipping; the decisions are Box2D 2.4.1's so that contacts
// match that engine step for step):
//  1. For each polygon, the face whose plane the other polygon's deepest vertex is furthest in
//     front of. If either separation exceeds the total radius, the shapes are apart.
//  2. The reference face is A's unless B's separation is larger by more than a small tolerance
//     (which keeps the choice from flickering between nearly equal faces).
//  3. The incident edge is the other polygon's edge whose normal is most anti-parallel to the
//     reference normal.
//  4. The incident edge is clipped against the two side planes through the ends of the
//     reference face (moved outward by the total radius); the clipped points that lie within
//     the total radius of the reference plane are the contact points.
// Rounded polygons add one case (not in Box2D 2.4.1, whose polygon radius is only the skin):
// when the cores are apart and their closest points are a corner of each, the rounded corners
// meet as two discs would, at the corners' true distance, with one point along the line between
// them (as Box2D v3 does). Measured along a face normal instead, two corners approaching
// diagonally would touch up to sqrt(2) times too early: a rounded box would rest on another's
// corner in mid-air. Between unrounded polygons nothing changes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "collision/clipping.h"
#include "collision/manifold.h"

namespace pivot {

namespace {

// Box2D's reference-face tolerance: B's face must beat A's by this much to become the
// reference, so that two nearly equal faces do not swap every step (m).
constexpr float kReferenceFaceTolerance = 0.1f * kLinearSlop;

struct FaceSeparation {
    int face = 0;
    float separation = 0.0f;  // m, largest over the faces of the first polygon
};

// The face of poly1 with the largest separation from poly2, measured in poly2's frame: for each
// face, the distance of poly2's deepest vertex in front of the face's plane.
#if defined(__SSE2__)
// Four faces at a time, one per lane, each lane doing the scalar form's operations in its order
// (below): the same separations to the bit, and minps keeps the scalar loop's choice
// (s < d ? s : d, NaN included). The lanes past poly1.count read the arrays' spare entries
// (fixed-size arrays, so always in bounds), and their results are never looked at.
FaceSeparation maxFaceSeparation(const ConvexPolygon& poly1, const Transform& xf1,
                                 const ConvexPolygon& poly2, const Transform& xf2) {
    static_assert(kMaxPolygonVertices % 4 == 0, "faces are read four at a time");
    const Transform xf = relativeTransform(xf2, xf1);
    const __m128 c = _mm_set1_ps(xf.q.c);
    const __m128 s = _mm_set1_ps(xf.q.s);
    const __m128 px = _mm_set1_ps(xf.p.x);
    const __m128 py = _mm_set1_ps(xf.p.y);
    alignas(16) float deepest[kMaxPolygonVertices];
    for (int i = 0; i < poly1.count; i += 4) {
        // Four Vec2s as their x lanes and their y lanes.
        auto split = [](const Vec2* four, __m128& x, __m128& y) {
            const __m128 low = _mm_loadu_ps(&four[0].x);
            const __m128 high = _mm_loadu_ps(&four[2].x);
            x = _mm_shuffle_ps(low, high, _MM_SHUFFLE(2, 0, 2, 0));
            y = _mm_shuffle_ps(low, high, _MM_SHUFFLE(3, 1, 3, 1));
        };
        __m128 lnx, lny, lvx, lvy;
        split(&poly1.normals[static_cast<std::size_t>(i)], lnx, lny);
        split(&poly1.vertices[static_cast<std::size_t>(i)], lvx, lvy);
        const __m128 nx = _mm_sub_ps(_mm_mul_ps(c, lnx), _mm_mul_ps(s, lny));
        const __m128 ny = _mm_add_ps(_mm_mul_ps(s, lnx), _mm_mul_ps(c, lny));
        const __m128 vx = _mm_add_ps(_mm_sub_ps(_mm_mul_ps(c, lvx), _mm_mul_ps(s, lvy)), px);
        const __m128 vy = _mm_add_ps(_mm_add_ps(_mm_mul_ps(s, lvx), _mm_mul_ps(c, lvy)), py);
        __m128 d = _mm_set1_ps(std::numeric_limits<float>::max());
        for (int j = 0; j < poly2.count; ++j) {
            const Vec2 w = poly2.vertices[static_cast<std::size_t>(j)];
            const __m128 dx = _mm_sub_ps(_mm_set1_ps(w.x), vx);
            const __m128 dy = _mm_sub_ps(_mm_set1_ps(w.y), vy);
            d = _mm_min_ps(_mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)), d);
        }
        _mm_store_ps(&deepest[i], d);
    }
    FaceSeparation best{0, -std::numeric_limits<float>::max()};
    for (int i = 0; i < poly1.count; ++i) {
        if (deepest[i] > best.separation) best = {i, deepest[i]};  // as below
    }
    return best;
}
#else
FaceSeparation maxFaceSeparation(const ConvexPolygon& poly1, const Transform& xf1,
                                 const ConvexPolygon& poly2, const Transform& xf2) {
    const Transform xf = relativeTransform(xf2, xf1);
    FaceSeparation best{0, -std::numeric_limits<float>::max()};
    for (int i = 0; i < poly1.count; ++i) {
        const Vec2 n = rotate(xf.q, poly1.normals[i]);
        const Vec2 v = transformPoint(xf, poly1.vertices[i]);
        float deepest = std::numeric_limits<float>::max();
        for (int j = 0; j < poly2.count; ++j) {
            const float s = dot(n, poly2.vertices[j] - v);
            if (s < deepest) deepest = s;
        }
        // Strictly greater: on an exact tie the lower face index wins, as in the reference.
        if (deepest > best.separation) best = {i, deepest};
    }
    return best;
}
#endif

// The incident edge (world frame) of poly2 against face `referenceFace` of poly1.
void findIncidentEdge(ClipVertex edge[2], const ConvexPolygon& poly1, const Transform& xf1,
                      int referenceFace, const ConvexPolygon& poly2, const Transform& xf2) {
    const Vec2 referenceNormal = inverseRotate(xf2.q, rotate(xf1.q, poly1.normals[referenceFace]));
    int incident = 0;
    float minDot = std::numeric_limits<float>::max();
    for (int i = 0; i < poly2.count; ++i) {
        const float d = dot(referenceNormal, poly2.normals[i]);
        if (d < minDot) {
            minDot = d;
            incident = i;
        }
    }
    const int i1 = incident;
    const int i2 = i1 + 1 < poly2.count ? i1 + 1 : 0;
    const auto face = static_cast<std::uint8_t>(referenceFace);
    edge[0] = {transformPoint(xf2, poly2.vertices[i1]), face, static_cast<std::uint8_t>(i1),
               FeatureType::Face, FeatureType::Vertex};
    edge[1] = {transformPoint(xf2, poly2.vertices[i2]), face, static_cast<std::uint8_t>(i2),
               FeatureType::Face, FeatureType::Vertex};
}

// Rounded polygons whose cores are apart with a corner of each closest: one point between the
// two corners, as a contact of two discs (ManifoldType::Circles). Returns false (the manifold
// untouched) in every other case.
bool roundedCornersMeet(Manifold& manifold, const ConvexPolygon& poly1, const Transform& xf1,
                        int face, const ClipVertex incident[2], const Transform& xf2,
                        bool referenceOnB, float totalRadius) {
    const int iv1 = face;
    const int iv2 = face + 1 < poly1.count ? face + 1 : 0;
    const Vec2 v1 = transformPoint(xf1, poly1.vertices[iv1]);
    const Vec2 v2 = transformPoint(xf1, poly1.vertices[iv2]);
    float s = 0.0f, t = 0.0f;
    closestFractions(v1, v2, incident[0].point, incident[1].point, s, t);
    const bool cornerOn1 = s == 0.0f || s == 1.0f;
    const bool cornerOn2 = t == 0.0f || t == 1.0f;
    if (!cornerOn1 || !cornerOn2) return false;
    const Vec2 corner1 = s == 0.0f ? v1 : v2;
    const ClipVertex& corner2 = t == 0.0f ? incident[0] : incident[1];
    manifold = Manifold{};
    if (lengthSquared(corner2.point - corner1) > totalRadius * totalRadius) return true;  // apart
    const std::uint8_t index1 = static_cast<std::uint8_t>(s == 0.0f ? iv1 : iv2);
    const Vec2 local1 = poly1.vertices[index1];
    const Vec2 local2 = inverseTransformPoint(xf2, corner2.point);
    manifold.type = ManifoldType::Circles;
    manifold.localPoint = referenceOnB ? local2 : local1;  // shape A's corner, in A's frame
    manifold.points[0] = ManifoldPoint{};
    manifold.points[0].localPoint = referenceOnB ? local1 : local2;
    manifold.points[0].id = referenceOnB ? makeFeatureId(corner2.incidentIndex, index1,
                                                         FeatureType::Vertex, FeatureType::Vertex)
                                         : makeFeatureId(index1, corner2.incidentIndex,
                                                         FeatureType::Vertex, FeatureType::Vertex);
    manifold.pointCount = 1;
    return true;
}

}  // namespace

void collidePolygons(Manifold& manifold, const ConvexPolygon& polygonA, const Transform& xfA,
                     const ConvexPolygon& polygonB, const Transform& xfB) {
    manifold = Manifold{};
    // Each polygon's skin beyond its rounding (for unrounded ones 2 kPolygonRadius exactly, as
    // Box2D's sum of two polygon radii).
    const float totalRadius =
        (kPolygonRadius + polygonA.radius) + (kPolygonRadius + polygonB.radius);

    const FaceSeparation onA = maxFaceSeparation(polygonA, xfA, polygonB, xfB);
    if (onA.separation > totalRadius) return;
    const FaceSeparation onB = maxFaceSeparation(polygonB, xfB, polygonA, xfA);
    if (onB.separation > totalRadius) return;

    // poly1 holds the reference face, poly2 the incident edge.
    const bool referenceOnB = onB.separation > onA.separation + kReferenceFaceTolerance;
    const ConvexPolygon& poly1 = referenceOnB ? polygonB : polygonA;
    const ConvexPolygon& poly2 = referenceOnB ? polygonA : polygonB;
    const Transform& xf1 = referenceOnB ? xfB : xfA;
    const Transform& xf2 = referenceOnB ? xfA : xfB;
    const int face = referenceOnB ? onB.face : onA.face;

    ClipVertex incidentEdge[2];
    findIncidentEdge(incidentEdge, poly1, xf1, face, poly2, xf2);

    const bool rounded = polygonA.radius > 0.0f || polygonB.radius > 0.0f;
    const float coreSeparation = referenceOnB ? onB.separation : onA.separation;
    if (rounded && coreSeparation > 0.1f * kLinearSlop &&
        roundedCornersMeet(manifold, poly1, xf1, face, incidentEdge, xf2, referenceOnB,
                           totalRadius)) {
        return;
    }

    const int iv1 = face;
    const int iv2 = face + 1 < poly1.count ? face + 1 : 0;
    const Vec2 localV1 = poly1.vertices[iv1];
    const Vec2 localV2 = poly1.vertices[iv2];

    // The normal is rebuilt from the edge itself, so it is exactly perpendicular to the side
    // planes' tangent (the stored normal may differ from it in the last bit).
    Vec2 localTangent = localV2 - localV1;
    const float edgeLength = length(localTangent);
    if (edgeLength >= std::numeric_limits<float>::epsilon()) {
        localTangent = (1.0f / edgeLength) * localTangent;
    }
    const Vec2 localNormal = cross(localTangent, 1.0f);
    const Vec2 planePoint = 0.5f * (localV1 + localV2);

    const Vec2 tangent = rotate(xf1.q, localTangent);
    const Vec2 normal = cross(tangent, 1.0f);
    const Vec2 v1 = transformPoint(xf1, localV1);
    const Vec2 v2 = transformPoint(xf1, localV2);

    const float frontOffset = dot(normal, v1);
    // The side planes are pushed out by the total radius: the rounded corners of the reference
    // face still support the incident edge a little beyond the face's ends.
    const float sideOffset1 = -dot(tangent, v1) + totalRadius;
    const float sideOffset2 = dot(tangent, v2) + totalRadius;

    ClipVertex clipped1[2];
    ClipVertex clipped2[2];
    // Fewer than two points left: the incident edge lies wholly beyond an end of the reference
    // face (the shapes approach corner to corner); like the reference, report no contact.
    if (clipSegmentToLine(clipped1, incidentEdge, -tangent, sideOffset1, iv1) < 2) return;
    if (clipSegmentToLine(clipped2, clipped1, tangent, sideOffset2, iv2) < 2) return;

    manifold.type = referenceOnB ? ManifoldType::FaceB : ManifoldType::FaceA;
    manifold.localNormal = localNormal;
    manifold.localPoint = planePoint;

    int count = 0;
    for (const ClipVertex& c : clipped2) {
        const float separation = dot(normal, c.point) - frontOffset;
        if (separation > totalRadius) continue;
        ManifoldPoint& mp = manifold.points[count++];
        mp.localPoint = inverseTransformPoint(xf2, c.point);
        // Ids always name shape A's feature first, whichever polygon held the reference face.
        mp.id =
            referenceOnB
                ? makeFeatureId(c.incidentIndex, c.referenceIndex, c.incidentType, c.referenceType)
                : makeFeatureId(c.referenceIndex, c.incidentIndex, c.referenceType, c.incidentType);
    }
    manifold.pointCount = count;
}

}  // namespace pivot
