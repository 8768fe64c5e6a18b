#include "shape.h"

#include <algorithm>
#include <cmath>

#include "validation.h"

namespace pivot {

Polygon Polygon::box(float halfWidth, float halfHeight) {
    const char* call = "Polygon::box";
    requireFinite(call, "halfWidth", halfWidth);
    requireFinite(call, "halfHeight", halfHeight);
    if (halfWidth <= 0.0f) fail(call, "halfWidth must be > 0 (got " + formatFloat(halfWidth) + ")");
    if (halfHeight <= 0.0f) {
        fail(call, "halfHeight must be > 0 (got " + formatFloat(halfHeight) + ")");
    }
    Polygon p;
    p.count = 4;
    p.vertices[0] = {-halfWidth, -halfHeight};
    p.vertices[1] = {halfWidth, -halfHeight};
    p.vertices[2] = {halfWidth, halfHeight};
    p.vertices[3] = {-halfWidth, halfHeight};
    return p;
}

Polygon Polygon::box(float halfWidth, float halfHeight, Vec2 center, float angle) {
    requireFinite("Polygon::box", "center", center);
    requireFinite("Polygon::box", "angle", angle);
    Polygon p = box(halfWidth, halfHeight);
    Transform xf{center, Rot(angle)};
    for (int i = 0; i < p.count; ++i) p.vertices[i] = transformPoint(xf, p.vertices[i]);
    return p;
}

Polygon Polygon::fromPoints(std::initializer_list<Vec2> points) {
    if (points.size() > static_cast<std::size_t>(kMaxPolygonVertices)) {
        fail("Polygon::fromPoints", "points has " + std::to_string(points.size()) +
                                        " vertices, more than kMaxPolygonVertices (" +
                                        std::to_string(kMaxPolygonVertices) + ")");
    }
    Polygon p;
    for (Vec2 v : points) p.vertices[p.count++] = v;
    return p;
}

namespace {

float signedArea(const Polygon& p) {
    // Shoelace formula relative to vertex 0, which keeps round-off small away from the origin.
    float twiceArea = 0.0f;
    for (int i = 1; i + 1 < p.count; ++i) {
        twiceArea += cross(p.vertices[i] - p.vertices[0], p.vertices[i + 1] - p.vertices[0]);
    }
    return 0.5f * twiceArea;
}

std::string vertexName(int i) {
    return "vertices[" + std::to_string(i) + "]";
}

}  // namespace

std::string makeConvexPolygon(const Polygon& input, ConvexPolygon& out) {
    const int n = input.count;
    if (n < 3 || n > kMaxPolygonVertices) {
        return "polygon.count must be in [3, " + std::to_string(kMaxPolygonVertices) + "] (got " +
               std::to_string(n) + ")";
    }
    for (int i = 0; i < n; ++i) {
        if (!isFinite(input.vertices[i])) {
            return "polygon." + vertexName(i) + " must be finite (got " +
                   formatVec2(input.vertices[i]) + ")";
        }
    }

    // Accept either winding; store counter-clockwise.
    const float area = signedArea(input);
    ConvexPolygon poly;
    poly.count = n;
    for (int i = 0; i < n; ++i) {
        poly.vertices[i] = area >= 0.0f ? input.vertices[i] : input.vertices[n - 1 - i];
    }

    for (int i = 0; i < n; ++i) {
        Vec2 edge = poly.vertices[(i + 1) % n] - poly.vertices[i];
        float len = length(edge);
        if (len < kLinearSlop) {
            return "polygon has repeated vertices: " + vertexName(i) + " and " +
                   vertexName((i + 1) % n) + " are " + formatFloat(len) +
                   " m apart, less than kLinearSlop";
        }
        poly.normals[i] = (1.0f / len) * Vec2{edge.y, -edge.x};
    }

    // Strict convexity: every vertex not on an edge lies inside that edge's line by more than
    // a tenth of the slop. On the line means collinear points; outside means a dent.
    const float tolerance = 0.1f * kLinearSlop;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            float d = dot(poly.normals[i], poly.vertices[j] - poly.vertices[i]);
            if (d > tolerance) {
                return "polygon is not convex: a vertex lies outside the line of another edge";
            }
            if (d > -tolerance) {
                return "polygon has collinear points (area " + formatFloat(std::fabs(area)) +
                       " m^2): a vertex lies on the line of another edge";
            }
        }
    }
    out = poly;
    return {};
}

MassData computeMass(const Circle& circle, float density) {
    MassData md;
    float rr = circle.radius * circle.radius;
    md.mass = density * kPi * rr;
    md.center = circle.center;
    md.rotationalInertia = md.mass * 0.5f * rr;
    return md;
}

MassData computeMass(const Polygon& polygon, float density) {
    // Split into triangles fanning from vertex 0 (small numbers, small round-off). For a
    // triangle (0, e1, e2) of area A = cross(e1, e2) / 2 the centroid is (e1 + e2) / 3 and the
    // second moment about vertex 0 is A/6 * (|e1|^2 + e1.e2 + |e2|^2).
    const Vec2 origin = polygon.vertices[0];
    float area = 0.0f;
    Vec2 firstMoment;
    float secondMoment = 0.0f;  // about origin, per unit density
    for (int i = 1; i + 1 < polygon.count; ++i) {
        Vec2 e1 = polygon.vertices[i] - origin;
        Vec2 e2 = polygon.vertices[i + 1] - origin;
        float triangleArea = 0.5f * cross(e1, e2);
        area += triangleArea;
        firstMoment += (triangleArea / 3.0f) * (e1 + e2);
        secondMoment += (triangleArea / 6.0f) * (dot(e1, e1) + dot(e1, e2) + dot(e2, e2));
    }
    MassData md;
    if (area == 0.0f) {
        md.center = origin;  // degenerate: no area, no mass
        return md;
    }
    Vec2 centroidFromOrigin = (1.0f / area) * firstMoment;
    md.center = origin + centroidFromOrigin;
    // Parallel-axis theorem: move the second moment from vertex 0 to the centroid. A clockwise
    // polygon gives area and moments of the opposite sign; the ratio above is unaffected.
    float sign = area > 0.0f ? 1.0f : -1.0f;
    md.mass = sign * density * area;
    md.rotationalInertia =
        sign * density * (secondMoment - area * dot(centroidFromOrigin, centroidFromOrigin));
    return md;
}

AABB computeShapeBox(const Shape& shape, const Transform& xf) {
    if (shape.type == ShapeType::Circle) {
        Vec2 c = transformPoint(xf, shape.circle.center);
        Vec2 r{shape.circle.radius, shape.circle.radius};
        return {c - r, c + r};
    }
    Vec2 lower = transformPoint(xf, shape.polygon.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < shape.polygon.count; ++i) {
        Vec2 v = transformPoint(xf, shape.polygon.vertices[i]);
        lower = {std::min(lower.x, v.x), std::min(lower.y, v.y)};
        upper = {std::max(upper.x, v.x), std::max(upper.y, v.y)};
    }
    Vec2 r{kPolygonRadius, kPolygonRadius};
    return {lower - r, upper + r};
}

MassData computeShapeMass(const Shape& shape) {
    if (shape.type == ShapeType::Circle) return computeMass(shape.circle, shape.density);
    Polygon p;
    p.count = shape.polygon.count;
    for (int i = 0; i < p.count; ++i) p.vertices[i] = shape.polygon.vertices[i];
    return computeMass(p, shape.density);
}

}  // namespace pivot
