// Shape storage: a body's collision geometry with its material, filter and broad-phase proxy.
#pragma once

#include <array>
#include <cstdint>

#include "collision/aabb.h"
#include "collision/distance.h"
#include "collision/geometry.h"
#include "collision/manifold.h"
#include "pivot/shape.h"

namespace pivot {

struct Shape {
    std::int32_t body = -1;
    ShapeType type = ShapeType::Circle;
    Circle circle;
    // A polygon's; a capsule's core, rounded by its radius; a segment's (either kind): two
    // vertices each.
    ConvexPolygon polygon;
    Vec2 ghost1;  // a chain segment's neighbouring chain points (ChainSegment)
    Vec2 ghost2;
    float density = 0.0f;
    float friction = 0.0f;
    float restitution = 0.0f;
    Filter filter;
    std::uint64_t userData = 0;
    bool sensor = false;        // ShapeDef::isSensor
    bool hitEvents = false;     // ShapeDef::enableHitEvents
    bool preSolve = false;      // ShapeDef::enablePreSolve
    std::int32_t proxyId = -1;  // broad-phase proxy
    AABB box;  // the shape's box at its body's current transform (kept by the broad-phase sync)
    // The body's shapes form a doubly linked list through the shape pool.
    std::int32_t prev = -1;
    std::int32_t next = -1;
};

/// A shape's mass, centroid, and second moment about its frame's origin (what a body sums)
/// and about its centroid (what computeMass reports, computed directly rather than by
/// subtracting two large numbers).
struct OriginMass {
    float mass = 0.0f;
    Vec2 center;
    float inertia = 0.0f;
    float centroidInertia = 0.0f;
};
OriginMass shapeMassAboutOrigin(const Shape& shape);

/// Segments and chain segments: no area, no mass, always shape A of their contacts.
inline bool isSegmentLike(ShapeType type) {
    return type == ShapeType::Segment || type == ShapeType::ChainSegment;
}

/// A segment or chain segment as the segment routines see it.
inline EdgeSegment edgeSegmentOf(const Shape& shape) {
    EdgeSegment e;
    e.v1 = shape.polygon.vertices[0];
    e.v2 = shape.polygon.vertices[1];
    e.oneSided = shape.type == ShapeType::ChainSegment;
    e.ghost1 = shape.ghost1;
    e.ghost2 = shape.ghost2;
    return e;
}

/// The radius a shape collides with: a circle's own, or the skin kPolygonRadius of polygons and
/// segments beyond a polygon's rounding or a capsule's radius.
inline float collisionRadius(const Shape& shape) {
    return shape.type == ShapeType::Circle ? shape.circle.radius
                                           : kPolygonRadius + shape.polygon.radius;
}

/// The shape as GJK and the time of impact see it in contacts: its core and collision radius.
DistanceProxy contactProxy(const Shape& shape);

/// How far a shape reaches from a body's centre of mass (`localCenter`, in the body frame):
/// `min` is the depth of its thinnest part measured from its centroid (a circle's radius, a
/// box's half width, 0 for a segment), `max` the distance of its farthest point from the
/// centre. Continuous collision's FastBodies takes a body as fast when it moved more than half
/// its shapes' smallest `min` in a step (continuous_collision.h).
struct ShapeExtent {
    float min = 0.0f;
    float max = 0.0f;
};
ShapeExtent shapeExtent(const Shape& shape, Vec2 localCenter);

/// The shape's bounding box at a transform, including its collision radius.
AABB computeShapeBox(const Shape& shape, const Transform& xf);

}  // namespace pivot
