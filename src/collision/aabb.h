// Axis-aligned bounding boxes (AABB itself is public: pivot/math.h).
#pragma once

#include <algorithm>

#include "pivot/math.h"

namespace pivot {

inline bool overlaps(const AABB& a, const AABB& b) {
    return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x ||
             a.lower.y > b.upper.y);
}

/// Whether `outer` contains `inner` entirely.
inline bool contains(const AABB& outer, const AABB& inner) {
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y &&
           inner.upper.x <= outer.upper.x && inner.upper.y <= outer.upper.y;
}

/// Whether `box` contains the point `p`.
inline bool contains(const AABB& box, Vec2 p) {
    return box.lower.x <= p.x && box.lower.y <= p.y && p.x <= box.upper.x && p.y <= box.upper.y;
}

inline AABB combine(const AABB& a, const AABB& b) {
    return {{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)},
            {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)}};
}

/// The cost measure of the tree's surface-area heuristic (in 2D, the perimeter).
inline float perimeter(const AABB& a) {
    return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y));
}

}  // namespace pivot
