// Box2D 2.4.1's vectors, transforms and shapes copied into pivot2d's types bit for bit, for the
// reference tests that feed both engines the same input.
#pragma once

#include <box2d/box2d.h>

#include "collision/geometry.h"
#include "pivot/math.h"
#include "pivot/shape.h"

namespace pivot::reference {

inline Vec2 toPivot(b2Vec2 v) {
    return {v.x, v.y};
}

inline Transform toPivot(const b2Transform& xf) {
    Transform t;
    t.p = toPivot(xf.p);
    t.q.s = xf.q.s;
    t.q.c = xf.q.c;
    return t;
}

/// Taken from the b2PolygonShape after SetAsBox or Set (whose hull may reorder the points), so
/// vertex and face indices mean the same polygon features in both engines.
inline ConvexPolygon toPivot(const b2PolygonShape& shape) {
    ConvexPolygon p;
    p.count = shape.m_count;
    for (int i = 0; i < shape.m_count; ++i) {
        p.vertices[i] = toPivot(shape.m_vertices[i]);
        p.normals[i] = toPivot(shape.m_normals[i]);
    }
    p.centroid = toPivot(shape.m_centroid);
    return p;
}

inline Circle toPivot(const b2CircleShape& shape) {
    return Circle{toPivot(shape.m_p), shape.m_radius};
}

}  // namespace pivot::reference
