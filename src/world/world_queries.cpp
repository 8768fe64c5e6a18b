// The World facade, part four: queries. Each walks the broad phase's tree (its fat boxes hold
// every shape's current box) and tests the shapes it reaches exactly.
#include <algorithm>
#include <cmath>

#include "collision/distance.h"
#include "collision/ray_cast.h"
#include "collision/shape_cast.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

namespace {

bool sees(const QueryFilter& filter, const Shape& shape) {
    return (shape.filter.categoryBits & filter.maskBits) != 0 &&
           (shape.filter.maskBits & filter.categoryBits) != 0;
}

std::optional<RayEntry> castOnShape(const Shape& shape, const Transform& xf, Vec2 origin,
                                    Vec2 translation, float maxFraction) {
    switch (shape.type) {
        case ShapeType::Circle:
            return rayCastCircle(shape.circle, xf, origin, translation, maxFraction);
        case ShapeType::Polygon:
            return rayCastPolygon(shape.polygon, xf, origin, translation, maxFraction);
        case ShapeType::Segment:
            return rayCastSegment(shape.polygon, xf, origin, translation, maxFraction);
    }
    return std::nullopt;
}

/// A segment has no inside: it contains no point.
bool shapeContains(const Shape& shape, const Transform& xf, Vec2 point) {
    switch (shape.type) {
        case ShapeType::Circle: return circleContains(shape.circle, xf, point);
        case ShapeType::Polygon: return polygonContains(shape.polygon, xf, point);
        case ShapeType::Segment: return false;
    }
    return false;
}

void checkTransform(const char* call, const Transform& xf) {
    requireCoordinate(call, "xf.p", xf.p);
    requireFinite(call, "xf.q.c", xf.q.c);
    requireFinite(call, "xf.q.s", xf.q.s);
}

void checkRay(const char* call, Vec2 origin, Vec2 translation) {
    requireCoordinate(call, "origin", origin);
    // The end point may lie outside the world's limits (a long line of sight), but the
    // arithmetic must stay finite.
    requireMagnitude(call, "translation", translation);
}

/// Counts a query under way for as long as it lives (see World::Impl::requireNoQuery).
class QueryScope {
public:
    explicit QueryScope(const World::Impl& w) : w_(w) { ++w_.queryDepth; }
    ~QueryScope() { --w_.queryDepth; }
    QueryScope(const QueryScope&) = delete;
    QueryScope& operator=(const QueryScope&) = delete;

private:
    const World::Impl& w_;
};

}  // namespace

void World::Impl::requireNoQuery(const char* call) const {
    if (queryDepth > 0) {
        fail(call,
             "called from inside a query's callback (a query may read the world; change "
             "its shapes after the query returns)");
    }
}

AABB World::shapeAABB(ShapeId id) const {
    const Impl& w = *impl_;
    return w.shapes[w.shapeIndex("World::shapeAABB", id)].box;
}

namespace {

// castRay and castRayClosest, each checking its arguments under its own name.
void castRayNamed(const char* call, const World::Impl& w, Vec2 origin, Vec2 translation,
                  const QueryFilter& filter, RayCallback callback) {
    checkRay(call, origin, translation);
    if (!(lengthSquared(translation) > 0.0f)) return;
    QueryScope scope(w);
    const BroadPhase& broadPhase = w.contactManager.broadPhase();
    broadPhase.tree().rayCast(
        origin, translation, 1.0f, [&](std::int32_t proxy, float maxFraction) {
            const std::int32_t index = broadPhase.userData(proxy);
            const Shape& shape = w.shapes[index];
            if (!sees(filter, shape)) return maxFraction;
            const std::optional<RayEntry> entry =
                castOnShape(shape, w.bodies[shape.body].xf, origin, translation, maxFraction);
            if (!entry) return maxFraction;
            const float answer =
                callback(RayHit{w.shapeId(index), entry->point, entry->normal, entry->fraction});
            if (answer < 0.0f) return maxFraction;  // ignore this shape
            return answer;  // 0 or NaN stops; the tree keeps the smaller of the two fractions
        });
}

}  // namespace

void World::castRay(Vec2 origin, Vec2 translation, const QueryFilter& filter,
                    RayCallback callback) const {
    castRayNamed("World::castRay", *impl_, origin, translation, filter, callback);
}

std::optional<RayHit> World::castRayClosest(Vec2 origin, Vec2 translation,
                                            const QueryFilter& filter) const {
    std::optional<RayHit> closest;
    castRayNamed(
        "World::castRayClosest", *impl_, origin, translation, filter, [&](const RayHit& hit) {
            closest = hit;
            return hit.fraction;  // only closer hits from here on (0, at the origin, stops)
        });
    return closest;
}

std::optional<RayHit> World::castRayOnShape(ShapeId id, Vec2 origin, Vec2 translation) const {
    const char* call = "World::castRayOnShape";
    const Impl& w = *impl_;
    const std::int32_t index = w.shapeIndex(call, id);
    checkRay(call, origin, translation);
    const Shape& shape = w.shapes[index];
    const std::optional<RayEntry> entry =
        castOnShape(shape, w.bodies[shape.body].xf, origin, translation, 1.0f);
    if (!entry) return std::nullopt;
    return RayHit{id, entry->point, entry->normal, entry->fraction};
}

void World::queryAABB(const AABB& box, const QueryFilter& filter, ShapeCallback callback) const {
    const char* call = "World::queryAABB";
    const Impl& w = *impl_;
    requireCoordinate(call, "box.lower", box.lower);
    requireCoordinate(call, "box.upper", box.upper);
    if (box.lower.x > box.upper.x || box.lower.y > box.upper.y) {
        fail(call, "box.lower must be <= box.upper in x and y (got " + formatVec2(box.lower) +
                       " and " + formatVec2(box.upper) + ")");
    }
    QueryScope scope(w);
    w.contactManager.broadPhase().tree().query(box, [&](std::int32_t proxy) {
        const std::int32_t index = w.contactManager.broadPhase().userData(proxy);
        const Shape& shape = w.shapes[index];
        if (!sees(filter, shape) || !overlaps(shape.box, box)) return true;
        return callback(w.shapeId(index));
    });
}

void World::queryPoint(Vec2 point, const QueryFilter& filter, ShapeCallback callback) const {
    const char* call = "World::queryPoint";
    const Impl& w = *impl_;
    requireCoordinate(call, "point", point);
    QueryScope scope(w);
    w.contactManager.broadPhase().tree().query(AABB{point, point}, [&](std::int32_t proxy) {
        const std::int32_t index = w.contactManager.broadPhase().userData(proxy);
        const Shape& shape = w.shapes[index];
        if (!sees(filter, shape) || !shapeContains(shape, w.bodies[shape.body].xf, point)) {
            return true;
        }
        return callback(w.shapeId(index));
    });
}

namespace {

// A shape as the distance routine sees it in a query: its core and, for a circle, its radius
// (the skins of polygons and segments are not part of a query).
DistanceProxy proxyOf(const Shape& shape) {
    DistanceProxy proxy;
    if (shape.type == ShapeType::Circle) {
        proxy.count = 1;
        proxy.vertices[0] = shape.circle.center;
        proxy.radius = shape.circle.radius;
        return proxy;
    }
    proxy.count = shape.polygon.count;
    for (int i = 0; i < proxy.count; ++i) proxy.vertices[i] = shape.polygon.vertices[i];
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

void queryOverlaps(const World::Impl& w, const DistanceProxy& query, const Transform& xf,
                   const QueryFilter& filter, ShapeCallback callback) {
    QueryScope scope(w);
    const BroadPhase& broadPhase = w.contactManager.broadPhase();
    broadPhase.tree().query(boxOf(query, xf), [&](std::int32_t proxy) {
        const std::int32_t index = broadPhase.userData(proxy);
        const Shape& shape = w.shapes[index];
        if (!sees(filter, shape)) return true;
        const DistanceResult d =
            shapeDistance(query, xf, proxyOf(shape), w.bodies[shape.body].xf, true);
        if (!d.overlap) return true;
        return callback(w.shapeId(index));
    });
}

}  // namespace

namespace {

DistanceProxy checkedProxy(const char* call, const Circle& circle) {
    checkCircle(call, circle);
    DistanceProxy proxy;
    proxy.count = 1;
    proxy.vertices[0] = circle.center;
    proxy.radius = circle.radius;
    return proxy;
}

DistanceProxy checkedProxy(const char* call, const Polygon& polygon) {
    ConvexPolygon checked;
    const std::string problem = makeConvexPolygon(polygon, checked);
    if (!problem.empty()) fail(call, problem);
    DistanceProxy proxy;
    proxy.count = checked.count;
    for (int i = 0; i < checked.count; ++i) proxy.vertices[i] = checked.vertices[i];
    return proxy;
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
    QueryScope scope(w);
    const BroadPhase& broadPhase = w.contactManager.broadPhase();
    broadPhase.tree().query(combine(start, end), [&](std::int32_t proxy) {
        const std::int32_t index = broadPhase.userData(proxy);
        const Shape& shape = w.shapes[index];
        if (!sees(filter, shape)) return true;
        const std::optional<CastEntry> entry =
            castShape(mover, xf, translation, proxyOf(shape), w.bodies[shape.body].xf, maxFraction);
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
    queryOverlaps(*impl_, query, xf, filter, callback);
}

void World::queryShape(const Polygon& polygon, const Transform& xf, const QueryFilter& filter,
                       ShapeCallback callback) const {
    const char* call = "World::queryShape";
    const DistanceProxy query = checkedProxy(call, polygon);
    checkTransform(call, xf);
    queryOverlaps(*impl_, query, xf, filter, callback);
}

// --- one shape, outside any world -------------------------------------------------------------

std::optional<RayHit> rayCast(const Circle& circle, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    checkCircle(call, circle);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    const std::optional<RayEntry> entry = rayCastCircle(circle, xf, origin, translation, 1.0f);
    if (!entry) return std::nullopt;
    return RayHit{ShapeId{}, entry->point, entry->normal, entry->fraction};
}

std::optional<RayHit> rayCast(const Polygon& polygon, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    ConvexPolygon checked;
    const std::string problem = makeConvexPolygon(polygon, checked);
    if (!problem.empty()) fail(call, problem);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    const std::optional<RayEntry> entry = rayCastPolygon(checked, xf, origin, translation, 1.0f);
    if (!entry) return std::nullopt;
    return RayHit{ShapeId{}, entry->point, entry->normal, entry->fraction};
}

std::optional<RayHit> rayCast(const Segment& segment, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    ConvexPolygon checked;
    const std::string problem = makeSegmentPolygon(segment, checked);
    if (!problem.empty()) fail(call, problem);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    const std::optional<RayEntry> entry = rayCastSegment(checked, xf, origin, translation, 1.0f);
    if (!entry) return std::nullopt;
    return RayHit{ShapeId{}, entry->point, entry->normal, entry->fraction};
}

bool testPoint(const Circle& circle, const Transform& xf, Vec2 point) {
    const char* call = "pivot::testPoint";
    checkCircle(call, circle);
    checkTransform(call, xf);
    requireCoordinate(call, "point", point);
    return circleContains(circle, xf, point);
}

bool testPoint(const Polygon& polygon, const Transform& xf, Vec2 point) {
    const char* call = "pivot::testPoint";
    ConvexPolygon checked;
    const std::string problem = makeConvexPolygon(polygon, checked);
    if (!problem.empty()) fail(call, problem);
    checkTransform(call, xf);
    requireCoordinate(call, "point", point);
    return polygonContains(checked, xf, point);
}

}  // namespace pivot
