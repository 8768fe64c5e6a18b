// The narrow phase: contact manifolds between two shapes. A manifold holds up to two points,
// kept in the bodies' local frames so the contact solver can re-measure each point's
// penetration from the bodies' current transforms without running collision again, and each
// point carries a feature id so impulses can be matched from one step to the next.
//
// Local-frame conventions (the normal always points from shape A to shape B):
//  - Circles: localPoint is circle A's centre in A's frame; points[0].localPoint is circle B's
//    centre in B's frame; localNormal is unused.
//  - FaceA: localNormal is the reference face's outward normal in A's frame; localPoint is a
//    point on the reference face (A's frame); points[i].localPoint are the clipped incident
//    points in B's frame.
//  - FaceB: as FaceA with the roles swapped: reference face on B (B's frame), points in A's
//    frame; the world normal is then -(B's face normal).
//  A segment's Circles manifold has its nearer end as localPoint (A's frame).
// Radii: circles collide with their radius, polygons with kPolygonRadius.
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include "collision/geometry.h"
#include "pivot/math.h"

namespace pivot {

/// Which features of the two shapes made a point: vertex or face index on each side, so the
/// same point is recognised next step. Packed into ManifoldPoint::id.
enum class FeatureType : std::uint8_t { Vertex = 0, Face = 1 };

inline std::uint32_t makeFeatureId(std::uint8_t indexA, std::uint8_t indexB, FeatureType typeA,
                                   FeatureType typeB) {
    return std::uint32_t(indexA) | (std::uint32_t(indexB) << 8) | (std::uint32_t(typeA) << 16) |
           (std::uint32_t(typeB) << 24);
}

struct ManifoldPoint {
    Vec2 localPoint;             // see the conventions above
    float normalImpulse = 0.0f;  // accumulated, N s (kept for warm starting)
    float tangentImpulse = 0.0f;
    // m/s, how fast the point closed at the start of the last step that solved it (its first
    // substep): what a hit event reports.
    float approachSpeed = 0.0f;
    std::uint32_t id = 0;  // feature id
};

enum class ManifoldType : std::uint8_t { Circles, FaceA, FaceB };

struct Manifold {
    std::array<ManifoldPoint, 2> points{};
    Vec2 localNormal;
    Vec2 localPoint;
    ManifoldType type = ManifoldType::Circles;
    int pointCount = 0;  // 0 when the shapes are apart
};

/// A manifold in world coordinates for given transforms: the unit normal from A to B, and per
/// point the midpoint between the two surfaces and the separation (negative when overlapping).
struct WorldManifold {
    Vec2 normal;
    std::array<Vec2, 2> points{};
    std::array<float, 2> separations{};
};

/// Each collide function writes pointCount = 0 when the shapes (with their radii) are apart.
/// Impulses in the output are zero; the caller carries old impulses over by feature id.
void collideCircles(Manifold& manifold, const Circle& circleA, const Transform& xfA,
                    const Circle& circleB, const Transform& xfB);
void collidePolygonAndCircle(Manifold& manifold, const ConvexPolygon& polygonA,
                             const Transform& xfA, const Circle& circleB, const Transform& xfB);
void collidePolygons(Manifold& manifold, const ConvexPolygon& polygonA, const Transform& xfA,
                     const ConvexPolygon& polygonB, const Transform& xfB);

/// Two capsules, each as makeCapsulePolygon stores it (a rounded polygon of two vertices).
void collideCapsules(Manifold& manifold, const ConvexPolygon& capsuleA, const Transform& xfA,
                     const ConvexPolygon& capsuleB, const Transform& xfB);

/// A segment as the segment routines see it, in its body's frame: from v1 to v2, and for a
/// one-sided segment (a chain's) the chain's points before v1 and after v2. A segment is always
/// shape A of its contacts; its skin is kPolygonRadius.
struct EdgeSegment {
    Vec2 ghost1;
    Vec2 v1;
    Vec2 v2;
    Vec2 ghost2;
    bool oneSided = false;
};
void collideSegmentAndCircle(Manifold& manifold, const EdgeSegment& segmentA, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB);
void collideSegmentAndCapsule(Manifold& manifold, const EdgeSegment& segmentA, const Transform& xfA,
                              const ConvexPolygon& capsuleB, const Transform& xfB);
void collideSegmentAndPolygon(Manifold& manifold, const EdgeSegment& segmentA, const Transform& xfA,
                              const ConvexPolygon& polygonB, const Transform& xfB);

/// Below this length a vector has no usable direction: the reference engine's threshold, kept
/// so that both engines fall back in exactly the same nearly-coincident cases.
constexpr float kDirectionEpsilon = std::numeric_limits<float>::epsilon();

WorldManifold computeWorldManifold(const Manifold& manifold, const Transform& xfA, float radiusA,
                                   const Transform& xfB, float radiusB);

}  // namespace pivot
