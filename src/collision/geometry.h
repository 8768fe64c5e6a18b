// Shape geometry as collision sees it, and the checks that turn a user's polygon or circle
// into it.
#pragma once

#include <array>
#include <string>

#include "pivot/shape.h"

namespace pivot {

/// A checked convex polygon: counter-clockwise, with outward unit edge normals
/// (normals[i] belongs to the edge from vertices[i] to vertices[i + 1]).
struct ConvexPolygon {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    std::array<Vec2, kMaxPolygonVertices> normals{};
    int count = 0;
    float radius = 0.0f;  // rounding (Polygon::radius); 0 for a segment
};

/// Checks a user polygon. Returns what is wrong with it as text, or an empty string and the
/// polygon in canonical form in `out`.
std::string makeConvexPolygon(const Polygon& input, ConvexPolygon& out);
/// Checks a user segment (points within kMaxCoordinate, at least kLinearSlop apart) and makes
/// it the two-sided polygon the narrow phase sees: two vertices, the face point1 -> point2 with
/// the normal on its right and the face back with the opposite normal. Returns what is wrong,
/// or an empty string.
std::string makeSegmentPolygon(const Segment& input, ConvexPolygon& out);
/// Checks a user circle (centre within kMaxCoordinate, radius in [kLinearSlop,
/// kMaxCoordinate]); throws pivot::Error naming `call`.
void checkCircle(const char* call, const Circle& circle);

}  // namespace pivot
