// Rays and points against shapes and boxes, in world coordinates. A ray runs from `origin`
// through origin + fraction * translation for fraction in [0, maxFraction].
//
// Circle (centre c, radius r): with s = origin - c and d = translation, the ray meets the circle
// where |s + t d| = r. Its closest approach is at t0 = -(s . d) / (d . d), at distance |q| with
// q = s + t0 d; it enters at t = t0 - sqrt((r^2 - q . q) / (d . d)). Measuring q directly, rather
// than expanding the quadratic, keeps the round-off of a far origin out of the square root.
//
// Convex polygon: the ray, taken into the polygon's frame, is clipped by each edge's half plane
// n . (x - v) <= 0 (Cyrus-Beck): an edge the ray crosses inwards (n . d < 0) raises the entry
// fraction to (n . (v - origin)) / (n . d), one it crosses outwards lowers the exit fraction. The
// entry edge gives the normal. A ray that starts inside enters through no edge: no hit. A
// rounded polygon is the union of the bands its radius deep outside its edges and the discs at
// its corners: the ray enters it where it first enters one of those.
//
// Segment (a to b, unit normal n): the ray crosses the segment's line at
// t = n . (a - origin) / (n . d), where it must also lie between a and b; the normal faces the
// side the ray comes from. A ray along the line never crosses it. A one-sided (chain) segment is
// only hit from its front, the side n points to (n . d < 0).
#pragma once

#include <optional>

#include "collision/aabb.h"
#include "collision/geometry.h"
#include "pivot/math.h"

namespace pivot {

/// Where a ray enters a shape: fraction of the translation, point and outward unit normal.
struct RayEntry {
    float fraction = 0.0f;
    Vec2 point;
    Vec2 normal;
};

std::optional<RayEntry> rayCastCircle(const Circle& circle, const Transform& xf, Vec2 origin,
                                      Vec2 translation, float maxFraction);
std::optional<RayEntry> rayCastPolygon(const ConvexPolygon& polygon, const Transform& xf,
                                       Vec2 origin, Vec2 translation, float maxFraction);

/// `segment` as makeSegmentPolygon stores it (vertices 0 and 1, normals[0] the unit normal).
std::optional<RayEntry> rayCastSegment(const ConvexPolygon& segment, const Transform& xf,
                                       Vec2 origin, Vec2 translation, float maxFraction,
                                       bool oneSided = false);

bool circleContains(const Circle& circle, const Transform& xf, Vec2 point);
bool polygonContains(const ConvexPolygon& polygon, const Transform& xf, Vec2 point);

/// Whether the segment from `origin` to origin + maxFraction * translation touches `box`: the
/// boxes' axes, then the segment's normal, as separating axes.
inline bool segmentOverlaps(const AABB& box, Vec2 origin, Vec2 translation, float maxFraction) {
    const Vec2 end = origin + maxFraction * translation;
    const AABB segmentBox{{std::min(origin.x, end.x), std::min(origin.y, end.y)},
                          {std::max(origin.x, end.x), std::max(origin.y, end.y)}};
    if (!overlaps(box, segmentBox)) return false;
    const Vec2 normal = leftPerp(translation);
    const Vec2 center = 0.5f * (box.lower + box.upper);
    const Vec2 half = 0.5f * (box.upper - box.lower);
    const float reach = std::fabs(normal.x) * half.x + std::fabs(normal.y) * half.y;
    return std::fabs(dot(normal, origin - center)) <= reach;
}

}  // namespace pivot
