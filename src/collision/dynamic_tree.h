// A dynamic AABB tree: a balanced binary tree of fattened boxes, one leaf ("proxy") per shape.
// Leaves are inserted where they grow the tree's total perimeter least and the tree is kept
// balanced by rotations, so queries cost O(log n) and moving a proxy is cheap when its box
// stays inside its fattened box.
#pragma once

#include <cstdint>
#include <vector>

#include "collision/aabb.h"

namespace pivot {

class DynamicTree {
public:
    /// Adds a leaf for `tightBox`, stored fattened by kAabbMargin. Returns the proxy id.
    std::int32_t createProxy(const AABB& tightBox, std::int32_t userData);
    void destroyProxy(std::int32_t proxyId);
    /// Updates a proxy whose shape now has `tightBox` and moved by `displacement` this step.
    /// Does nothing and returns false while the stored fat box still contains `tightBox`;
    /// otherwise re-inserts the leaf with a box fattened by kAabbMargin and stretched by
    /// kAabbMotionFactor * displacement, and returns true.
    bool moveProxy(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement);

    const AABB& fatBox(std::int32_t proxyId) const;
    std::int32_t userData(std::int32_t proxyId) const;

    /// Calls `visit(proxyId)` for every proxy whose fat box overlaps `box`; `visit` returns
    /// false to stop the query early.
    template <typename Visit>
    void query(const AABB& box, Visit&& visit) const;

    int proxyCount() const;
    /// Height of the tree (0 for a single leaf, -1 when empty).
    int height() const;
    /// Checks every structural invariant (parents, heights, boxes enclosing children, free
    /// list); returns false at the first violation. For tests.
    bool isValid() const;

private:
    // (implementation detail: node pool, free list, root, insertion, removal, balancing)
};

}  // namespace pivot
