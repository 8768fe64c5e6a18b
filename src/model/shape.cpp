#include "model/shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/validation.h"

namespace pivot {

// Mass properties are evaluated in the same float order as Box2D 2.4.1, so that bodies built
// from the same shapes get bit-identical masses, centres and inertias in both engines (the
// reference comparison of docs/reference-agreement.md depends on it). Internally a shape's
// second moment is kept about its frame's origin, which is what a body sums.
OriginMass circleMassAboutOrigin(const Circle& circle, float density) {
    OriginMass m;
    m.mass = density * kPi * circle.radius * circle.radius;
    m.center = circle.center;
    m.inertia = m.mass * (0.5f * circle.radius * circle.radius + dot(circle.center, circle.center));
    m.centroidInertia = m.mass * (0.5f * circle.radius * circle.radius);
    return m;
}

OriginMass polygonMassAboutOrigin(const Vec2* vertices, int count, float density) {
    // A fan of triangles (apex, v[i], v[i+1]) from the first vertex, which keeps coordinates
    // and so round-off small. For edge vectors e1, e2 from the apex, a triangle has area
    // D / 2 with D = cross(e1, e2), centroid (e1 + e2) / 3, and second moment about the apex
    // D / 12 * (e1.x^2 + e1.x e2.x + e2.x^2 + the same in y). The fan closes back on the apex,
    // so its first and last triangles are empty; they are summed anyway, as the reference does.
    const Vec2 apex = vertices[0];
    const float third = 1.0f / 3.0f;
    Vec2 firstMoment;
    float area = 0.0f;
    float secondMoment = 0.0f;
    for (int i = 0; i < count; ++i) {
        Vec2 e1 = vertices[i] - apex;
        Vec2 e2 = (i + 1 < count ? vertices[i + 1] : vertices[0]) - apex;
        float D = cross(e1, e2);
        float triangleArea = 0.5f * D;
        area += triangleArea;
        firstMoment += triangleArea * third * (e1 + e2);
        float xx = e1.x * e1.x + e2.x * e1.x + e2.x * e2.x;
        float yy = e1.y * e1.y + e2.y * e1.y + e2.y * e2.y;
        secondMoment += (0.25f * third * D) * (xx + yy);
    }
    OriginMass m;
    if (area == 0.0f) {
        m.center = apex;  // degenerate: no area, no mass
        return m;
    }
    m.mass = density * area;
    Vec2 centroidFromApex = firstMoment;
    centroidFromApex *= 1.0f / area;
    m.center = centroidFromApex + apex;
    // Parallel-axis theorem twice: from the apex to the centroid, then to the frame's origin.
    m.inertia = density * secondMoment;
    m.inertia += m.mass * (dot(m.center, m.center) - dot(centroidFromApex, centroidFromApex));
    m.centroidInertia = density * secondMoment - m.mass * dot(centroidFromApex, centroidFromApex);
    return m;
}

// A rounded polygon is its core polygon, plus a rectangle radius r deep outside each edge, plus
// a sector of radius r at each corner (the corners' sectors turn through the exterior angles,
// which sum to a whole turn). Each piece's area, first and second moments about the frame's
// origin are exact and summed in double precision: with y measured from a piece's own corner
// a, the moments about the origin are area |a|^2 + 2 a . S1 + S2, where S1 = integral of y and
// S2 = integral of |y|^2 over the piece.
//   rectangle on edge a -> b (length L, outward normal n): area L r,
//       S1 = L r (b - a) / 2 + L r^2 n / 2,   S2 = L (L^2 r + r^3) / 3;
//   sector at corner a turning theta from normal n1 to n2: area theta r^2 / 2,
//       S1 = 2/3 r^3 sin(theta/2) u (u the unit bisector of n1 and n2),   S2 = theta r^4 / 4.
OriginMass roundedPolygonMassAboutOrigin(const ConvexPolygon& polygon, float density) {
    const OriginMass core = polygonMassAboutOrigin(polygon.vertices.data(), polygon.count, 1.0f);
    const double r = polygon.radius;
    double area = core.mass;  // density 1: the core's area
    double mx = double(core.mass) * core.center.x;
    double my = double(core.mass) * core.center.y;
    double second = core.inertia;
    auto addPiece = [&](Vec2 corner, double pieceArea, double s1x, double s1y, double s2) {
        const double ax = corner.x, ay = corner.y;
        area += pieceArea;
        mx += pieceArea * ax + s1x;
        my += pieceArea * ay + s1y;
        second += pieceArea * (ax * ax + ay * ay) + 2.0 * (ax * s1x + ay * s1y) + s2;
    };
    const int n = polygon.count;
    for (int i = 0; i < n; ++i) {
        const Vec2 a = polygon.vertices[i];
        const Vec2 b = polygon.vertices[(i + 1) % n];
        const Vec2 normal = polygon.normals[i];
        const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
        const double L = std::sqrt(ex * ex + ey * ey);
        addPiece(a, L * r, 0.5 * L * r * ex + 0.5 * L * r * r * normal.x,
                 0.5 * L * r * ey + 0.5 * L * r * r * normal.y, L * (L * L * r + r * r * r) / 3.0);
        const Vec2 before = polygon.normals[(i + n - 1) % n];
        const double theta = std::atan2(double(cross(before, normal)), double(dot(before, normal)));
        double ux = double(before.x) + normal.x, uy = double(before.y) + normal.y;
        const double u = std::sqrt(ux * ux + uy * uy);
        ux /= u;
        uy /= u;
        const double arm = 2.0 / 3.0 * r * r * r * std::sin(0.5 * theta);
        addPiece(a, 0.5 * theta * r * r, arm * ux, arm * uy, 0.25 * theta * r * r * r * r);
    }
    OriginMass m;
    m.mass = static_cast<float>(density * area);
    m.center = {static_cast<float>(mx / area), static_cast<float>(my / area)};
    m.inertia = static_cast<float>(density * second);
    const double cx = mx / area, cy = my / area;
    m.centroidInertia = static_cast<float>(density * (second - area * (cx * cx + cy * cy)));
    return m;
}

// A capsule of core length L and radius r: a rectangle L x 2r and two half discs. In double,
// about the core's midpoint c:
//   mass  m = rho (2 r L + pi r^2),
//   I_c = rho [2 r L (L^2 + 4 r^2) / 12                      (the rectangle)
//             + pi r^2 (r^2 / 2 - d^2) + pi r^2 (L/2 + d)^2]  (the half discs, d = 4 r / (3 pi)
//                                                              their centroids past the ends)
// and about the origin I = I_c + m |c|^2.
OriginMass capsuleMassAboutOrigin(const ConvexPolygon& capsule, float density) {
    const Vec2 a = capsule.vertices[0], b = capsule.vertices[1];
    const double r = capsule.radius;
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    const double L = std::sqrt(ex * ex + ey * ey);
    const double cx = 0.5 * (double(a.x) + b.x), cy = 0.5 * (double(a.y) + b.y);
    const double rectangle = 2.0 * r * L;
    const double discs = kPi * r * r;  // the two halves together
    const double d = 4.0 * r / (3.0 * kPi);
    const double unitCentroidInertia = rectangle * (L * L + 4.0 * r * r) / 12.0 +
                                       discs * (0.5 * r * r - d * d) +
                                       discs * (0.5 * L + d) * (0.5 * L + d);
    const double mass = density * (rectangle + discs);
    OriginMass m;
    m.mass = static_cast<float>(mass);
    m.center = {static_cast<float>(cx), static_cast<float>(cy)};
    m.centroidInertia = static_cast<float>(density * unitCentroidInertia);
    m.inertia = static_cast<float>(density * unitCentroidInertia + mass * (cx * cx + cy * cy));
    return m;
}

OriginMass shapeMassAboutOrigin(const Shape& shape) {
    if (shape.type == ShapeType::Circle) return circleMassAboutOrigin(shape.circle, shape.density);
    if (isSegmentLike(shape.type)) {
        OriginMass m;  // no area, no mass (segments sit on static and kinematic bodies)
        m.center = 0.5f * (shape.polygon.vertices[0] + shape.polygon.vertices[1]);
        return m;
    }
    if (shape.type == ShapeType::Capsule)
        return capsuleMassAboutOrigin(shape.polygon, shape.density);
    if (shape.polygon.radius > 0.0f)
        return roundedPolygonMassAboutOrigin(shape.polygon, shape.density);
    return polygonMassAboutOrigin(shape.polygon.vertices.data(), shape.polygon.count,
                                  shape.density);
}

namespace {
MassData aboutCentroid(const OriginMass& m) {
    MassData md;
    md.mass = m.mass;
    md.center = m.center;
    md.rotationalInertia = m.centroidInertia;
    return md;
}
}  // namespace

MassData computeMass(const Circle& circle, float density) {
    const char* call = "computeMass";
    checkCircle(call, circle);
    requireDensity(call, "density", density);
    return aboutCentroid(circleMassAboutOrigin(circle, density));
}

MassData computeMass(const Polygon& polygon, float density) {
    const char* call = "computeMass";
    // The checked polygon is counter-clockwise whatever the input's winding, so area and mass
    // come out positive; its vertices are the input's, in the order the reference integrates.
    ConvexPolygon ccw;
    std::string problem = makeConvexPolygon(polygon, ccw);
    if (!problem.empty()) fail(call, problem);
    requireDensity(call, "density", density);
    if (ccw.radius > 0.0f) return aboutCentroid(roundedPolygonMassAboutOrigin(ccw, density));
    return aboutCentroid(polygonMassAboutOrigin(ccw.vertices.data(), ccw.count, density));
}

MassData computeMass(const Capsule& capsule, float density) {
    const char* call = "computeMass";
    ConvexPolygon checked;
    std::string problem = makeCapsulePolygon(capsule, checked);
    if (!problem.empty()) fail(call, problem);
    requireDensity(call, "density", density);
    return aboutCentroid(capsuleMassAboutOrigin(checked, density));
}

ShapeExtent shapeExtent(const Shape& shape, Vec2 localCenter) {
    if (shape.type == ShapeType::Circle) {
        return {shape.circle.radius,
                length(shape.circle.center - localCenter) + shape.circle.radius};
    }
    const ConvexPolygon& p = shape.polygon;
    const float radius = collisionRadius(shape);
    // A segment has no inside (min 0): any motion may carry it through something.
    float inner = isSegmentLike(shape.type) ? 0.0f : std::numeric_limits<float>::max();
    float outer = 0.0f;
    for (int i = 0; i < p.count; ++i) {
        if (!isSegmentLike(shape.type)) {
            inner = std::min(inner, dot(p.normals[i], p.vertices[i] - p.centroid));
        }
        outer = std::max(outer, length(p.vertices[i] - localCenter));
    }
    return {isSegmentLike(shape.type) ? 0.0f : inner + radius, outer + radius};
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
    const float radius = collisionRadius(shape);
    const Vec2 r{radius, radius};
    return {lower - r, upper + r};
}

DistanceProxy contactProxy(const Shape& shape) {
    DistanceProxy proxy;
    if (shape.type == ShapeType::Circle) {
        proxy.count = 1;
        proxy.vertices[0] = shape.circle.center;
    } else {
        proxy.count = shape.polygon.count;
        for (int i = 0; i < proxy.count; ++i) proxy.vertices[i] = shape.polygon.vertices[i];
    }
    proxy.radius = collisionRadius(shape);
    return proxy;
}

}  // namespace pivot
