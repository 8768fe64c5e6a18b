// What the manifold routines share (polygon against polygon, segment against polygon, capsule
// against capsule): the relative frame of two bodies, the clip vertex with its features, the clip
// against one side plane, and the closest points of two segments. The first three do Box2D
// 2.4.1's arithmetic, so that near-tie decisions and feature ids agree with that engine's.
#pragma once

#include <cmath>
#include <cstdint>

#include "collision/manifold.h"

namespace pivot {

// The frame `to` as seen from the frame `from`: maps `to`-local points into `from`-local ones.
// Written as one composed transform (rather than two transforms per point) so that the
// arithmetic, and with it every near-tie decision, is that of the reference engine.
inline Transform relativeTransform(const Transform& from, const Transform& to) {
    Transform t;
    t.q.s = from.q.c * to.q.s - from.q.s * to.q.c;
    t.q.c = from.q.c * to.q.c + from.q.s * to.q.s;
    t.p = inverseRotate(from.q, to.p - from.p);
    return t;
}

// A point of the incident edge during clipping, with the features that made it: the
// reference shape's face or vertex, and the incident shape's vertex or face (the first and
// second halves of the feature id before the caller orders them as shape A's and B's).
struct ClipVertex {
    Vec2 point;
    std::uint8_t referenceIndex = 0;
    std::uint8_t incidentIndex = 0;
    FeatureType referenceType = FeatureType::Face;
    FeatureType incidentType = FeatureType::Vertex;
};

// Keeps the part of segment `in` behind the plane dot(normal, x) = offset (Sutherland-Hodgman
// for one plane). A point made by the cut is where reference vertex `referenceVertex` meets the
// incident face; the incident index is taken from in[0], whatever in[0] is, which is what the
// reference does and what makes the ids agree. Returns the number of points written.
inline int clipSegmentToLine(ClipVertex out[2], const ClipVertex in[2], Vec2 normal, float offset,
                             int referenceVertex) {
    int count = 0;
    const float distance0 = dot(normal, in[0].point) - offset;
    const float distance1 = dot(normal, in[1].point) - offset;
    if (distance0 <= 0.0f) out[count++] = in[0];
    if (distance1 <= 0.0f) out[count++] = in[1];
    if (distance0 * distance1 < 0.0f) {
        const float t = distance0 / (distance0 - distance1);
        out[count] = {in[0].point + t * (in[1].point - in[0].point),
                      static_cast<std::uint8_t>(referenceVertex), in[0].incidentIndex,
                      FeatureType::Vertex, FeatureType::Face};
        ++count;
    }
    return count;
}

// The closest points of the segments p1-q1 and p2-q2, as the fractions s along the first and t
// along the second (each in [0, 1]).
inline void closestFractions(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2, float& s, float& t) {
    const Vec2 d1 = q1 - p1;
    const Vec2 d2 = q2 - p2;
    const Vec2 r = p1 - p2;
    const float a = dot(d1, d1);
    const float e = dot(d2, d2);
    const float f = dot(d2, r);
    const float c = dot(d1, r);
    const float b = dot(d1, d2);
    const float denominator = a * e - b * b;
    auto unit = [](float x) { return std::fmin(std::fmax(x, 0.0f), 1.0f); };
    // Parallel segments (denominator 0): any point of the first will do; take its start.
    s = denominator > 0.0f ? unit((b * f - c * e) / denominator) : 0.0f;
    t = (b * s + f) / e;
    if (t < 0.0f) {
        t = 0.0f;
        s = unit(-c / a);
    } else if (t > 1.0f) {
        t = 1.0f;
        s = unit((b - c) / a);
    }
}

}  // namespace pivot
