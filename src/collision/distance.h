// The distance between two convex shapes, by the Gilbert-Johnson-Keerthi algorithm (GJK): the
// closest point to the origin of the Minkowski difference B - A, found on a simplex of at most
// three of its support points w = b - a that is moved towards the origin one support point at a
// time. A shape is its core's vertices (a circle's centre, a segment's two ends, a polygon's
// corners) and a radius around them (a circle's radius; a polygon's or segment's skin when
// contacts need it, none in queries).
//
// Each iteration keeps the smallest sub-simplex holding the simplex's closest point v to the
// origin (a point, an edge with barycentric weights, or, when the origin is inside a triangle,
// overlap), then adds the support point of B - A furthest towards the origin: along -v from a
// point, along the edge's normal on the origin's side from an edge. It stops when that support
// point is already in the simplex (no progress is possible) or the direction vanishes (the
// origin lies on the simplex). The witness points on A and B carry the same weights.
//
// This is the iteration of Box2D 2.4.1's b2Distance, in the same float operations, so that the
// time of impact built on it (time_of_impact.h) agrees with Box2D's bit for bit
// (tests/reference/toi_reference_test.cpp). A SimplexCache carries the final simplex's vertex
// indices from one call to the next: a time-of-impact search calls GJK many times on poses a
// little apart, and starting from the last simplex saves most of the iterations.
#pragma once

#include <array>
#include <cstdint>

#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

/// A convex shape as GJK sees it: up to kMaxPolygonVertices core vertices and a radius.
struct DistanceProxy {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    int count = 0;
    float radius = 0.0f;
};

/// The simplex one GJK call ended on, to start the next call with. count 0: start afresh.
struct SimplexCache {
    float metric = 0.0f;  // the simplex's size (an edge's length, a triangle's area), to notice
                          // when the poses moved so far that the old simplex no longer fits
    int count = 0;
    std::array<std::uint8_t, 3> indexA{};
    std::array<std::uint8_t, 3> indexB{};
};

struct DistanceResult {
    Vec2 pointA;            ///< closest point on A (on its radius, if counted), world frame
    Vec2 pointB;            ///< closest point on B
    float distance = 0.0f;  ///< >= 0; 0 when the shapes overlap
    bool overlap = false;   ///< the cores (or, with radii, the rounded shapes) overlap
    int iterations = 0;     ///< support points computed
};

/// The distance between the cores of A at xfA and B at xfB, as GJK's witness points leave it:
/// `overlap` when the simplex encloses the origin or the search direction vanished on it (the
/// distance is then 0 or round-off small). `cache` starts the search from a former simplex and
/// receives the final one.
DistanceResult coreDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                            const Transform& xfB, SimplexCache& cache);

/// The distance between A at xfA and B at xfB; with useRadii, between the rounded shapes.
DistanceResult shapeDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                             const Transform& xfB, bool useRadii);

/// The index of the proxy's vertex furthest along `direction` (in the proxy's frame); the first
/// of equals.
int supportIndex(const DistanceProxy& proxy, Vec2 direction);

}  // namespace pivot
