// The World facade, part four: rays, boxes and points (shapes as queries and casts:
// world_shape_queries.cpp). Each walks the broad phase's tree (its fat boxes hold every shape's
// current box) and tests the shapes it reaches exactly.
#include <algorithm>
#include <cmath>

#include "collision/ray_cast.h"
#include "world/query_support.h"

namespace pivot {

namespace {

using namespace queries;

std::optional<RayEntry> castOnShape(const Shape& shape, const Transform& xf, Vec2 origin,
                                    Vec2 translation, float maxFraction) {
    switch (shape.type) {
        case ShapeType::Circle:
            return rayCastCircle(shape.circle, xf, origin, translation, maxFraction);
        case ShapeType::Polygon:
        case ShapeType::Capsule:
            return rayCastPolygon(shape.polygon, xf, origin, translation, maxFraction);
        case ShapeType::Segment:
            return rayCastSegment(shape.polygon, xf, origin, translation, maxFraction);
        case ShapeType::ChainSegment:
            return rayCastSegment(shape.polygon, xf, origin, translation, maxFraction, true);
    }
    return std::nullopt;
}

/// A segment (of either kind) has no inside: it contains no point.
bool shapeContains(const Shape& shape, const Transform& xf, Vec2 point) {
    switch (shape.type) {
        case ShapeType::Circle: return circleContains(shape.circle, xf, point);
        case ShapeType::Polygon:
        case ShapeType::Capsule: return polygonContains(shape.polygon, xf, point);
        case ShapeType::Segment:
        case ShapeType::ChainSegment: return false;
    }
    return false;
}

}  // namespace

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
    const WorldAccess::QueryScope scope(w.access, call);
    const BroadPhase& broadPhase = w.contactManager.broadPhase();
    broadPhase.rayCast(origin, translation, 1.0f, [&](std::int32_t proxy, float maxFraction) {
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
    return asHit(id, castOnShape(shape, w.bodies[shape.body].xf, origin, translation, 1.0f));
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
    forEachCandidate(call, w, box, filter, [&](std::int32_t index, const Shape& shape) {
        return !overlaps(shape.box, box) || callback(w.shapeId(index));
    });
}

void World::queryPoint(Vec2 point, const QueryFilter& filter, ShapeCallback callback) const {
    const char* call = "World::queryPoint";
    const Impl& w = *impl_;
    requireCoordinate(call, "point", point);
    forEachCandidate(call, w, AABB{point, point}, filter,
                     [&](std::int32_t index, const Shape& shape) {
                         return !shapeContains(shape, w.bodies[shape.body].xf, point) ||
                                callback(w.shapeId(index));
                     });
}

// --- one shape, outside any world -------------------------------------------------------------

std::optional<RayHit> rayCast(const Circle& circle, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    checkCircle(call, circle);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    return asHit(ShapeId{}, rayCastCircle(circle, xf, origin, translation, 1.0f));
}

std::optional<RayHit> rayCast(const Polygon& polygon, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    const ConvexPolygon checked = checkedPolygon(call, polygon);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    return asHit(ShapeId{}, rayCastPolygon(checked, xf, origin, translation, 1.0f));
}

std::optional<RayHit> rayCast(const Segment& segment, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    const ConvexPolygon checked = checkedSegment(call, segment);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    return asHit(ShapeId{}, rayCastSegment(checked, xf, origin, translation, 1.0f));
}

std::optional<RayHit> rayCast(const ChainSegment& segment, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    ConvexPolygon checked;
    const std::string problem = makeChainSegment(segment, checked);
    if (!problem.empty()) fail(call, problem);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    return asHit(ShapeId{}, rayCastSegment(checked, xf, origin, translation, 1.0f, true));
}

std::optional<RayHit> rayCast(const Capsule& capsule, const Transform& xf, Vec2 origin,
                              Vec2 translation) {
    const char* call = "pivot::rayCast";
    const ConvexPolygon checked = checkedCapsule(call, capsule);
    checkTransform(call, xf);
    checkRay(call, origin, translation);
    return asHit(ShapeId{}, rayCastPolygon(checked, xf, origin, translation, 1.0f));
}

bool testPoint(const Capsule& capsule, const Transform& xf, Vec2 point) {
    const char* call = "pivot::testPoint";
    const ConvexPolygon checked = checkedCapsule(call, capsule);
    checkTransform(call, xf);
    requireCoordinate(call, "point", point);
    return polygonContains(checked, xf, point);
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
    const ConvexPolygon checked = checkedPolygon(call, polygon);
    checkTransform(call, xf);
    requireCoordinate(call, "point", point);
    return polygonContains(checked, xf, point);
}

}  // namespace pivot
