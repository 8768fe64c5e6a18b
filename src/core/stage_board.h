// Where the members of a region (TaskPool::region) claim the blocks of its stages. Every member
// runs the same program and numbers its stages the same way (1, 2, ...); a stage is cut into
// the same blocks by all, and each block is done by whichever member claims it first. So a
// member that has no core for a while holds nobody up: the others do its blocks, and when it
// comes back it finds its stages done and moves on. Only a member that stops in the middle of
// a block is waited for.
//
// A stage's blocks are dealt into segments, one per member (up to kMaxSegments, then shared):
// a member claims the blocks of its own segment first, in order, and only then those left in
// the others'. So while every member has its core, a member solves the same stretch of every
// stage over an island's same constraints or bodies, from one sweep to the next, and the bodies
// those touch stay in its own cache instead of crossing to another core's at every sweep (a
// cache line took about 200 ns to cross on the machine measured, docs/performance.md). Which
// member solves a block never changes a result.
//
// Stage s lives in slot s % kSlots: a word per segment, the stage's number (high 32 bits) and
// the blocks claimed of that segment (low 32), and a word counting the blocks finished, with
// the number likewise. The first member to reach a word opens it by writing the number over
// the older stage's; the older stage was finished by then, since a member waits for its stages
// to finish (Team::sync) at least once every kSlots stages. A word numbered past s means s
// finished long ago. Each word has a cache line of its own: a member claiming from its own
// segment touches no line another member writes.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>

#include "core/index_range.h"

namespace pivot {

class StageBoard {
public:
    static constexpr int kSlots = 64;
    static constexpr int kMaxBlocks = 0xFFFF;
    static constexpr int kMaxSegments = 8;

    /// Between regions, with no member inside one, for a region of `members` (the segments
    /// they will use).
    void reset(int members) {
        const int segments = std::clamp(members, 1, kMaxSegments);
        for (Slot& slot : slots_) {
            slot.finished.word.store(0, std::memory_order_relaxed);
            for (int k = 0; k < segments; ++k) {
                slot.segments[static_cast<std::size_t>(k)].word.store(0, std::memory_order_relaxed);
            }
        }
    }

    /// A member reaching stage `stage` (>= 1), before it claims any of its blocks: opens the
    /// stage's count of finished blocks, so that finish() counts for this stage. False if the
    /// stage finished long ago (nothing is left to claim).
    bool enter(std::uint32_t stage) {
        return open(slots_[stage % kSlots].finished.word, std::uint64_t{stage} << 32);
    }

    /// The next unclaimed block of stage `stage` (entered) of `blocks` (1 to kMaxBlocks) for
    /// member `member` of `members`: its own segment's first, then the others'. -1 when every
    /// block is claimed. A claimed block must be reported with finish().
    int claim(std::uint32_t stage, int blocks, int member, int members) {
        Slot& slot = slots_[stage % kSlots];
        const std::uint64_t tag = std::uint64_t{stage} << 32;
        const int segments = segmentCount(blocks, members);
        for (int k = 0; k < segments; ++k) {
            const int segment = (member + k) % segments;
            const IndexRange own = segmentBlocks(blocks, segment, segments);
            const int block = claimIn(slot.segments[segment].word, tag, own.end - own.begin);
            if (block == kLongAgo) return -1;
            if (block >= 0) return own.begin + block;
        }
        return -1;
    }

    /// How many segments `blocks` blocks are dealt into for `members` members, and the blocks
    /// of segment `segment` (member `segment`'s own, claimed first).
    static int segmentCount(int blocks, int members) {
        return std::clamp(members, 1, std::min(kMaxSegments, blocks));
    }
    static IndexRange segmentBlocks(int blocks, int segment, int segments) {
        return {shareStart(blocks, segment, segments), shareStart(blocks, segment + 1, segments)};
    }

    /// A block of `stage` is done: what it wrote is visible to whoever sees the stage finished.
    void finish(std::uint32_t stage) {
        slots_[stage % kSlots].finished.word.fetch_add(1, std::memory_order_acq_rel);
    }

    /// Whether all `blocks` of `stage` are finished (only asked by a member that reached it).
    bool finished(std::uint32_t stage, int blocks) const {
        const std::uint64_t v =
            slots_[stage % kSlots].finished.word.load(std::memory_order_acquire);
        const std::uint64_t tag = std::uint64_t{stage} << 32;
        if (v >= tag + kNextStage) return true;
        return v >= tag && static_cast<int>(v & kCountMask) >= blocks;
    }

private:
    static constexpr std::uint64_t kNextStage = std::uint64_t{1} << 32;
    static constexpr std::uint64_t kCountMask = kNextStage - 1;
    static constexpr int kLongAgo = -2;

    // Makes `word` this stage's (tag) if it still holds an older one; false if it holds a later
    // one: this stage finished long ago.
    static bool open(std::atomic<std::uint64_t>& word, std::uint64_t tag) {
        std::uint64_t v = word.load(std::memory_order_acquire);
        while (v < tag) {
            if (word.compare_exchange_weak(v, tag, std::memory_order_acq_rel)) return true;
        }
        return v < tag + kNextStage;
    }

    // The next of a segment's `count` blocks, -1 when all are claimed, kLongAgo when the word
    // holds a later stage.
    static int claimIn(std::atomic<std::uint64_t>& word, std::uint64_t tag, int count) {
        if (count <= 0) return -1;
        std::uint64_t v = word.load(std::memory_order_acquire);
        for (;;) {
            if (v < tag) {  // an older stage's: open this one
                if (word.compare_exchange_weak(v, tag, std::memory_order_acq_rel)) v = tag;
                continue;
            }
            if (v >= tag + kNextStage) return kLongAgo;
            const int claimed = static_cast<int>(v & kCountMask);
            if (claimed >= count) return -1;
            if (word.compare_exchange_weak(v, v + 1, std::memory_order_acq_rel)) return claimed;
        }
    }

    struct alignas(64) Word {
        std::atomic<std::uint64_t> word{0};
    };
    struct Slot {
        Word finished;
        std::array<Word, kMaxSegments> segments;
    };
    std::array<Slot, kSlots> slots_;
};

}  // namespace pivot
