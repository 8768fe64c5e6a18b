#include "collision/distance.h"

#include <cmath>

namespace pivot {

namespace {

// GJK converges in a handful of iterations on polygons of up to 8 vertices; the cap only stops
// a cycle that round-off could start.
constexpr int kMaxGjkIterations = 30;

struct SimplexVertex {
    Vec2 a;        // A's support point (world)
    Vec2 b;        // B's support point (world)
    Vec2 w;        // b - a
    float weight;  // barycentric weight of the closest point
    int indexA;
    int indexB;
};

struct Simplex {
    SimplexVertex v[3];
    int count = 0;
};

int furthestAlong(const DistanceProxy& proxy, const Transform& xf, Vec2 direction) {
    const Vec2 local = inverseRotate(xf.q, direction);
    int best = 0;
    float bestDot = dot(proxy.vertices[0], local);
    for (int i = 1; i < proxy.count; ++i) {
        const float d = dot(proxy.vertices[i], local);
        if (d > bestDot) {
            best = i;
            bestDot = d;
        }
    }
    return best;
}

SimplexVertex supportVertex(const DistanceProxy& a, const Transform& xfA, int indexA,
                            const DistanceProxy& b, const Transform& xfB, int indexB) {
    SimplexVertex s;
    s.indexA = indexA;
    s.indexB = indexB;
    s.a = transformPoint(xfA, a.vertices[indexA]);
    s.b = transformPoint(xfB, b.vertices[indexB]);
    s.w = s.b - s.a;
    s.weight = 1.0f;
    return s;
}

// Reduces the simplex to the smallest sub-simplex whose closest point to the origin is the
// whole simplex's, setting the weights. Returns false when the origin is inside the triangle.
bool reduce(Simplex& s) {
    if (s.count == 1) {
        s.v[0].weight = 1.0f;
        return true;
    }
    if (s.count == 2) {
        const Vec2 w1 = s.v[0].w, w2 = s.v[1].w;
        const Vec2 e = w2 - w1;
        const float t1 = -dot(w1, e);  // > 0: the origin lies past w1 towards w2
        if (t1 <= 0.0f) {
            s.count = 1;
            s.v[0].weight = 1.0f;
            return true;
        }
        const float t2 = dot(w2, e);  // > 0: the origin lies before w2
        if (t2 <= 0.0f) {
            s.v[0] = s.v[1];
            s.count = 1;
            s.v[0].weight = 1.0f;
            return true;
        }
        const float sum = t1 + t2;  // = e . e
        s.v[0].weight = t2 / sum;
        s.v[1].weight = t1 / sum;
        return true;
    }
    // A triangle: the origin's Voronoi region among its vertices, edges and face.
    const Vec2 w1 = s.v[0].w, w2 = s.v[1].w, w3 = s.v[2].w;
    const Vec2 e12 = w2 - w1, e13 = w3 - w1, e23 = w3 - w2;
    // Edge weights (unnormalised barycentric coordinates along each edge).
    const float d12_1 = dot(w2, e12), d12_2 = -dot(w1, e12);
    const float d13_1 = dot(w3, e13), d13_2 = -dot(w1, e13);
    const float d23_1 = dot(w3, e23), d23_2 = -dot(w2, e23);
    // Face weights: signed areas of the sub-triangles with the origin.
    const float area = cross(e12, e13);
    const float d123_1 = area * cross(w2, w3);
    const float d123_2 = area * cross(w3, w1);
    const float d123_3 = area * cross(w1, w2);

    if (d12_2 <= 0.0f && d13_2 <= 0.0f) {  // vertex 1
        s.count = 1;
        s.v[0].weight = 1.0f;
        return true;
    }
    if (d12_1 > 0.0f && d12_2 > 0.0f && d123_3 <= 0.0f) {  // edge 1-2
        const float sum = d12_1 + d12_2;
        s.v[0].weight = d12_1 / sum;
        s.v[1].weight = d12_2 / sum;
        s.count = 2;
        return true;
    }
    if (d13_1 > 0.0f && d13_2 > 0.0f && d123_2 <= 0.0f) {  // edge 1-3
        const float sum = d13_1 + d13_2;
        s.v[0].weight = d13_1 / sum;
        s.v[2].weight = d13_2 / sum;
        s.v[1] = s.v[2];
        s.count = 2;
        return true;
    }
    if (d12_1 <= 0.0f && d23_2 <= 0.0f) {  // vertex 2
        s.v[0] = s.v[1];
        s.v[0].weight = 1.0f;
        s.count = 1;
        return true;
    }
    if (d13_1 <= 0.0f && d23_1 <= 0.0f) {  // vertex 3
        s.v[0] = s.v[2];
        s.v[0].weight = 1.0f;
        s.count = 1;
        return true;
    }
    if (d23_1 > 0.0f && d23_2 > 0.0f && d123_1 <= 0.0f) {  // edge 2-3
        const float sum = d23_1 + d23_2;
        s.v[0] = s.v[2];  // keep the order (2, 3) as (v0 = 3's copy) / (v1 = 2)
        s.v[0].weight = d23_2 / sum;
        s.v[1].weight = d23_1 / sum;
        s.count = 2;
        return true;
    }
    // The face: the origin is inside the triangle.
    const float sum = d123_1 + d123_2 + d123_3;
    s.v[0].weight = d123_1 / sum;
    s.v[1].weight = d123_2 / sum;
    s.v[2].weight = d123_3 / sum;
    return false;
}

Vec2 closestPoint(const Simplex& s) {
    Vec2 p;
    for (int i = 0; i < s.count; ++i) p += s.v[i].weight * s.v[i].w;
    return p;
}

}  // namespace

DistanceResult shapeDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                             const Transform& xfB, bool useRadii) {
    DistanceResult result;
    Simplex s;
    s.v[0] = supportVertex(a, xfA, 0, b, xfB, 0);
    s.count = 1;
    bool inside = false;
    for (int it = 0; it < kMaxGjkIterations; ++it) {
        result.iterations = it + 1;
        if (!reduce(s)) {
            inside = true;
            break;
        }
        const Vec2 v = closestPoint(s);
        const float vv = dot(v, v);
        if (vv < 1e-12f) {  // the origin is on the simplex: the cores touch
            inside = true;
            break;
        }
        // The support point of B - A furthest along -v.
        const int indexA = furthestAlong(a, xfA, v);
        const int indexB = furthestAlong(b, xfB, -v);
        bool repeated = false;
        for (int i = 0; i < s.count; ++i) {
            repeated = repeated || (s.v[i].indexA == indexA && s.v[i].indexB == indexB);
        }
        const SimplexVertex next = supportVertex(a, xfA, indexA, b, xfB, indexB);
        // No closer along v than the simplex already is: v is the closest point.
        if (repeated || vv - dot(v, next.w) <= 1e-6f * vv) break;
        s.v[s.count++] = next;
    }

    Vec2 pA, pB;
    for (int i = 0; i < s.count; ++i) {
        pA += s.v[i].weight * s.v[i].a;
        pB += s.v[i].weight * s.v[i].b;
    }
    result.pointA = pA;
    result.pointB = pB;
    result.distance = inside ? 0.0f : length(pB - pA);
    result.overlap = inside;
    if (useRadii && !inside) {
        const float radii = a.radius + b.radius;
        if (result.distance > radii) {
            const Vec2 n = (1.0f / result.distance) * (pB - pA);
            result.distance -= radii;
            result.pointA = pA + a.radius * n;
            result.pointB = pB - b.radius * n;
        } else {
            const Vec2 mid = 0.5f * (pA + pB);
            result.pointA = mid;
            result.pointB = mid;
            result.distance = 0.0f;
            result.overlap = true;
        }
    } else if (useRadii) {
        result.overlap = true;
    }
    return result;
}

}  // namespace pivot
