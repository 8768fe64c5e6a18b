// Growing the step's reusable buffers so that a warm step does not allocate.
//
// The step reuses its arrays from one step to the next, so it allocates only when one must hold
// more than ever before. Two habits keep that from happening over and over:
//  - resizeBuffer grows capacity at least twofold. std::vector::resize grows from the current
//    size, not the capacity: an array last used for a small island and resized for a slightly
//    larger one than ever would get exactly that size, and allocate again at the next record;
//  - arrays bounded by a count of objects are reserved for it, rounded up to a power of two:
//    the island set for the world's pool capacities, and the solver's workspaces for the totals
//    of this step's islands (World::Impl::reserveStepBuffers, reserveWorkspaces). So while the
//    world holds no more awake bodies and touching contacts than it ever did, islands may
//    merge, split and churn freely, and a record reserves again only when it has doubled.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pivot {

/// What to reserve for `needed` objects where `reserved` are reserved already: unchanged while
/// they fit, else `needed` rounded up to a power of two (16 at least), so a count that grows one
/// at a time reserves again only when it has doubled.
inline std::size_t withRoom(std::size_t reserved, std::size_t needed) {
    if (needed <= reserved) return reserved;
    std::size_t rounded = 16;
    while (rounded < needed) rounded *= 2;
    return rounded;
}

/// Reserves room for `count` elements by withRoom.
template <typename T>
void reserveBuffer(std::vector<T>& buffer, std::size_t count) {
    if (count > buffer.capacity()) buffer.reserve(withRoom(buffer.capacity(), count));
}

template <typename T>
void resizeBuffer(std::vector<T>& buffer, std::size_t size) {
    if (size > buffer.capacity()) buffer.reserve(std::max(size, 2 * buffer.capacity()));
    buffer.resize(size);
}
/// Makes `buffer` hold at least `size` elements, never fewer than before: for an array reused
/// by objects of varying sizes (one island after another) whose owner keeps its own count and
/// writes every element it uses. resizeBuffer value-initialises every element it adds, so an
/// array resized down for one island and up for the next zeroed the difference each time, for
/// elements about to be overwritten (2% of `smash`'s step, 9,000 islands a step).
template <typename T>
void growBuffer(std::vector<T>& buffer, std::size_t size) {
    if (size > buffer.size()) resizeBuffer(buffer, size);
}
template <typename T>
void resizeBuffer(std::vector<T>& buffer, std::size_t size, const T& value) {
    if (size > buffer.capacity()) buffer.reserve(std::max(size, 2 * buffer.capacity()));
    buffer.resize(size, value);
}

/// The most objects an island or a step can involve, from the world's pool capacities.
struct BufferBounds {
    std::size_t bodies = 0;
    std::size_t joints = 0;
    std::size_t contacts = 0;
    std::size_t mouseJoints = 0;

    friend bool operator==(const BufferBounds& a, const BufferBounds& b) {
        return a.bodies == b.bodies && a.joints == b.joints && a.contacts == b.contacts &&
               a.mouseJoints == b.mouseJoints;
    }
    friend bool operator!=(const BufferBounds& a, const BufferBounds& b) { return !(a == b); }
};

}  // namespace pivot
