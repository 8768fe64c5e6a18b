#include "collision/distance.h"

#include <cmath>
#include <limits>

namespace pivot {

namespace {

// Each iteration computes one support point; GJK needs a handful on polygons of up to 8
// vertices. The cap (Box2D 2.4.1's) only stops a cycle that round-off could start.
constexpr int kMaxGjkIterations = 20;
constexpr float kEpsilon = std::numeric_limits<float>::epsilon();

struct SimplexVertex {
    Vec2 a;               // A's support point (world)
    Vec2 b;               // B's support point (world)
    Vec2 w;               // b - a
    float weight = 0.0f;  // barycentric weight of the closest point
    int indexA = 0;
    int indexB = 0;
};

struct Simplex {
    SimplexVertex v[3];
    int count = 0;

    // The size the cache remembers: 0 for a point, an edge's length, a triangle's area.
    float metric() const {
        if (count == 2) return distance(v[0].w, v[1].w);
        if (count == 3) return cross(v[1].w - v[0].w, v[2].w - v[0].w);
        return 0.0f;
    }
};

SimplexVertex supportVertex(const DistanceProxy& a, const Transform& xfA, int indexA,
                            const DistanceProxy& b, const Transform& xfB, int indexB) {
    SimplexVertex s;
    s.indexA = indexA;
    s.indexB = indexB;
    s.a = transformPoint(xfA, a.vertices[indexA]);
    s.b = transformPoint(xfB, b.vertices[indexB]);
    s.w = s.b - s.a;
    return s;
}

// The cached simplex at the new poses, unless it has grown or shrunk by more than a factor of
// two (or collapsed): then the poses moved too far for it to be a good start, and the search
// starts from the first vertices.
Simplex startFrom(const SimplexCache& cache, const DistanceProxy& a, const Transform& xfA,
                  const DistanceProxy& b, const Transform& xfB) {
    Simplex s;
    s.count = cache.count;
    for (int i = 0; i < s.count; ++i) {
        s.v[i] = supportVertex(a, xfA, cache.indexA[i], b, xfB, cache.indexB[i]);
    }
    if (s.count > 1) {
        const float before = cache.metric;
        const float now = s.metric();
        if (now < 0.5f * before || 2.0f * before < now || now < kEpsilon) s.count = 0;
    }
    if (s.count == 0) {
        s.v[0] = supportVertex(a, xfA, 0, b, xfB, 0);
        s.v[0].weight = 1.0f;
        s.count = 1;
    }
    return s;
}

// The closest point of an edge w1-w2 to the origin: an end (the simplex shrinks to it) or the
// interior, with barycentric weights from the origin's projection.
void reduceEdge(Simplex& s) {
    const Vec2 w1 = s.v[0].w;
    const Vec2 w2 = s.v[1].w;
    const Vec2 e12 = w2 - w1;
    const float beforeW1 = -dot(w1, e12);  // <= 0: the origin projects before w1
    if (beforeW1 <= 0.0f) {
        s.v[0].weight = 1.0f;
        s.count = 1;
        return;
    }
    const float beforeW2 = dot(w2, e12);  // <= 0: past w2
    if (beforeW2 <= 0.0f) {
        s.v[1].weight = 1.0f;
        s.count = 1;
        s.v[0] = s.v[1];
        return;
    }
    const float inverse = 1.0f / (beforeW2 + beforeW1);
    s.v[0].weight = beforeW2 * inverse;
    s.v[1].weight = beforeW1 * inverse;
    s.count = 2;
}

// The closest point of a triangle to the origin: which of its vertices, edges or its inside
// holds the origin's Voronoi region, from the edges' projections and the signed areas of the
// sub-triangles the origin makes with each edge.
void reduceTriangle(Simplex& s) {
    const Vec2 w1 = s.v[0].w;
    const Vec2 w2 = s.v[1].w;
    const Vec2 w3 = s.v[2].w;

    const Vec2 e12 = w2 - w1;
    const float d12_1 = dot(w2, e12);
    const float d12_2 = -dot(w1, e12);
    const Vec2 e13 = w3 - w1;
    const float d13_1 = dot(w3, e13);
    const float d13_2 = -dot(w1, e13);
    const Vec2 e23 = w3 - w2;
    const float d23_1 = dot(w3, e23);
    const float d23_2 = -dot(w2, e23);

    const float n123 = cross(e12, e13);
    const float d123_1 = n123 * cross(w2, w3);
    const float d123_2 = n123 * cross(w3, w1);
    const float d123_3 = n123 * cross(w1, w2);

    if (d12_2 <= 0.0f && d13_2 <= 0.0f) {  // vertex 1
        s.v[0].weight = 1.0f;
        s.count = 1;
        return;
    }
    if (d12_1 > 0.0f && d12_2 > 0.0f && d123_3 <= 0.0f) {  // edge 1-2
        const float inverse = 1.0f / (d12_1 + d12_2);
        s.v[0].weight = d12_1 * inverse;
        s.v[1].weight = d12_2 * inverse;
        s.count = 2;
        return;
    }
    if (d13_1 > 0.0f && d13_2 > 0.0f && d123_2 <= 0.0f) {  // edge 1-3
        const float inverse = 1.0f / (d13_1 + d13_2);
        s.v[0].weight = d13_1 * inverse;
        s.v[2].weight = d13_2 * inverse;
        s.count = 2;
        s.v[1] = s.v[2];
        return;
    }
    if (d12_1 <= 0.0f && d23_2 <= 0.0f) {  // vertex 2
        s.v[1].weight = 1.0f;
        s.count = 1;
        s.v[0] = s.v[1];
        return;
    }
    if (d13_1 <= 0.0f && d23_1 <= 0.0f) {  // vertex 3
        s.v[2].weight = 1.0f;
        s.count = 1;
        s.v[0] = s.v[2];
        return;
    }
    if (d23_1 > 0.0f && d23_2 > 0.0f && d123_1 <= 0.0f) {  // edge 2-3, kept as (3, 2)
        const float inverse = 1.0f / (d23_1 + d23_2);
        s.v[1].weight = d23_1 * inverse;
        s.v[2].weight = d23_2 * inverse;
        s.count = 2;
        s.v[0] = s.v[2];
        return;
    }
    // The origin is inside.
    const float inverse = 1.0f / (d123_1 + d123_2 + d123_3);
    s.v[0].weight = d123_1 * inverse;
    s.v[1].weight = d123_2 * inverse;
    s.v[2].weight = d123_3 * inverse;
    s.count = 3;
}

// Towards the origin from the simplex: from a point, straight at it; from an edge, along the
// edge's normal on the origin's side (exact where -closest point would be round-off).
Vec2 searchDirection(const Simplex& s) {
    if (s.count == 1) return -s.v[0].w;
    const Vec2 e12 = s.v[1].w - s.v[0].w;
    const float side = cross(e12, -s.v[0].w);
    return side > 0.0f ? cross(1.0f, e12) : cross(e12, 1.0f);
}

void witnessPoints(const Simplex& s, Vec2& pointA, Vec2& pointB) {
    switch (s.count) {
        case 1:
            pointA = s.v[0].a;
            pointB = s.v[0].b;
            break;
        case 2:
            pointA = s.v[0].weight * s.v[0].a + s.v[1].weight * s.v[1].a;
            pointB = s.v[0].weight * s.v[0].b + s.v[1].weight * s.v[1].b;
            break;
        default:
            pointA = s.v[0].weight * s.v[0].a + s.v[1].weight * s.v[1].a + s.v[2].weight * s.v[2].a;
            pointB = pointA;
            break;
    }
}

}  // namespace

int supportIndex(const DistanceProxy& proxy, Vec2 direction) {
    int best = 0;
    float bestDot = dot(proxy.vertices[0], direction);
    for (int i = 1; i < proxy.count; ++i) {
        const float d = dot(proxy.vertices[i], direction);
        if (d > bestDot) {
            best = i;
            bestDot = d;
        }
    }
    return best;
}

DistanceResult coreDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                            const Transform& xfB, SimplexCache& cache) {
    Simplex s = startFrom(cache, a, xfA, b, xfB);
    bool overlap = false;
    int iterations = 0;
    while (iterations < kMaxGjkIterations) {
        // The support points of the simplex before it is reduced: a new point among them means
        // the search cycles.
        const int previousCount = s.count;
        int previousA[3], previousB[3];
        for (int i = 0; i < previousCount; ++i) {
            previousA[i] = s.v[i].indexA;
            previousB[i] = s.v[i].indexB;
        }
        if (s.count == 2) reduceEdge(s);
        if (s.count == 3) reduceTriangle(s);
        if (s.count == 3) {
            overlap = true;
            break;
        }
        const Vec2 d = searchDirection(s);
        if (lengthSquared(d) < kEpsilon * kEpsilon) {  // the origin is on the simplex
            overlap = true;
            break;
        }
        const int indexA = supportIndex(a, inverseRotate(xfA.q, -d));
        const int indexB = supportIndex(b, inverseRotate(xfB.q, d));
        s.v[s.count] = supportVertex(a, xfA, indexA, b, xfB, indexB);
        ++iterations;
        bool repeated = false;
        for (int i = 0; i < previousCount; ++i) {
            if (indexA == previousA[i] && indexB == previousB[i]) {
                repeated = true;
                break;
            }
        }
        if (repeated) break;
        ++s.count;
    }

    DistanceResult result;
    witnessPoints(s, result.pointA, result.pointB);
    result.distance = distance(result.pointA, result.pointB);
    result.overlap = overlap;
    result.iterations = iterations;

    cache.metric = s.metric();
    cache.count = s.count;
    for (int i = 0; i < s.count; ++i) {
        cache.indexA[i] = static_cast<std::uint8_t>(s.v[i].indexA);
        cache.indexB[i] = static_cast<std::uint8_t>(s.v[i].indexB);
    }
    return result;
}

DistanceResult shapeDistance(const DistanceProxy& a, const Transform& xfA, const DistanceProxy& b,
                             const Transform& xfB, bool useRadii) {
    SimplexCache cache;
    DistanceResult result = coreDistance(a, xfA, b, xfB, cache);
    if (result.overlap) result.distance = 0.0f;
    if (!useRadii) return result;
    const float radii = a.radius + b.radius;
    if (!result.overlap && result.distance > radii) {
        const Vec2 n = (1.0f / result.distance) * (result.pointB - result.pointA);
        result.distance -= radii;
        result.pointA += a.radius * n;
        result.pointB -= b.radius * n;
    } else {
        const Vec2 mid = 0.5f * (result.pointA + result.pointB);
        result.pointA = mid;
        result.pointB = mid;
        result.distance = 0.0f;
        result.overlap = true;
    }
    return result;
}

}  // namespace pivot
