// Segments (two-sided) and chain segments (one-sided, with the chain's neighbouring points as
// ghosts) against circles and polygons. The decisions are Box2D 2.4.1's edge routines', so that
// contacts on its edges and chains can be compared with it bit for bit.
//
// The segment runs from v1 to v2; its normal n = perp(v2 - v1) points to the right looking from
// v1 at v2. A one-sided segment is solid only on that side: a shape whose centre (a circle's, a
// polygon's centroid) is behind the line touches nothing, so a body inside a closed chain that
// winds counter-clockwise cannot leave it, and one that arrives from behind passes through.
//
// Ghosts. At a join of two chain segments, a body sliding along the chain must not catch on the
// shared corner. The ghost vertices g1 (before v1) and g2 (after v2) tell each segment what its
// neighbours are:
//  - a circle in the corner region beyond v1 (or v2) belongs to the neighbouring segment when it
//    is in that segment's own face region: this segment leaves it alone;
//  - a polygon's contact normal n_c is checked against the Gauss map at each end. At a convex
//    join (the chain turns right, away from the body) normals between this face's and the
//    neighbour's are the corner's own, and a normal tilted past the neighbour's face normal by
//    more than sin = 0.1 is the neighbour's business (skipped). At a concave join the corner
//    cannot be reached, so any normal snaps to this segment's face normal.
// (Box2D's note on the idea: https://box2d.org/posts/2020/06/ghost-collisions/.)
//
// Segment against polygon is a separating-axis test with two candidate axes from the segment
// (+n and -n) and one per polygon face, the polygon's axis preferred only when it separates by
// clearly more (0.98 relative, 1 mm absolute hysteresis), then clipping as for two polygons.
// One case is added (not in Box2D 2.4.1, whose polygons have only the thin skin): where the
// clip leaves nothing because a rounded polygon is past an end of the segment, its rounding may
// still reach the segment; one point then joins the cores' closest points (unless, at a chain's
// join, it is the neighbour's, as for a circle). Capsules have a routine of their own
// (collide_capsules.cpp).
#include <limits>

#include "collision/clipping.h"
#include "collision/distance.h"
#include "collision/manifold.h"

namespace pivot {

namespace {

// The reference engine's normalisation: unchanged when shorter than float epsilon.
Vec2 normalizedOrUnchanged(Vec2 v) {
    const float len = length(v);
    if (len < std::numeric_limits<float>::epsilon()) return v;
    const float inv = 1.0f / len;
    return {v.x * inv, v.y * inv};
}

// Right-hand perpendicular: the outward normal of an edge followed counter-clockwise.
Vec2 rightOf(Vec2 v) {
    return {v.y, -v.x};
}

void setCircleManifold(Manifold& manifold, ManifoldType type, Vec2 localNormal, Vec2 localPoint,
                       const Circle& circle, std::uint32_t id) {
    manifold.type = type;
    manifold.localNormal = localNormal;
    manifold.localPoint = localPoint;
    manifold.points[0] = ManifoldPoint{};
    manifold.points[0].localPoint = circle.center;
    manifold.points[0].id = id;
    manifold.pointCount = 1;
}

// A candidate contact normal with how far the shapes are apart along it.
struct Axis {
    enum class Owner : std::uint8_t { Segment, Polygon } owner = Owner::Segment;
    int index = -1;  // the polygon's face, for a polygon axis
    float separation = -std::numeric_limits<float>::max();
    Vec2 normal;
};

// The segment's axis, +n or -n: for each, the polygon's deepest vertex; the axis along which
// that vertex is least deep wins (+n on a tie).
Axis segmentAxis(const ConvexPolygon& polygon, Vec2 v1, Vec2 normal) {
    Axis best;
    const Vec2 candidates[2] = {normal, -normal};
    for (int j = 0; j < 2; ++j) {
        float deepest = std::numeric_limits<float>::max();
        for (int i = 0; i < polygon.count; ++i) {
            const float s = dot(candidates[j], polygon.vertices[i] - v1);
            if (s < deepest) deepest = s;
        }
        if (deepest > best.separation) {
            best.index = j;
            best.separation = deepest;
            best.normal = candidates[j];
        }
    }
    return best;
}

// The polygon face that best separates it from the segment (the segment's nearer end).
Axis polygonAxis(const ConvexPolygon& polygon, Vec2 v1, Vec2 v2) {
    Axis best;
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 n = -polygon.normals[i];
        const float s1 = dot(n, polygon.vertices[i] - v1);
        const float s2 = dot(n, polygon.vertices[i] - v2);
        const float s = s1 < s2 ? s1 : s2;
        if (s > best.separation) best = {Axis::Owner::Polygon, i, s, n};
    }
    return best;
}

// A rounded polygon past an end of the segment: the clip found nothing, but the rounding may
// still reach the segment. GJK gives the cores' closest points; within reach, one point between
// them: as two discs (ManifoldType::Circles) where they are the segment's end and a corner,
// along the line between them otherwise (FaceA). At a chain segment's end the point is the
// neighbour's when the polygon's closest point is in that segment's face region, as for a
// circle. Leaves the manifold empty otherwise.
void roundedPolygonReachesEnd(Manifold& manifold, const EdgeSegment& edge,
                              const ConvexPolygon& polygonB, const Transform& xf, float radius) {
    manifold = Manifold{};
    DistanceProxy segmentCore;
    segmentCore.count = 2;
    segmentCore.vertices[0] = edge.v1;
    segmentCore.vertices[1] = edge.v2;
    DistanceProxy polygonCore;
    polygonCore.count = polygonB.count;
    for (int i = 0; i < polygonB.count; ++i) polygonCore.vertices[i] = polygonB.vertices[i];
    const DistanceResult d = shapeDistance(segmentCore, Transform{}, polygonCore, xf, false);
    if (d.overlap || d.distance > radius || !(d.distance > 0.0f)) return;
    const Vec2 onSegment = d.pointA;  // in the segment's frame (its transform was the identity)
    const Vec2 onPolygon = d.pointB;
    const int end = onSegment == edge.v1 ? 0 : (onSegment == edge.v2 ? 1 : -1);
    if (edge.oneSided && end == 0 && dot(edge.v1 - edge.ghost1, edge.v1 - onPolygon) > 0.0f) return;
    if (edge.oneSided && end == 1 && dot(edge.ghost2 - edge.v2, onPolygon - edge.v2) > 0.0f) return;
    const Vec2 local = inverseTransformPoint(xf, onPolygon);
    // A corner when the witness point is one (up to the round trip through the transform).
    int corner = -1;
    for (int i = 0; i < polygonB.count; ++i) {
        if (lengthSquared(polygonB.vertices[i] - local) < 1e-12f) corner = i;
    }
    manifold.points[0] = ManifoldPoint{};
    manifold.pointCount = 1;
    if (end >= 0 && corner >= 0) {
        manifold.type = ManifoldType::Circles;
        manifold.localPoint = onSegment;
        manifold.points[0].localPoint = polygonB.vertices[corner];
        manifold.points[0].id =
            makeFeatureId(static_cast<std::uint8_t>(end), static_cast<std::uint8_t>(corner),
                          FeatureType::Vertex, FeatureType::Vertex);
        return;
    }
    manifold.type = ManifoldType::FaceA;
    manifold.localNormal = (1.0f / d.distance) * (onPolygon - onSegment);
    manifold.localPoint = onSegment;
    manifold.points[0].localPoint = local;
    manifold.points[0].id = makeFeatureId(static_cast<std::uint8_t>(end >= 0 ? end : 0),
                                          static_cast<std::uint8_t>(corner >= 0 ? corner : 0),
                                          end >= 0 ? FeatureType::Vertex : FeatureType::Face,
                                          corner >= 0 ? FeatureType::Vertex : FeatureType::Face);
}

}  // namespace

void collideSegmentAndCircle(Manifold& manifold, const EdgeSegment& edge, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB) {
    manifold = Manifold{};
    const Vec2 q = inverseTransformPoint(xfA, transformPoint(xfB, circleB.center));
    const Vec2 a = edge.v1;
    const Vec2 b = edge.v2;
    const Vec2 e = b - a;
    Vec2 n = rightOf(e);
    const float offset = dot(n, q - a);
    if (edge.oneSided && offset < 0.0f) return;

    // Where q projects on the segment: before a (towardA <= 0), past b (towardB <= 0), or
    // between, as unnormalised barycentric weights.
    const float towardB = dot(e, b - q);
    const float towardA = dot(e, q - a);
    const float radius = kPolygonRadius + circleB.radius;
    const float radiusSquared = radius * radius;

    if (towardA <= 0.0f) {
        const Vec2 d = q - a;
        if (dot(d, d) > radiusSquared) return;
        // Past the previous segment's end as seen from it? Then q is in that segment's face
        // region and the contact is its.
        if (edge.oneSided && dot(a - edge.ghost1, a - q) > 0.0f) return;
        setCircleManifold(manifold, ManifoldType::Circles, Vec2{}, a, circleB,
                          makeFeatureId(0, 0, FeatureType::Vertex, FeatureType::Vertex));
        return;
    }
    if (towardB <= 0.0f) {
        const Vec2 d = q - b;
        if (dot(d, d) > radiusSquared) return;
        if (edge.oneSided && dot(edge.ghost2 - b, q - b) > 0.0f) return;
        setCircleManifold(manifold, ManifoldType::Circles, Vec2{}, b, circleB,
                          makeFeatureId(1, 0, FeatureType::Vertex, FeatureType::Vertex));
        return;
    }

    const float inv = 1.0f / dot(e, e);
    const Vec2 p = inv * (towardB * a + towardA * b);
    const Vec2 d = q - p;
    if (dot(d, d) > radiusSquared) return;
    if (offset < 0.0f) n = -n;
    setCircleManifold(manifold, ManifoldType::FaceA, normalizedOrUnchanged(n), a, circleB,
                      makeFeatureId(0, 0, FeatureType::Face, FeatureType::Vertex));
}

void collideSegmentAndPolygon(Manifold& manifold, const EdgeSegment& edge, const Transform& xfA,
                              const ConvexPolygon& polygonB, const Transform& xfB) {
    manifold = Manifold{};
    const Transform xf = relativeTransform(xfA, xfB);  // B's frame in A's
    const Vec2 centroid = transformPoint(xf, polygonB.centroid);
    const Vec2 v1 = edge.v1;
    const Vec2 v2 = edge.v2;
    const Vec2 tangent = normalizedOrUnchanged(v2 - v1);
    const Vec2 normal = rightOf(tangent);
    if (edge.oneSided && dot(normal, centroid - v1) < 0.0f) return;

    // The polygon in the segment's frame.
    ConvexPolygon polygon;
    polygon.count = polygonB.count;
    for (int i = 0; i < polygonB.count; ++i) {
        polygon.vertices[i] = transformPoint(xf, polygonB.vertices[i]);
        polygon.normals[i] = rotate(xf.q, polygonB.normals[i]);
    }
    const float radius = (kPolygonRadius + polygonB.radius) + kPolygonRadius;

    const Axis onSegment = segmentAxis(polygon, v1, normal);
    if (onSegment.separation > radius) return;
    const Axis onPolygon = polygonAxis(polygon, v1, v2);
    if (onPolygon.separation > radius) return;

    constexpr float kRelativeTolerance = 0.98f;
    constexpr float kAbsoluteTolerance = 0.001f;  // m
    Axis primary = onPolygon.separation - radius >
                           kRelativeTolerance * (onSegment.separation - radius) + kAbsoluteTolerance
                       ? onPolygon
                       : onSegment;

    if (edge.oneSided) {
        // The Gauss map at the end the normal leans towards (see the top of the file).
        const Vec2 tangent0 = normalizedOrUnchanged(v1 - edge.ghost1);
        const Vec2 tangent2 = normalizedOrUnchanged(edge.ghost2 - v2);
        const bool convex1 = cross(tangent0, tangent) >= 0.0f;
        const bool convex2 = cross(tangent, tangent2) >= 0.0f;
        constexpr float kSinTolerance = 0.1f;
        if (dot(primary.normal, tangent) <= 0.0f) {
            if (!convex1) {
                primary = onSegment;
            } else if (cross(primary.normal, rightOf(tangent0)) > kSinTolerance) {
                return;
            }
        } else {
            if (!convex2) {
                primary = onSegment;
            } else if (cross(rightOf(tangent2), primary.normal) > kSinTolerance) {
                return;
            }
        }
    }

    // The reference face (segment or polygon face) and the incident edge to clip against its
    // side planes, all in the segment's frame.
    ClipVertex incident[2];
    Vec2 refV1, refV2, refNormal, side1;
    int refI1 = 0, refI2 = 1;
    if (primary.owner == Axis::Owner::Segment) {
        manifold.type = ManifoldType::FaceA;
        int best = 0;
        float bestValue = dot(primary.normal, polygon.normals[0]);
        for (int i = 1; i < polygon.count; ++i) {
            const float value = dot(primary.normal, polygon.normals[i]);
            if (value < bestValue) {
                bestValue = value;
                best = i;
            }
        }
        const int i2 = best + 1 < polygon.count ? best + 1 : 0;
        incident[0] = {polygon.vertices[best], 0, static_cast<std::uint8_t>(best),
                       FeatureType::Face, FeatureType::Vertex};
        incident[1] = {polygon.vertices[i2], 0, static_cast<std::uint8_t>(i2), FeatureType::Face,
                       FeatureType::Vertex};
        refV1 = v1;
        refV2 = v2;
        refNormal = primary.normal;
        side1 = -tangent;
    } else {
        manifold.type = ManifoldType::FaceB;
        const auto face = static_cast<std::uint8_t>(primary.index);
        incident[0] = {v2, 1, face, FeatureType::Vertex, FeatureType::Face};
        incident[1] = {v1, 0, face, FeatureType::Vertex, FeatureType::Face};
        refI1 = primary.index;
        refI2 = refI1 + 1 < polygon.count ? refI1 + 1 : 0;
        refV1 = polygon.vertices[refI1];
        refV2 = polygon.vertices[refI2];
        refNormal = polygon.normals[refI1];
        side1 = rightOf(refNormal);
    }
    const Vec2 side2 = -side1;

    ClipVertex clipped1[2];
    ClipVertex clipped2[2];
    // Fewer than two points left: the polygon is past an end of the reference face. Box2D
    // reports nothing, right for its thin skin; a rounded polygon may still reach the segment.
    if (clipSegmentToLine(clipped1, incident, side1, dot(side1, refV1), refI1) < 2 ||
        clipSegmentToLine(clipped2, clipped1, side2, dot(side2, refV2), refI2) < 2) {
        if (polygonB.radius > 0.0f) {
            roundedPolygonReachesEnd(manifold, edge, polygonB, xf, radius);
        }
        return;
    }

    if (primary.owner == Axis::Owner::Segment) {
        manifold.localNormal = refNormal;
        manifold.localPoint = refV1;
    } else {
        manifold.localNormal = polygonB.normals[refI1];
        manifold.localPoint = polygonB.vertices[refI1];
    }
    int count = 0;
    for (const ClipVertex& c : clipped2) {
        if (dot(refNormal, c.point - refV1) > radius) continue;
        ManifoldPoint& mp = manifold.points[count++];
        if (primary.owner == Axis::Owner::Segment) {
            mp.localPoint = inverseTransformPoint(xf, c.point);
            mp.id =
                makeFeatureId(c.referenceIndex, c.incidentIndex, c.referenceType, c.incidentType);
        } else {
            mp.localPoint = c.point;
            mp.id =
                makeFeatureId(c.incidentIndex, c.referenceIndex, c.incidentType, c.referenceType);
        }
    }
    manifold.pointCount = count;
}

}  // namespace pivot
