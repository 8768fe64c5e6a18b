// A contact: two shapes whose broad-phase boxes overlap. It exists from the moment the boxes
// first overlap until they part; it is "touching" while its manifold has points. Only touching
// contacts join islands and reach the contact solver.
#pragma once

#include <cmath>
#include <cstdint>

#include "collision/manifold.h"
#include "model/body_edge.h"
#include "model/shape.h"
#include "pivot/shape.h"

namespace pivot {

struct Contact {
    BodyEdge edges[2];  // edges[0].body owns shapeA, edges[1].body owns shapeB
    std::int32_t shapeA = -1;
    std::int32_t shapeB = -1;
    Manifold manifold;
    float friction = 0.0f;  // mixed from the two shapes when the contact is made
    float restitution = 0.0f;
    // The shapes' collision radii (collisionRadius): a shape's geometry never changes, so they
    // are copied here when the contact is made, and the solver's build reads no shape.
    float radiusA = 0.0f;
    float radiusB = 0.0f;
    bool touching = false;
    bool needsFiltering = false;  // re-check the filter before the next update
    // A sensor overlap (one shape is a sensor): "touching" means overlapping; it never reaches
    // islands, the solver or continuous collision, and reports sensor events.
    bool sensor = false;
    // The pre-solve callback's answer for this step (World::setPreSolveCallback): a disabled
    // contact touches but is left out of islands, the solver and continuous collision.
    bool enabled = true;

    // The order contacts were made in: the island search's and continuous collision's
    // (the newest wins a tie between times of impact).
    std::uint64_t serial = 0;

    std::int32_t bodyA() const { return edges[0].body; }
    std::int32_t bodyB() const { return edges[1].body; }
};

/// Friction mixing: the geometric mean, so a frictionless shape makes a frictionless contact.
inline float mixFriction(float a, float b) {
    return std::sqrt(a * b);
}
/// Restitution mixing: the bouncier shape wins.
inline float mixRestitution(float a, float b) {
    return a > b ? a : b;
}

/// The filter rule of pivot::Filter.
inline bool filtersAllowContact(const Filter& a, const Filter& b) {
    if (a.groupIndex == b.groupIndex && a.groupIndex != 0) return a.groupIndex > 0;
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

/// Recomputes the manifold at the given transforms and carries each point's impulses over
/// from the previous manifold's point with the same feature id. Returns whether the contact
/// touches now.
bool updateContact(Contact& contact, const Shape& shapeA, const Transform& xfA, const Shape& shapeB,
                   const Transform& xfB);

}  // namespace pivot
