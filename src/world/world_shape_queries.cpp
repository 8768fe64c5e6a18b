// The World facade, part five: shapes as queries. queryShape finds what a circle, capsule or
// polygon placed
// anywhere overlaps, castShape where one moving in a straight line first touches something; both
// walk the broad phase's tree and measure with GJK (collision/distance.h, shape_cast.h).
#include <algorithm>

#include "collision/distance.h"
#include "collision/shape_cast.h"
#include "world/query_support.h"

namespace pivot {

namespace {

using namespace queries;

// Shapes as the distance routine sees them in a query: the core and, for a circle, its radius,
// for a polygon its rounding (the skins of polygons and segments are not part of a query).
DistanceProxy proxyOf(const Circle& circle) {
    DistanceProxy proxy;
    proxy.count = 1;
    proxy.vertices[0] = circle.center;
    proxy.radius = circle.radius;
    return proxy;
}

DistanceProxy proxyOf(const ConvexPolygon& polygon) {
    DistanceProxy proxy;
    proxy.count = polygon.count;
    for (int i = 0; i < proxy.count; ++i) proxy.vertices[i] = polygon.vertices[i];
    proxy.radius = polygon.radius;
    return proxy;
}

DistanceProxy proxyOf(const Shape& shape) {
    DistanceProxy proxy = contactProxy(shape);
    // No skin in a query: a polygon's rounding only.
    if (shape.type != ShapeType::Circle) proxy.radius = shape.polygon.radius;
    return proxy;
}

AABB boxOf(const DistanceProxy& proxy, const Transform& xf) {
    Vec2 lower = transformPoint(xf, proxy.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < proxy.count; ++i) {
        const Vec2 v = transformPoint(xf, proxy.vertices[i]);
        lower = {std::min(lower.x, v.x), std::min(lower.y, v.y)};
        upper = {std::max(upper.x, v.x), std::max(upper.y, v.y)};
    }
    const Vec2 r{proxy.radius, proxy.radius};
    return {lower - r, upper + r};
}

void queryOverlaps(const char* call, const World::Impl& w, const DistanceProxy& query,
                   const Transform& xf, const QueryFilter& filter, ShapeCallback callback) {
    forEachCandidate(
        call, w, boxOf(query, xf), filter, [&](std::int32_t index, const Shape& shape) {
            const DistanceResult d =
                shapeDistance(query, xf, proxyOf(shape), w.bodies[shape.body].xf, true);
            return !d.overlap || callback(w.shapeId(index));
        });
}

}  // namespace

namespace {

DistanceProxy checkedProxy(const char* call, const Circle& circle) {
    checkCircle(call, circle);
    return proxyOf(circle);
}

DistanceProxy checkedProxy(const char* call, const Polygon& polygon) {
    return proxyOf(checkedPolygon(call, polygon));
}

DistanceProxy checkedProxy(const char* call, const Capsule& capsule) {
    return proxyOf(checkedCapsule(call, capsule));
}

void castShapeNamed(const char* call, const World::Impl& w, const DistanceProxy& mover,
                    const Transform& xf, Vec2 translation, const QueryFilter& filter,
                    RayCallback callback) {
    checkTransform(call, xf);
    requireMagnitude(call, "translation", translation);
    // Every shape whose box meets the box swept by the mover; the casts then clip as they go.
    const AABB start = boxOf(mover, xf);
    const AABB end = boxOf(mover, Transform{xf.p + translation, xf.q});
    float maxFraction = 1.0f;
    forEachCandidate(
        call, w, combine(start, end), filter, [&](std::int32_t index, const Shape& shape) {
            const std::optional<CastEntry> entry = castShape(mover, xf, translation, proxyOf(shape),
                                                             w.bodies[shape.body].xf, maxFraction);
            if (!entry) return true;
            const float answer =
                callback(RayHit{w.shapeId(index), entry->point, entry->normal, entry->fraction});
            if (answer < 0.0f) return true;      // ignore this shape
            if (!(answer > 0.0f)) return false;  // 0 or NaN: stop
            maxFraction = std::min(maxFraction, answer);
            return true;
        });
}

template <typename Geometry>
std::optional<RayHit> castShapeClosestNamed(const char* call, const World::Impl& w,
                                            const Geometry& geometry, const Transform& xf,
                                            Vec2 translation, const QueryFilter& filter) {
    std::optional<RayHit> closest;
    castShapeNamed(call, w, checkedProxy(call, geometry), xf, translation, filter,
                   [&](const RayHit& hit) {
                       if (!closest || hit.fraction < closest->fraction) closest = hit;
                       return hit.fraction;  // only closer hits from here on (0 stops)
                   });
    return closest;
}

}  // namespace

void World::castShape(const Circle& circle, const Transform& xf, Vec2 translation,
                      const QueryFilter& filter, RayCallback callback) const {
    const char* call = "World::castShape";
    castShapeNamed(call, *impl_, checkedProxy(call, circle), xf, translation, filter, callback);
}

void World::castShape(const Polygon& polygon, const Transform& xf, Vec2 translation,
                      const QueryFilter& filter, RayCallback callback) const {
    const char* call = "World::castShape";
    castShapeNamed(call, *impl_, checkedProxy(call, polygon), xf, translation, filter, callback);
}

void World::castShape(const Capsule& capsule, const Transform& xf, Vec2 translation,
                      const QueryFilter& filter, RayCallback callback) const {
    const char* call = "World::castShape";
    castShapeNamed(call, *impl_, checkedProxy(call, capsule), xf, translation, filter, callback);
}

std::optional<RayHit> World::castShapeClosest(const Capsule& capsule, const Transform& xf,
                                              Vec2 translation, const QueryFilter& filter) const {
    return castShapeClosestNamed("World::castShapeClosest", *impl_, capsule, xf, translation,
                                 filter);
}

std::optional<RayHit> World::castShapeClosest(const Circle& circle, const Transform& xf,
                                              Vec2 translation, const QueryFilter& filter) const {
    return castShapeClosestNamed("World::castShapeClosest", *impl_, circle, xf, translation,
                                 filter);
}

std::optional<RayHit> World::castShapeClosest(const Polygon& polygon, const Transform& xf,
                                              Vec2 translation, const QueryFilter& filter) const {
    return castShapeClosestNamed("World::castShapeClosest", *impl_, polygon, xf, translation,
                                 filter);
}

void World::queryShape(const Circle& circle, const Transform& xf, const QueryFilter& filter,
                       ShapeCallback callback) const {
    const char* call = "World::queryShape";
    const DistanceProxy query = checkedProxy(call, circle);
    checkTransform(call, xf);
    queryOverlaps(call, *impl_, query, xf, filter, callback);
}

void World::queryShape(const Capsule& capsule, const Transform& xf, const QueryFilter& filter,
                       ShapeCallback callback) const {
    const char* call = "World::queryShape";
    const DistanceProxy query = checkedProxy(call, capsule);
    checkTransform(call, xf);
    queryOverlaps(call, *impl_, query, xf, filter, callback);
}

void World::queryShape(const Polygon& polygon, const Transform& xf, const QueryFilter& filter,
                       ShapeCallback callback) const {
    const char* call = "World::queryShape";
    const DistanceProxy query = checkedProxy(call, polygon);
    checkTransform(call, xf);
    queryOverlaps(call, *impl_, query, xf, filter, callback);
}

}  // namespace pivot
