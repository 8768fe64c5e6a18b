// Mass properties by brute force, for the tests of rounded shapes: a rounded polygon (a capsule
// is one of two vertices) integrated over a fine grid, in double precision.
#pragma once

#include <cmath>

#include "pivot/pivot.h"

namespace pivot::testing {

// The distance from p to the polygon's core (0 inside), in double precision.
inline double coreDistance(const Polygon& polygon, double px, double py) {
    bool inside = true;
    double best = 1e300;
    // Counter-clockwise or not, inside means on the same side of every edge.
    double sign = 0.0;
    for (int i = 0; i < polygon.count; ++i) {
        const Vec2 a = polygon.vertices[i];
        const Vec2 b = polygon.vertices[(i + 1) % polygon.count];
        const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
        const double qx = px - a.x, qy = py - a.y;
        const double side = ex * qy - ey * qx;
        if (sign == 0.0) sign = side > 0.0 ? 1.0 : -1.0;
        if (side * sign < 0.0) inside = false;
        double t = (qx * ex + qy * ey) / (ex * ex + ey * ey);
        t = std::fmin(std::fmax(t, 0.0), 1.0);
        const double dx = qx - t * ex, dy = qy - t * ey;
        best = std::fmin(best, std::sqrt(dx * dx + dy * dy));
    }
    return inside ? 0.0 : best;
}

// Mass, centroid and inertia about the centroid of a rounded polygon of density 1 by
// integration over a fine grid.
inline MassData integrate(const Polygon& polygon) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int i = 0; i < polygon.count; ++i) {
        lo[0] = std::fmin(lo[0], polygon.vertices[i].x - polygon.radius);
        lo[1] = std::fmin(lo[1], polygon.vertices[i].y - polygon.radius);
        hi[0] = std::fmax(hi[0], polygon.vertices[i].x + polygon.radius);
        hi[1] = std::fmax(hi[1], polygon.vertices[i].y + polygon.radius);
    }
    const int n = 1500;
    const double hx = (hi[0] - lo[0]) / n, hy = (hi[1] - lo[1]) / n;
    double area = 0, mx = 0, my = 0, second = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double x = lo[0] + (i + 0.5) * hx, y = lo[1] + (j + 0.5) * hy;
            if (coreDistance(polygon, x, y) > polygon.radius) continue;
            const double dA = hx * hy;
            area += dA;
            mx += x * dA;
            my += y * dA;
            second += (x * x + y * y) * dA;
        }
    }
    MassData m;
    m.mass = static_cast<float>(area);
    const double cx = mx / area, cy = my / area;
    m.center = {static_cast<float>(cx), static_cast<float>(cy)};
    m.rotationalInertia = static_cast<float>(second - area * (cx * cx + cy * cy));
    return m;
}

}  // namespace pivot::testing
