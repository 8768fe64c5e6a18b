#include "collision/geometry.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/validation.h"

namespace pivot {

namespace {
void requireExtent(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (value <= 0.0f)
        fail(call, std::string(field) + " must be > 0 (got " + formatFloat(value) + ")");
    if (value > kMaxCoordinate) {
        fail(call, std::string(field) + " must be <= kMaxCoordinate (" +
                       formatFloat(kMaxCoordinate) + " m) (got " + formatFloat(value) + ")");
    }
}
}  // namespace

Polygon Polygon::box(float halfWidth, float halfHeight) {
    const char* call = "Polygon::box";
    requireExtent(call, "halfWidth", halfWidth);
    requireExtent(call, "halfHeight", halfHeight);
    Polygon p;
    p.count = 4;
    p.vertices[0] = {-halfWidth, -halfHeight};
    p.vertices[1] = {halfWidth, -halfHeight};
    p.vertices[2] = {halfWidth, halfHeight};
    p.vertices[3] = {-halfWidth, halfHeight};
    return p;
}

Polygon Polygon::box(float halfWidth, float halfHeight, Vec2 center, float angle) {
    requireCoordinate("Polygon::box", "center", center);
    requireMagnitude("Polygon::box", "angle", angle);
    Polygon p = box(halfWidth, halfHeight);
    Transform xf{center, Rot(angle)};
    for (int i = 0; i < p.count; ++i) p.vertices[i] = transformPoint(xf, p.vertices[i]);
    return p;
}

Polygon Polygon::roundedBox(float halfWidth, float halfHeight, float radius) {
    const char* call = "Polygon::roundedBox";
    if (!std::isfinite(radius) || radius < 0.0f) {
        fail(call, "radius must be finite and >= 0 (got " + formatFloat(radius) + ")");
    }
    const float coreWidth = halfWidth - radius;
    const float coreHeight = halfHeight - radius;
    if (!(coreWidth >= 0.5f * kLinearSlop && coreHeight >= 0.5f * kLinearSlop)) {
        fail(call, "half extents " + formatFloat(halfWidth) + " x " + formatFloat(halfHeight) +
                       " must each exceed the radius " + formatFloat(radius) +
                       " by at least kLinearSlop / 2");
    }
    Polygon p = box(coreWidth, coreHeight);
    p.radius = radius;
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

// The hull's corners, counter-clockwise, by Andrew's monotone chain: the points sorted by x then
// y, a lower chain left to right and an upper one back, each keeping only left turns.
std::vector<Vec2> monotoneChain(std::vector<Vec2> points) {
    std::sort(points.begin(), points.end(),
              [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2> hull;
    const auto turnsLeft = [&](Vec2 next) {
        const std::size_t n = hull.size();
        return cross(hull[n - 1] - hull[n - 2], next - hull[n - 2]) > 0.0f;
    };
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = hull.size();
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Vec2 p = pass == 0 ? points[k] : points[points.size() - 1 - k];
            while (hull.size() >= start + 2 && !turnsLeft(p)) hull.pop_back();
            hull.push_back(p);
        }
        hull.pop_back();  // the chain's last point starts the other chain
    }
    return hull;
}

// Drops what makeConvexPolygon would refuse: a corner within kLinearSlop of the next one, and a
// corner within a tenth of the slop of the line through its neighbours, until neither is left.
void cleanHull(std::vector<Vec2>& hull) {
    bool changed = true;
    while (changed && hull.size() >= 3) {
        changed = false;
        for (std::size_t i = 0; i < hull.size() && hull.size() >= 3; ++i) {
            const Vec2 previous = hull[(i + hull.size() - 1) % hull.size()];
            const Vec2 next = hull[(i + 1) % hull.size()];
            const Vec2 edge = next - previous;
            const float span = length(edge);
            const bool merged = length(next - hull[i]) < kLinearSlop;
            // How far the corner stands out of the line through its neighbours.
            const bool onLine =
                span > 0.0f && cross(hull[i] - previous, edge) / span < 0.1f * kLinearSlop;
            if (merged || onLine) {
                hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                break;
            }
        }
    }
}

}  // namespace

Polygon Polygon::convexHull(const Vec2* points, int count) {
    const char* call = "Polygon::convexHull";
    if (count < 3) fail(call, "needs at least 3 points (got " + std::to_string(count) + ")");
    for (int i = 0; i < count; ++i) {
        requireCoordinate(call, ("points[" + std::to_string(i) + "]").c_str(), points[i]);
    }
    std::vector<Vec2> hull = monotoneChain(std::vector<Vec2>(points, points + count));
    cleanHull(hull);
    if (hull.size() < 3) {
        fail(call, "the points have no area: they lie on one line, or within kLinearSlop (" +
                       formatFloat(kLinearSlop) + " m) of each other");
    }
    if (hull.size() > static_cast<std::size_t>(kMaxPolygonVertices)) {
        fail(call, "the hull has " + std::to_string(hull.size()) +
                       " corners, more than kMaxPolygonVertices (" +
                       std::to_string(kMaxPolygonVertices) + "); simplify the points first");
    }
    Polygon polygon;
    for (Vec2 v : hull) polygon.vertices[polygon.count++] = v;
    ConvexPolygon checked;
    const std::string problem = makeConvexPolygon(polygon, checked);
    if (!problem.empty()) fail(call, "the hull is not a valid polygon: " + problem);
    return polygon;
}

Polygon Polygon::convexHull(std::initializer_list<Vec2> points) {
    return convexHull(points.begin(), static_cast<int>(points.size()));
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
        Vec2 v = input.vertices[i];
        if (!isFinite(v)) {
            return "polygon." + vertexName(i) + " must be finite (got " + formatVec2(v) + ")";
        }
        if (std::fpclassify(v.x) == FP_SUBNORMAL || std::fpclassify(v.y) == FP_SUBNORMAL) {
            return "polygon." + vertexName(i) + " must be 0 or normal floats, not denormals (got " +
                   formatVec2(v) + ")";
        }
        if (std::fabs(v.x) > kMaxCoordinate || std::fabs(v.y) > kMaxCoordinate) {
            return "polygon." + vertexName(i) + " must be within +-kMaxCoordinate (" +
                   formatFloat(kMaxCoordinate) + " m) (got " + formatVec2(v) + ")";
        }
    }

    const float r = input.radius;
    if (!std::isfinite(r) || r < 0.0f || r > kMaxCoordinate) {
        return "polygon.radius must be in [0, kMaxCoordinate] (got " + formatFloat(r) + ")";
    }
    if (std::fpclassify(r) == FP_SUBNORMAL) {
        return "polygon.radius must be 0 or a normal float, not a denormal (got " + formatFloat(r) +
               ")";
    }

    // Accept either winding; store counter-clockwise.
    const float area = signedArea(input);
    ConvexPolygon poly;
    poly.count = n;
    poly.radius = r;
    for (int i = 0; i < n; ++i) {
        poly.vertices[i] = area >= 0.0f ? input.vertices[i] : input.vertices[n - 1 - i];
    }

    // Messages name the vertices as the caller numbered them, before any reversal.
    const auto given = [&](int i) { return area >= 0.0f ? i : n - 1 - i; };
    for (int i = 0; i < n; ++i) {
        Vec2 edge = poly.vertices[(i + 1) % n] - poly.vertices[i];
        float len = length(edge);
        if (len < kLinearSlop) {
            const int a = std::min(given(i), given((i + 1) % n));
            const int b = std::max(given(i), given((i + 1) % n));
            return "polygon edge from " + vertexName(a) + " to " + vertexName(b) + " is " +
                   formatFloat(len) + " m long; every edge must be at least kLinearSlop (" +
                   formatFloat(kLinearSlop) + " m)" + (len == 0.0f ? " (repeated vertex)" : "");
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
    poly.centroid = polygonCentroid(poly.vertices.data(), poly.count);
    out = poly;
    return {};
}

Vec2 polygonCentroid(const Vec2* vertices, int count) {
    // Triangles fanned from the first vertex, measured from it (small numbers, little
    // round-off); the sums in Box2D 2.4.1's order, so the one-sided segment routine's front test
    // sees the same centroid as that engine's.
    const Vec2 origin = vertices[0];
    const float third = 1.0f / 3.0f;
    Vec2 weighted{0.0f, 0.0f};
    float area = 0.0f;
    for (int i = 0; i < count; ++i) {
        const Vec2 p1 = vertices[0] - origin;
        const Vec2 p2 = vertices[i] - origin;
        const Vec2 p3 = i + 1 < count ? vertices[i + 1] - origin : vertices[0] - origin;
        const float triangleArea = 0.5f * cross(p2 - p1, p3 - p1);
        area += triangleArea;
        weighted += triangleArea * third * (p1 + p2 + p3);
    }
    return (1.0f / area) * weighted + origin;
}

std::string checkPathPoint(const std::string& name, Vec2 point) {
    if (!isFinite(point)) return name + " must be finite (got " + formatVec2(point) + ")";
    if (std::fpclassify(point.x) == FP_SUBNORMAL || std::fpclassify(point.y) == FP_SUBNORMAL) {
        return name + " must be 0 or a normal float, not a denormal (got " + formatVec2(point) +
               ")";
    }
    if (std::fabs(point.x) > kMaxCoordinate || std::fabs(point.y) > kMaxCoordinate) {
        return name + " must be within +-kMaxCoordinate (" + formatFloat(kMaxCoordinate) +
               " m) (got " + formatVec2(point) + ")";
    }
    return {};
}

std::string checkPathStep(const std::string& from, Vec2 a, const std::string& to, Vec2 b) {
    const float distance = length(b - a);
    // Shorter than the slop a contact could not resolve it, as for a polygon's edges; and the
    // segment routines take directions from these steps.
    if (!(distance >= kLinearSlop)) {
        return from + " and " + to + " must be at least kLinearSlop (" + formatFloat(kLinearSlop) +
               " m) apart (got " + formatFloat(distance) + " m)" +
               (distance == 0.0f ? " (repeated point)" : "");
    }
    return {};
}

std::string makeSegmentPolygon(const Segment& input, ConvexPolygon& out) {
    const Vec2 points[2] = {input.point1, input.point2};
    for (int i = 0; i < 2; ++i) {
        std::string problem =
            checkPathPoint(i == 0 ? "segment.point1" : "segment.point2", points[i]);
        if (!problem.empty()) return problem;
    }
    std::string problem = checkPathStep("segment.point1", points[0], "segment.point2", points[1]);
    if (!problem.empty()) return problem;
    const Vec2 edge = points[1] - points[0];
    const float edgeLength = length(edge);
    out = ConvexPolygon{};
    out.count = 2;
    out.vertices[0] = points[0];
    out.vertices[1] = points[1];
    out.normals[0] = (1.0f / edgeLength) * cross(edge, 1.0f);
    out.normals[1] = -out.normals[0];
    out.centroid = 0.5f * (points[0] + points[1]);
    return {};
}

std::string makeCapsulePolygon(const Capsule& input, ConvexPolygon& out) {
    std::string problem = checkPathPoint("capsule.center1", input.center1);
    if (problem.empty()) problem = checkPathPoint("capsule.center2", input.center2);
    if (problem.empty()) {
        problem = checkPathStep("capsule.center1", input.center1, "capsule.center2", input.center2);
        if (!problem.empty()) problem += "; a shorter capsule is a Circle";
    }
    if (problem.empty() && !(input.radius >= kLinearSlop && input.radius <= kMaxCoordinate)) {
        problem = "capsule.radius must be in [kLinearSlop, kMaxCoordinate] = [" +
                  formatFloat(kLinearSlop) + ", " + formatFloat(kMaxCoordinate) + "] m (got " +
                  formatFloat(input.radius) + ")";
    }
    if (!problem.empty()) return problem;
    // The core is a two-sided segment; the radius rounds it into the capsule.
    problem = makeSegmentPolygon(Segment{input.center1, input.center2}, out);
    out.radius = input.radius;
    return problem;
}

std::string makeChainSegment(const ChainSegment& input, ConvexPolygon& out) {
    std::string problem = checkPathPoint("ghost1", input.ghost1);
    if (problem.empty()) problem = checkPathPoint("ghost2", input.ghost2);
    if (problem.empty()) problem = makeSegmentPolygon(input.segment, out);
    if (problem.empty()) {
        problem = checkPathStep("ghost1", input.ghost1, "segment.point1", input.segment.point1);
    }
    if (problem.empty()) {
        problem = checkPathStep("segment.point2", input.segment.point2, "ghost2", input.ghost2);
    }
    return problem;
}

void checkCircle(const char* call, const Circle& circle) {
    requireCoordinate(call, "circle.center", circle.center);
    requireFinite(call, "circle.radius", circle.radius);
    // Smaller than the slop a contact could not resolve it, as for a polygon's edges; the bound
    // also keeps the lightest circle's inverse mass a finite float (see kMinDensity).
    if (circle.radius < kLinearSlop) {
        fail(call, "circle.radius must be >= kLinearSlop (" + formatFloat(kLinearSlop) +
                       " m) (got " + formatFloat(circle.radius) + ")");
    }
    if (circle.radius > kMaxCoordinate) {
        fail(call, "circle.radius must be <= kMaxCoordinate (" + formatFloat(kMaxCoordinate) +
                       " m) (got " + formatFloat(circle.radius) + ")");
    }
}

}  // namespace pivot
