#include "model/shape.h"

#include <algorithm>
#include <cmath>

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

OriginMass shapeMassAboutOrigin(const Shape& shape) {
    if (shape.type == ShapeType::Circle) return circleMassAboutOrigin(shape.circle, shape.density);
    if (shape.type == ShapeType::Segment) {
        OriginMass m;  // no area, no mass (segments sit on static and kinematic bodies)
        m.center = 0.5f * (shape.polygon.vertices[0] + shape.polygon.vertices[1]);
        return m;
    }
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
    return aboutCentroid(polygonMassAboutOrigin(ccw.vertices.data(), ccw.count, density));
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
