// What the World's query files share: the filter rule, the argument checks, and the scope that
// marks a query under way (world_access.h).
#pragma once

#include <optional>
#include <string>

#include "collision/geometry.h"
#include "collision/ray_cast.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot::queries {

inline bool sees(const QueryFilter& filter, const Shape& shape) {
    return (shape.filter.categoryBits & filter.maskBits) != 0 &&
           (shape.filter.maskBits & filter.categoryBits) != 0;
}

inline void checkTransform(const char* call, const Transform& xf) {
    requireTransform(call, "xf", xf);
}

inline void checkRay(const char* call, Vec2 origin, Vec2 translation) {
    requireCoordinate(call, "origin", origin);
    // The end point may lie outside the world's limits (a long line of sight), but the
    // arithmetic must stay finite.
    requireMagnitude(call, "translation", translation);
}

inline ConvexPolygon checkedPolygon(const char* call, const Polygon& polygon) {
    ConvexPolygon checked;
    const std::string problem = makeConvexPolygon(polygon, checked);
    if (!problem.empty()) fail(call, problem);
    return checked;
}

inline ConvexPolygon checkedCapsule(const char* call, const Capsule& capsule) {
    ConvexPolygon checked;
    const std::string problem = makeCapsulePolygon(capsule, checked);
    if (!problem.empty()) fail(call, problem);
    return checked;
}

inline ConvexPolygon checkedSegment(const char* call, const Segment& segment) {
    ConvexPolygon checked;
    const std::string problem = makeSegmentPolygon(segment, checked);
    if (!problem.empty()) fail(call, problem);
    return checked;
}

inline std::optional<RayHit> asHit(ShapeId shape, const std::optional<RayEntry>& entry) {
    if (!entry) return std::nullopt;
    return RayHit{shape, entry->point, entry->normal, entry->fraction};
}

/// Walks the shapes whose fat boxes overlap `box` and that the filter sees, as the query scope
/// requires: visit(index, shape) returns false to stop.
template <typename Visit>
void forEachCandidate(const char* call, const World::Impl& w, const AABB& box,
                      const QueryFilter& filter, Visit&& visit) {
    const WorldAccess::QueryScope scope(w.access, call);
    const BroadPhase& broadPhase = w.contactManager.broadPhase();
    broadPhase.query(box, [&](std::int32_t proxy) {
        const std::int32_t index = broadPhase.userData(proxy);
        const Shape& shape = w.shapes[index];
        return !sees(filter, shape) || visit(index, shape);
    });
}

}  // namespace pivot::queries
