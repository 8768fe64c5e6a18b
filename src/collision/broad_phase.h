// The broad phase: which shapes might touch. Keeps a DynamicTree of every shape's fat box and a
// buffer of proxies that moved (or were created) since the last update; updatePairs reports
// each overlapping pair that involves at least one of them.
#pragma once

#include <cstdint>
#include <vector>

#include "collision/dynamic_tree.h"

namespace pivot {

class BroadPhase {
public:
    std::int32_t createProxy(const AABB& tightBox, std::int32_t userData);
    void destroyProxy(std::int32_t proxyId);
    /// See DynamicTree::moveProxy; a proxy the tree re-inserted is buffered for updatePairs.
    void moveProxy(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement);
    /// Buffers a proxy so its pairs are reported again at the next updatePairs (for example
    /// after its filter changed).
    void touchProxy(std::int32_t proxyId);

    bool testOverlap(std::int32_t proxyA, std::int32_t proxyB) const;
    const AABB& fatBox(std::int32_t proxyId) const;
    std::int32_t userData(std::int32_t proxyId) const;
    const DynamicTree& tree() const;

    /// Calls addPair(userDataA, userDataB) once for every pair of distinct proxies whose fat
    /// boxes overlap and at least one of which was buffered since the last call, then clears
    /// the buffer. Pairs are reported in a deterministic order (sorted by proxy ids), each
    /// with the smaller proxy id's user data first. It does not know which pairs already have
    /// contacts: the caller ignores pairs it already has.
    template <typename AddPair>
    void updatePairs(AddPair&& addPair);
};

}  // namespace pivot
