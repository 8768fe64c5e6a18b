// Circle manifolds (circle against circle, polygon against circle) and the conversion of any
// manifold to world space. The decisions (when a pair counts as touching, which region of the
// polygon the circle is in, which normal that gives) are those of Box2D 2.4.1, so that contacts
// built from these manifolds can be compared with that engine step for step.
#include "collision/manifold.h"

#include <limits>

namespace pivot {

namespace {

// The unit vector along v, or v itself when v is too short to give a direction (the caller
// then gets a tiny non-unit normal rather than a division blow-up, as in the reference).
Vec2 normalizedOrUnchanged(Vec2 v) {
    const float len = length(v);
    if (len < kDirectionEpsilon) return v;
    const float inv = 1.0f / len;
    return {v.x * inv, v.y * inv};
}

// Every polygon-circle manifold has the same shape apart from its plane: one point, the circle's
// centre (B's frame), with a key of 0 since there is only one pair of features to match.
void setPolygonCircleManifold(Manifold& manifold, Vec2 localNormal, Vec2 localPoint,
                              const Circle& circleB) {
    manifold.type = ManifoldType::FaceA;
    manifold.localNormal = localNormal;
    manifold.localPoint = localPoint;
    manifold.points[0] = ManifoldPoint{};
    manifold.points[0].localPoint = circleB.center;
    manifold.pointCount = 1;
}

}  // namespace

void collideCircles(Manifold& manifold, const Circle& circleA, const Transform& xfA,
                    const Circle& circleB, const Transform& xfB) {
    manifold = Manifold{};
    const Vec2 centerA = transformPoint(xfA, circleA.center);
    const Vec2 centerB = transformPoint(xfB, circleB.center);
    const Vec2 d = centerB - centerA;
    const float radius = circleA.radius + circleB.radius;
    // Squared lengths avoid a square root for the (common) pairs that are apart.
    if (dot(d, d) > radius * radius) return;

    // The normal is not stored: it follows from the two centres at every re-measure, which
    // keeps it right as the bodies turn.
    manifold.type = ManifoldType::Circles;
    manifold.localPoint = circleA.center;
    manifold.points[0].localPoint = circleB.center;
    manifold.pointCount = 1;
}

void collidePolygonAndCircle(Manifold& manifold, const ConvexPolygon& polygonA,
                             const Transform& xfA, const Circle& circleB, const Transform& xfB) {
    manifold = Manifold{};
    // Work in A's frame: the polygon's vertices and normals are then used as stored.
    const Vec2 center = inverseTransformPoint(xfA, transformPoint(xfB, circleB.center));
    const float radius = (kPolygonRadius + polygonA.radius) + circleB.radius;
    const int n = polygonA.count;

    // The face whose plane the centre is furthest in front of. If the centre is further than
    // the radius in front of any face, that face separates the shapes.
    int face = 0;
    float separation = -std::numeric_limits<float>::max();
    for (int i = 0; i < n; ++i) {
        const float s = dot(polygonA.normals[i], center - polygonA.vertices[i]);
        if (s > radius) return;
        if (s > separation) {
            separation = s;
            face = i;
        }
    }

    const int i1 = face;
    const int i2 = i1 + 1 < n ? i1 + 1 : 0;
    const Vec2 v1 = polygonA.vertices[i1];
    const Vec2 v2 = polygonA.vertices[i2];

    // Centre inside the polygon (or on its boundary): push out through the least-penetrated
    // face; the vertex regions below would give a meaningless direction here.
    if (separation < kDirectionEpsilon) {
        setPolygonCircleManifold(manifold, polygonA.normals[i1], 0.5f * (v1 + v2), circleB);
        return;
    }

    // Outside: the closest feature is vertex v1, vertex v2 or the face between them, told apart
    // by where the centre projects onto the edge.
    const float alongFromV1 = dot(center - v1, v2 - v1);
    const float alongFromV2 = dot(center - v2, v1 - v2);
    if (alongFromV1 <= 0.0f) {
        const Vec2 toCenter = center - v1;
        if (dot(toCenter, toCenter) > radius * radius) return;
        setPolygonCircleManifold(manifold, normalizedOrUnchanged(toCenter), v1, circleB);
    } else if (alongFromV2 <= 0.0f) {
        const Vec2 toCenter = center - v2;
        if (dot(toCenter, toCenter) > radius * radius) return;
        setPolygonCircleManifold(manifold, normalizedOrUnchanged(toCenter), v2, circleB);
    } else {
        const Vec2 faceCenter = 0.5f * (v1 + v2);
        if (dot(center - faceCenter, polygonA.normals[i1]) > radius) return;
        setPolygonCircleManifold(manifold, polygonA.normals[i1], faceCenter, circleB);
    }
}

WorldManifold computeWorldManifold(const Manifold& manifold, const Transform& xfA, float radiusA,
                                   const Transform& xfB, float radiusB) {
    WorldManifold world;
    if (manifold.pointCount == 0) return world;

    switch (manifold.type) {
        case ManifoldType::Circles: {
            const Vec2 centerA = transformPoint(xfA, manifold.localPoint);
            const Vec2 centerB = transformPoint(xfB, manifold.points[0].localPoint);
            // Concentric circles have no normal of their own; any unit vector will do, and +x
            // is the reference engine's choice.
            world.normal = {1.0f, 0.0f};
            const Vec2 d = centerA - centerB;
            if (dot(d, d) > kDirectionEpsilon * kDirectionEpsilon) {
                world.normal = normalizedOrUnchanged(centerB - centerA);
            }
            const Vec2 surfaceA = centerA + radiusA * world.normal;
            const Vec2 surfaceB = centerB - radiusB * world.normal;
            world.points[0] = 0.5f * (surfaceA + surfaceB);
            world.separations[0] = dot(surfaceB - surfaceA, world.normal);
            break;
        }
        case ManifoldType::FaceA: {
            world.normal = rotate(xfA.q, manifold.localNormal);
            const Vec2 planePoint = transformPoint(xfA, manifold.localPoint);
            for (int i = 0; i < manifold.pointCount; ++i) {
                const Vec2 p = transformPoint(xfB, manifold.points[i].localPoint);
                // A's surface: p projected onto the reference plane, then out by A's radius.
                const Vec2 surfaceA =
                    p + (radiusA - dot(p - planePoint, world.normal)) * world.normal;
                const Vec2 surfaceB = p - radiusB * world.normal;
                world.points[i] = 0.5f * (surfaceA + surfaceB);
                world.separations[i] = dot(surfaceB - surfaceA, world.normal);
            }
            break;
        }
        case ManifoldType::FaceB: {
            // Built with B's face normal (pointing from B to A), flipped at the end so the
            // caller always sees a normal from A to B.
            const Vec2 normalB = rotate(xfB.q, manifold.localNormal);
            const Vec2 planePoint = transformPoint(xfB, manifold.localPoint);
            for (int i = 0; i < manifold.pointCount; ++i) {
                const Vec2 p = transformPoint(xfA, manifold.points[i].localPoint);
                const Vec2 surfaceB = p + (radiusB - dot(p - planePoint, normalB)) * normalB;
                const Vec2 surfaceA = p - radiusA * normalB;
                world.points[i] = 0.5f * (surfaceA + surfaceB);
                world.separations[i] = dot(surfaceA - surfaceB, normalB);
            }
            world.normal = -normalB;
            break;
        }
    }
    return world;
}

}  // namespace pivot
