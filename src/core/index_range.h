// A share of an array: elements [begin, end); a batch of constraints, and how its blocks are cut.
#pragma once

#include <cstdint>

namespace pivot {

struct IndexRange {
    int begin = 0;
    int end = 0;
};

/// Constraints [begin, end) of one array that may be solved in any order, or, if serial, only
/// in order (by one member).
struct Batch {
    std::int32_t begin = 0;
    std::int32_t end = 0;
    bool serial = true;
};

/// Where share `part` of `parts` starts when `count` items are dealt into that many shares in
/// order, as evenly as they go (share `parts` starts at `count`).
inline int shareStart(int count, int part, int parts) {
    return static_cast<int>(std::int64_t{count} * part / parts);
}

/// A batch of independent constraints is cut into blocks at multiples of this from its start
/// (islands/team.h), so that a solver working on several constraints at a time finds its runs
/// where it laid them out (constraints/contact_tiles.h), whatever the number of workers.
constexpr int kBatchAlignment = 8;

}  // namespace pivot
