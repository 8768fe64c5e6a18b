// Shape storage and polygon checking.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "collision/aabb.h"
#include "pivot/shape.h"

namespace pivot {

/// A checked convex polygon: counter-clockwise, with outward unit edge normals
/// (normals[i] belongs to the edge from vertices[i] to vertices[i + 1]).
struct ConvexPolygon {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    std::array<Vec2, kMaxPolygonVertices> normals{};
    int count = 0;
};

struct Shape {
    std::int32_t body = -1;
    ShapeType type = ShapeType::Circle;
    Circle circle;
    ConvexPolygon polygon;
    float density = 0.0f;
    float friction = 0.0f;
    float restitution = 0.0f;
    Filter filter;
    std::uint64_t userData = 0;
    std::int32_t proxyId = -1;  // broad-phase proxy
    AABB box;  // the shape's box at its body's current transform (kept by the broad-phase sync)
    // The body's shapes form a doubly linked list through the shape pool.
    std::int32_t prev = -1;
    std::int32_t next = -1;
};

/// Checks a user polygon. Returns what is wrong with it as text, or an empty string and the
/// polygon in canonical form in `out`.
std::string makeConvexPolygon(const Polygon& input, ConvexPolygon& out);
/// Checks a user circle (centre within kMaxCoordinate, radius in [kLinearSlop,
/// kMaxCoordinate]); throws pivot::Error naming `call`.
void checkCircle(const char* call, const Circle& circle);

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

/// The radius a shape collides with: a circle's own, or the polygon skin kPolygonRadius.
inline float collisionRadius(const Shape& shape) {
    return shape.type == ShapeType::Circle ? shape.circle.radius : kPolygonRadius;
}

/// The shape's bounding box at a transform, including its collision radius.
AABB computeShapeBox(const Shape& shape, const Transform& xf);

}  // namespace pivot
