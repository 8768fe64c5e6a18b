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
    Vec2 centroid;        // of the area (a segment's midpoint)
};

/// The centroid of a counter-clockwise polygon's area, computed as Box2D 2.4.1 computes it.
Vec2 polygonCentroid(const Vec2* vertices, int count);

/// Checks a user polygon. Returns what is wrong with it as text, or an empty string and the
/// polygon in canonical form in `out`.
std::string makeConvexPolygon(const Polygon& input, ConvexPolygon& out);
/// Checks a user segment (points within kMaxCoordinate, at least kLinearSlop apart) and makes
/// it the two-sided polygon the narrow phase sees: two vertices, the face point1 -> point2 with
/// the normal on its right and the face back with the opposite normal. Returns what is wrong,
/// or an empty string.
std::string makeSegmentPolygon(const Segment& input, ConvexPolygon& out);
/// Checks a chain segment: its segment as above, its ghosts as its points, each ghost at least
/// kLinearSlop from the point beside it. Returns what is wrong, or an empty string and the
/// segment in `out`.
std::string makeChainSegment(const ChainSegment& input, ConvexPolygon& out);
/// Checks one point of a segment or chain (finite, not denormal, within kMaxCoordinate) and one
/// step between two (at least kLinearSlop); each returns what is wrong, naming the points, or an
/// empty string.
std::string checkPathPoint(const std::string& name, Vec2 point);
std::string checkPathStep(const std::string& from, Vec2 a, const std::string& to, Vec2 b);
/// Checks a user capsule (centres as a segment's points, radius in [kLinearSlop,
/// kMaxCoordinate]) and makes it the rounded polygon of two vertices the narrow phase sees.
/// Returns what is wrong, or an empty string.
std::string makeCapsulePolygon(const Capsule& input, ConvexPolygon& out);
/// Checks a user circle (centre within kMaxCoordinate, radius in [kLinearSlop,
/// kMaxCoordinate]); throws pivot::Error naming `call`.
void checkCircle(const char* call, const Circle& circle);

}  // namespace pivot
