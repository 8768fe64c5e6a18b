// What the face-clipping manifolds share (polygon against polygon, segment against polygon):
// the relative frame of two bodies, the clip vertex with its features, and the clip against one
// side plane. Their arithmetic is Box2D 2.4.1's, so that near-tie decisions and feature ids
// agree with that engine's.
#pragma once

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

}  // namespace pivot
