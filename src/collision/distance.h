// The distance between two convex shapes, by the Gilbert-Johnson-Keerthi algorithm (GJK): the
// closest point to the origin of the Minkowski difference B - A, found on a simplex of at most
// three of its support points w = b - a that is moved towards the origin one support point at a
// time. A shape is its core's vertices (a circle's centre, a segment's two ends, a polygon's
// corners) and a radius around them (a circle's radius; a polygon's or segment's skin when
// contacts need it, none in queries).
//
// Each iteration: the simplex's closest point v to the origin (and the smallest sub-simplex
// holding it: a point, an edge, or, when the origin is inside the triangle, overlap); then the
// support point of B - A furthest along -v (A's vertex furthest along v, B's furthest along -v).
// If it brings the simplex no closer than v already is, or repeats a point, v is the closest
// point. The witness points on A and B come from the same barycentric weights on the simplex's
// a's and b's.
#pragma once

#include <array>

#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

/// A convex shape as GJK sees it: up to kMaxPolygonVertices core vertices and a radius.
struct DistanceProxy {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    int count = 0;
    float radius = 0.0f;
};

struct DistanceResult {
    Vec2 pointA;            ///< closest point on A (on its radius, if counted), world frame
    Vec2 pointB;            ///< closest point on B
    float distance = 0.0f;  ///< >= 0; 0 when the shapes overlap
    bool overlap = false;   ///< the cores (or, with radii, the rounded shapes) overlap
    int iterations = 0;
};

/// The distance between A at xfA and B at xfB; with useRadii, between the rounded shapes.
DistanceResult shapeDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                             const Transform& xfB, bool useRadii);

}  // namespace pivot
