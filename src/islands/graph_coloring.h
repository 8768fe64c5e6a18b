// Graph colouring of constraints: constraints of one colour share no movable body, so the
// members of a team can solve them at the same time without locks and still get the result a
// single thread would (each body is written by one constraint of the colour at most).
//
// Greedy first fit in the island's order: each constraint takes the lowest colour neither of
// its bodies has yet. Bodies that never move (static, kinematic) do not count: the solver
// gives every constraint its own copy of them (see island_schedule.h). A constraint that finds
// all kMaxColors taken goes to the overflow batch, solved by one member after the colours.
// First fit makes the first colours the biggest, which is what splits best.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "constraints/solver_body.h"
#include "core/buffer.h"
#include "islands/team.h"

namespace pivot {

class GraphColoring {
public:
    static constexpr int kMaxColors = 32;

    /// Colours items[0..count) (constraint numbers; pairs[item] are its solver bodies, two or
    /// more, kNoSlot for none; fixed[body] != 0 for bodies that never move). Appends the items to
    /// `order`, colour by colour and in their original order within a colour, and one batch per
    /// non-empty colour to `batches`, numbered from `base` (the position in the constraint array of
    /// the first item appended). Allocates only while its scratch grows.
    ///
    /// With `regions` (per item, below kRegions), each colour lists its items region by region
    /// (in their original order within a region); the overflow keeps its order, since it is
    /// solved in sequence. Constraints of one colour share no movable body, so their order
    /// within the colour changes no result: the regions only decide which member of a team
    /// solves which (Team deals a batch out in consecutive segments, member by member).
    static constexpr int kRegions = 16;
    template <typename Pairs>
    void color(const std::int32_t* items, int count, const Pairs& pairs, const std::uint8_t* fixed,
               int bodyCount, std::vector<std::int32_t>& order, std::vector<Batch>& batches,
               std::int32_t base, const std::uint8_t* regions = nullptr);

private:
    std::vector<std::uint64_t> masks_;  // per body: colours already used by its constraints
    std::vector<std::uint16_t> binOf_;  // per item
};

template <typename Pairs>
void GraphColoring::color(const std::int32_t* items, int count, const Pairs& pairs,
                          const std::uint8_t* fixed, int bodyCount,
                          std::vector<std::int32_t>& order, std::vector<Batch>& batches,
                          std::int32_t base, const std::uint8_t* regions) {
    constexpr std::uint64_t kAllColors = (std::uint64_t{1} << kMaxColors) - 1;
    if (masks_.size() < static_cast<std::size_t>(bodyCount)) {
        resizeBuffer(masks_, static_cast<std::size_t>(bodyCount), std::uint64_t{0});
    }
    resizeBuffer(binOf_, static_cast<std::size_t>(count));
    // Bin (colour, region): the bins in order make the colours' batches; the overflow's bin is
    // the last, whole.
    const int regionCount = regions ? kRegions : 1;
    const int overflowBin = kMaxColors * regionCount;
    std::int32_t next[kMaxColors * kRegions + 1];
    std::fill(next, next + overflowBin + 1, 0);
    std::int32_t sizes[kMaxColors + 1] = {};

    for (int i = 0; i < count; ++i) {
        const auto movable = [&](std::int32_t body) { return body != kNoSlot && !fixed[body]; };
        std::uint64_t used = 0;
        for (const std::int32_t body : pairs[items[i]]) {
            if (movable(body)) used |= masks_[body];
        }
        std::uint64_t free = ~used & kAllColors;
        int color = kMaxColors;  // overflow
        int bin = overflowBin;
        if (free != 0) {
            color = __builtin_ctzll(free);
            const std::uint64_t bit = std::uint64_t{1} << color;
            for (const std::int32_t body : pairs[items[i]]) {
                if (movable(body)) masks_[body] |= bit;
            }
            bin = color * regionCount + (regions ? regions[i] : 0);
        }
        binOf_[i] = static_cast<std::uint16_t>(bin);
        ++next[bin];
        ++sizes[color];
    }

    std::int32_t at = 0;
    for (int c = 0; c <= kMaxColors; ++c) {
        if (sizes[c] > 0) batches.push_back({base + at, base + at + sizes[c], c == kMaxColors});
        at += sizes[c];
    }
    at = 0;
    for (int bin = 0; bin <= overflowBin; ++bin) {
        const std::int32_t size = next[bin];
        next[bin] = at;
        at += size;
    }
    const std::size_t first = order.size();
    resizeBuffer(order, first + static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) order[first + next[binOf_[i]]++] = items[i];

    // Leave the masks zeroed for the next call.
    for (int i = 0; i < count; ++i) {
        for (const std::int32_t body : pairs[items[i]]) {
            if (body != kNoSlot) masks_[body] = 0;
        }
    }
}

}  // namespace pivot
