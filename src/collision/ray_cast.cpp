#include "collision/ray_cast.h"

#include <cmath>

namespace pivot {

std::optional<RayEntry> rayCastCircle(const Circle& circle, const Transform& xf, Vec2 origin,
                                      Vec2 translation, float maxFraction) {
    const float dd = dot(translation, translation);
    if (!(dd > 0.0f)) return std::nullopt;
    const Vec2 center = transformPoint(xf, circle.center);
    const Vec2 s = origin - center;
    const float closest = -dot(s, translation) / dd;
    const Vec2 q = s + closest * translation;
    const float inside = circle.radius * circle.radius - dot(q, q);
    if (inside < 0.0f) return std::nullopt;  // the line passes the circle by
    const float t = closest - std::sqrt(inside / dd);
    // t < 0: the circle is behind the origin, or the origin is inside it.
    if (t < 0.0f || t > maxFraction) return std::nullopt;
    RayEntry entry;
    entry.fraction = t;
    entry.point = origin + t * translation;
    const Vec2 out = entry.point - center;
    const float distance = length(out);
    entry.normal = distance > 0.0f ? (1.0f / distance) * out : Vec2{0.0f, 1.0f};
    return entry;
}

std::optional<RayEntry> rayCastPolygon(const ConvexPolygon& polygon, const Transform& xf,
                                       Vec2 origin, Vec2 translation, float maxFraction) {
    const Vec2 p = inverseTransformPoint(xf, origin);
    const Vec2 d = inverseRotate(xf.q, translation);
    float enter = 0.0f;
    float leave = maxFraction;
    int entryEdge = -1;
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 n = polygon.normals[i];
        const float numerator = dot(n, polygon.vertices[i] - p);  // > 0: p on the inner side
        const float denominator = dot(n, d);
        if (denominator == 0.0f) {
            if (numerator < 0.0f) return std::nullopt;  // parallel to the edge, outside it
            continue;
        }
        // Compared as products so that no division runs until the fraction is needed.
        if (denominator < 0.0f && numerator < enter * denominator) {
            enter = numerator / denominator;
            entryEdge = i;
        } else if (denominator > 0.0f && numerator < leave * denominator) {
            leave = numerator / denominator;
        }
        if (leave < enter) return std::nullopt;
    }
    if (entryEdge < 0) return std::nullopt;  // the ray starts inside
    RayEntry entry;
    entry.fraction = enter;
    entry.point = origin + enter * translation;
    entry.normal = rotate(xf.q, polygon.normals[entryEdge]);
    return entry;
}

std::optional<RayEntry> rayCastSegment(const ConvexPolygon& segment, const Transform& xf,
                                       Vec2 origin, Vec2 translation, float maxFraction) {
    const Vec2 p = inverseTransformPoint(xf, origin);
    const Vec2 d = inverseRotate(xf.q, translation);
    const Vec2 a = segment.vertices[0];
    const Vec2 n = segment.normals[0];
    const float approach = dot(n, d);
    if (approach == 0.0f) return std::nullopt;  // along the line, or no translation
    const float t = dot(n, a - p) / approach;
    if (!(t >= 0.0f && t <= maxFraction)) return std::nullopt;
    const Vec2 e = segment.vertices[1] - a;
    const float along = dot(e, p + t * d - a);
    if (along < 0.0f || along > dot(e, e)) return std::nullopt;  // past an end
    RayEntry entry;
    entry.fraction = t;
    entry.point = origin + t * translation;
    entry.normal = rotate(xf.q, approach < 0.0f ? n : -n);
    return entry;
}

bool circleContains(const Circle& circle, const Transform& xf, Vec2 point) {
    const Vec2 d = point - transformPoint(xf, circle.center);
    return dot(d, d) <= circle.radius * circle.radius;
}

bool polygonContains(const ConvexPolygon& polygon, const Transform& xf, Vec2 point) {
    const Vec2 p = inverseTransformPoint(xf, point);
    for (int i = 0; i < polygon.count; ++i) {
        if (dot(polygon.normals[i], p - polygon.vertices[i]) > 0.0f) return false;
    }
    return true;
}

}  // namespace pivot
