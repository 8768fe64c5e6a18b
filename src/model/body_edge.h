// Joints and contacts are each linked into both of their bodies' lists, so a body can find
// everything attached to it. An object's two list entries ("edges") are addressed by the key
// (index << 1) | side: side 0 belongs to the first body, side 1 to the second.
#pragma once

#include <cstdint>

#include "core/slot_pool.h"
#include "model/body.h"

namespace pivot {

struct BodyEdge {
    std::int32_t body = -1;
    std::int32_t prevKey = -1;
    std::int32_t nextKey = -1;
};

inline std::int32_t edgeKey(std::int32_t index, int side) {
    return (index << 1) | side;
}
inline std::int32_t edgeOwner(std::int32_t key) {
    return key >> 1;
}
inline int edgeSide(std::int32_t key) {
    return key & 1;
}

/// Pushes both edges of pool[index] onto the front of their bodies' lists (`head` selects the
/// list: Body::jointList or Body::contactList), so a body lists its newest attachment first.
template <typename T>
void linkEdges(SlotPool<T>& pool, SlotPool<Body>& bodies, std::int32_t Body::*head,
               std::int32_t index) {
    for (int side = 0; side < 2; ++side) {
        BodyEdge& edge = pool[index].edges[side];
        Body& body = bodies[edge.body];
        edge.prevKey = -1;
        edge.nextKey = body.*head;
        if (body.*head != -1)
            pool[edgeOwner(body.*head)].edges[edgeSide(body.*head)].prevKey = edgeKey(index, side);
        body.*head = edgeKey(index, side);
    }
}

/// Removes both edges of pool[index] from their bodies' lists.
template <typename T>
void unlinkEdges(SlotPool<T>& pool, SlotPool<Body>& bodies, std::int32_t Body::*head,
                 std::int32_t index) {
    for (int side = 0; side < 2; ++side) {
        const BodyEdge edge = pool[index].edges[side];
        if (edge.prevKey != -1) {
            pool[edgeOwner(edge.prevKey)].edges[edgeSide(edge.prevKey)].nextKey = edge.nextKey;
        } else {
            bodies[edge.body].*head = edge.nextKey;
        }
        if (edge.nextKey != -1) {
            pool[edgeOwner(edge.nextKey)].edges[edgeSide(edge.nextKey)].prevKey = edge.prevKey;
        }
    }
}

}  // namespace pivot
