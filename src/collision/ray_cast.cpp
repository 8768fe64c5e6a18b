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

namespace {

// A rounded polygon is the union of the bands r deep outside its edges and the discs of radius
// r at its corners (the core lies inside them): a ray from outside enters it where it first
// enters one of those pieces.
std::optional<RayEntry> rayCastRoundedPolygon(const ConvexPolygon& polygon, const Transform& xf,
                                              Vec2 origin, Vec2 translation, float maxFraction) {
    if (polygonContains(polygon, xf, origin)) return std::nullopt;
    const float r = polygon.radius;
    std::optional<RayEntry> first;
    float limit = maxFraction;
    auto keep = [&](std::optional<RayEntry> entry) {
        if (entry && entry->fraction <= limit) {
            first = entry;
            limit = entry->fraction;
        }
    };
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 a = polygon.vertices[i];
        const Vec2 b = polygon.vertices[(i + 1) % polygon.count];
        const Vec2 out = r * polygon.normals[i];
        ConvexPolygon band;  // counter-clockwise: a, a + out, b + out, b
        band.count = 4;
        band.vertices = {a, a + out, b + out, b};
        for (int k = 0; k < 4; ++k) {
            const Vec2 edge = band.vertices[(k + 1) % 4] - band.vertices[k];
            band.normals[k] = (1.0f / length(edge)) * Vec2{edge.y, -edge.x};
        }
        keep(rayCastPolygon(band, xf, origin, translation, limit));
        keep(rayCastCircle(Circle{a, r}, xf, origin, translation, limit));
    }
    return first;
}

// The distance from p to the segment a-b, squared.
float distanceSquaredToSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 e = b - a;
    const float t = std::fmin(std::fmax(dot(p - a, e) / dot(e, e), 0.0f), 1.0f);
    const Vec2 d = p - (a + t * e);
    return dot(d, d);
}

}  // namespace

std::optional<RayEntry> rayCastPolygon(const ConvexPolygon& polygon, const Transform& xf,
                                       Vec2 origin, Vec2 translation, float maxFraction) {
    if (polygon.radius > 0.0f) {
        return rayCastRoundedPolygon(polygon, xf, origin, translation, maxFraction);
    }
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
                                       Vec2 origin, Vec2 translation, float maxFraction,
                                       bool oneSided) {
    const Vec2 p = inverseTransformPoint(xf, origin);
    const Vec2 d = inverseRotate(xf.q, translation);
    const Vec2 a = segment.vertices[0];
    const Vec2 n = segment.normals[0];
    const float approach = dot(n, d);
    if (approach == 0.0f) return std::nullopt;             // along the line, or no translation
    if (oneSided && approach > 0.0f) return std::nullopt;  // from behind
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
    bool inCore = true;
    for (int i = 0; i < polygon.count; ++i) {
        if (dot(polygon.normals[i], p - polygon.vertices[i]) > 0.0f) inCore = false;
    }
    if (inCore || polygon.radius == 0.0f) return inCore;
    // Outside the core, a rounded polygon holds the points within its radius of an edge.
    const float rr = polygon.radius * polygon.radius;
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 a = polygon.vertices[i];
        const Vec2 b = polygon.vertices[(i + 1) % polygon.count];
        if (distanceSquaredToSegment(p, a, b) <= rr) return true;
    }
    return false;
}

}  // namespace pivot
