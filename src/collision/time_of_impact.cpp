#include "collision/time_of_impact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pivot {

namespace {

constexpr int kMaxAxisIterations = 20;  // separating axes tried before giving up
constexpr int kMaxRootIterations = 50;
constexpr float kTouchTolerance = 0.25f * kLinearSlop;

// Scales v to unit length and returns its length; leaves a vector shorter than float epsilon
// as it is and returns 0.
float normalizeInPlace(Vec2& v) {
    const float len = length(v);
    if (len < std::numeric_limits<float>::epsilon()) return 0.0f;
    const float inverse = 1.0f / len;
    v.x *= inverse;
    v.y *= inverse;
    return len;
}

// The separation of A and B along one axis, as a function of time: the axis is either the line
// between a point of each (Points), or the normal of a face of A (FaceA) or B (FaceB) through
// that face's midpoint, turning with its body.
class SeparatingAxis {
public:
    SeparatingAxis(const SimplexCache& cache, const DistanceProxy& a, const Sweep& sweepA,
                   const DistanceProxy& b, const Sweep& sweepB, float t)
        : a_(a), b_(b), sweepA_(sweepA), sweepB_(sweepB) {
        const Transform xfA = sweepA_.transformAt(t);
        const Transform xfB = sweepB_.transformAt(t);
        if (cache.count == 1) {
            kind_ = Kind::Points;
            axis_ = transformPoint(xfB, b_.vertices[cache.indexB[0]]) -
                    transformPoint(xfA, a_.vertices[cache.indexA[0]]);
            normalizeInPlace(axis_);
            return;
        }
        // An edge of the simplex: two vertices of one shape against one of the other.
        const bool faceOfB = cache.indexA[0] == cache.indexA[1];
        kind_ = faceOfB ? Kind::FaceB : Kind::FaceA;
        const DistanceProxy& faceShape = faceOfB ? b_ : a_;
        const auto& faceIndex = faceOfB ? cache.indexB : cache.indexA;
        const Transform& faceXf = faceOfB ? xfB : xfA;
        const Vec2 v1 = faceShape.vertices[faceIndex[0]];
        const Vec2 v2 = faceShape.vertices[faceIndex[1]];
        axis_ = cross(v2 - v1, 1.0f);
        normalizeInPlace(axis_);
        const Vec2 normal = rotate(faceXf.q, axis_);
        localPoint_ = 0.5f * (v1 + v2);
        const Vec2 facePoint = transformPoint(faceXf, localPoint_);
        const Vec2 otherPoint = faceOfB ? transformPoint(xfA, a_.vertices[cache.indexA[0]])
                                        : transformPoint(xfB, b_.vertices[cache.indexB[0]]);
        // The face's normal towards the other shape.
        if (dot(otherPoint - facePoint, normal) < 0.0f) axis_ = -axis_;
    }

    // The smallest separation along the axis at time t, and the vertices that have it
    // (-1 for the face's side).
    float deepest(int& indexA, int& indexB, float t) const {
        const Transform xfA = sweepA_.transformAt(t);
        const Transform xfB = sweepB_.transformAt(t);
        switch (kind_) {
            case Kind::Points:
                indexA = supportIndex(a_, inverseRotate(xfA.q, axis_));
                indexB = supportIndex(b_, inverseRotate(xfB.q, -axis_));
                break;
            case Kind::FaceA:
                indexA = -1;
                indexB = supportIndex(b_, inverseRotate(xfB.q, -rotate(xfA.q, axis_)));
                break;
            case Kind::FaceB:
                indexB = -1;
                indexA = supportIndex(a_, inverseRotate(xfA.q, -rotate(xfB.q, axis_)));
                break;
        }
        return separation(indexA, indexB, xfA, xfB);
    }

    // The separation of the given vertices along the axis at time t.
    float evaluate(int indexA, int indexB, float t) const {
        return separation(indexA, indexB, sweepA_.transformAt(t), sweepB_.transformAt(t));
    }

private:
    enum class Kind { Points, FaceA, FaceB };

    float separation(int indexA, int indexB, const Transform& xfA, const Transform& xfB) const {
        switch (kind_) {
            case Kind::Points: {
                const Vec2 pointA = transformPoint(xfA, a_.vertices[indexA]);
                const Vec2 pointB = transformPoint(xfB, b_.vertices[indexB]);
                return dot(pointB - pointA, axis_);
            }
            case Kind::FaceA: {
                const Vec2 normal = rotate(xfA.q, axis_);
                const Vec2 facePoint = transformPoint(xfA, localPoint_);
                const Vec2 pointB = transformPoint(xfB, b_.vertices[indexB]);
                return dot(pointB - facePoint, normal);
            }
            case Kind::FaceB:
            default: {
                const Vec2 normal = rotate(xfB.q, axis_);
                const Vec2 facePoint = transformPoint(xfB, localPoint_);
                const Vec2 pointA = transformPoint(xfA, a_.vertices[indexA]);
                return dot(pointA - facePoint, normal);
            }
        }
    }

    const DistanceProxy& a_;
    const DistanceProxy& b_;
    const Sweep& sweepA_;
    const Sweep& sweepB_;
    Kind kind_ = Kind::Points;
    Vec2 axis_;        // world direction (Points) or the face normal in its body's frame
    Vec2 localPoint_;  // the face's midpoint in its body's frame
};

}  // namespace

Transform Sweep::transformAt(float beta) const {
    Transform xf;
    xf.p = (1.0f - beta) * c0 + beta * c;
    const float angle = (1.0f - beta) * a0 + beta * a;
    xf.q = Rot(angle);
    xf.p -= rotate(xf.q, localCenter);
    return xf;
}

void Sweep::advance(float alpha) {
    const float beta = (alpha - alpha0) / (1.0f - alpha0);
    c0 += beta * (c - c0);
    a0 += beta * (a - a0);
    alpha0 = alpha;
}

void Sweep::normalizeAngles() {
    const float twoPi = 2.0f * kPi;
    const float turns = twoPi * std::floor(a0 / twoPi);
    a0 -= turns;
    a -= turns;
}

ImpactResult timeOfImpact(const DistanceProxy& a, const Sweep& sweepAIn, const DistanceProxy& b,
                          const Sweep& sweepBIn, float tMax) {
    Sweep sweepA = sweepAIn;
    Sweep sweepB = sweepBIn;
    sweepA.normalizeAngles();
    sweepB.normalizeAngles();

    const float target = std::max(kLinearSlop, a.radius + b.radius - 3.0f * kLinearSlop);
    const float tolerance = kTouchTolerance;

    float t1 = 0.0f;
    SimplexCache cache;
    for (int axisIteration = 1;; ++axisIteration) {
        const DistanceResult d =
            coreDistance(a, sweepA.transformAt(t1), b, sweepB.transformAt(t1), cache);
        if (d.distance <= 0.0f) return {ImpactState::Overlapped, 0.0f};
        if (d.distance < target + tolerance) return {ImpactState::Touching, t1};

        const SeparatingAxis axis(cache, a, sweepA, b, sweepB, t1);
        // Resolve the deepest point at t2, one vertex at a time: at most one per vertex.
        float t2 = tMax;
        for (int pushBack = 0; pushBack < kMaxPolygonVertices; ++pushBack) {
            int indexA = 0, indexB = 0;
            float s2 = axis.deepest(indexA, indexB, t2);
            if (s2 > target + tolerance) return {ImpactState::Separated, tMax};
            if (s2 > target - tolerance) {  // this axis is done: advance to t2
                t1 = t2;
                break;
            }
            float s1 = axis.evaluate(indexA, indexB, t1);
            // Already too deep at t1: the root finder must have run out of iterations.
            if (s1 < target - tolerance) return {ImpactState::Failed, t1};
            if (s1 <= target + tolerance) return {ImpactState::Touching, t1};

            // The root of s(t) = target in [a1, a2], where s(a1) > target > s(a2).
            float a1 = t1, a2 = t2;
            for (int root = 0; root < kMaxRootIterations; ++root) {
                const float t =
                    (root & 1) ? a1 + (target - s1) * (a2 - a1) / (s2 - s1) : 0.5f * (a1 + a2);
                const float s = axis.evaluate(indexA, indexB, t);
                if (std::fabs(s - target) < tolerance) {
                    t2 = t;
                    break;
                }
                if (s > target) {
                    a1 = t;
                    s1 = s;
                } else {
                    a2 = t;
                    s2 = s;
                }
            }
        }
        if (axisIteration == kMaxAxisIterations) return {ImpactState::Failed, t1};
    }
}

}  // namespace pivot
