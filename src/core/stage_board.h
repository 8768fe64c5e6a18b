// Where the members of a region (TaskPool::region) claim the blocks of its stages. Every member
// runs the same program and numbers its stages the same way (1, 2, ...); a stage is cut into
// the same blocks by all, and each block is done by whichever member claims it first. So a
// member that has no core for a while holds nobody up: the others do its blocks, and when it
// comes back it finds its stages done and moves on. Only a member that stops in the middle of
// a block is waited for.
//
// Stage s lives in slot s % kSlots as one word: its number (high 32 bits), the blocks finished
// (16 bits) and the blocks claimed (low 16 bits). The first member to reach a stage opens its
// slot by writing the number over the older stage's; the older stage was finished by then,
// since a member waits for its stages to finish (Team::sync) at least once every kSlots stages.
// A slot numbered past s means s finished long ago.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace pivot {

class StageBoard {
public:
    static constexpr int kSlots = 64;
    static constexpr int kMaxBlocks = 0xFFFF;

    /// Between regions, with no member inside one.
    void reset() {
        for (Slot& slot : slots_) slot.word.store(0, std::memory_order_relaxed);
    }

    /// The next unclaimed block of stage `stage` (>= 1) of `blocks` (1 to kMaxBlocks), or -1
    /// when every block is claimed. A claimed block must be reported with finish().
    int claim(std::uint32_t stage, int blocks) {
        std::atomic<std::uint64_t>& word = slots_[stage % kSlots].word;
        const std::uint64_t tag = std::uint64_t{stage} << 32;
        std::uint64_t v = word.load(std::memory_order_acquire);
        for (;;) {
            if (v < tag) {  // an older stage's: open this one
                if (word.compare_exchange_weak(v, tag, std::memory_order_acq_rel)) v = tag;
                continue;
            }
            if (v >= tag + (std::uint64_t{1} << 32)) return -1;  // finished long ago
            const int claimed = static_cast<int>(v & 0xFFFF);
            if (claimed >= blocks) return -1;
            if (word.compare_exchange_weak(v, v + 1, std::memory_order_acq_rel)) return claimed;
        }
    }

    /// A block of `stage` is done: what it wrote is visible to whoever sees the stage finished.
    void finish(std::uint32_t stage) {
        slots_[stage % kSlots].word.fetch_add(std::uint64_t{1} << 16, std::memory_order_acq_rel);
    }

    /// Whether all `blocks` of `stage` are finished (only asked by a member that reached it).
    bool finished(std::uint32_t stage, int blocks) const {
        const std::uint64_t v = slots_[stage % kSlots].word.load(std::memory_order_acquire);
        const std::uint64_t tag = std::uint64_t{stage} << 32;
        if (v >= tag + (std::uint64_t{1} << 32)) return true;
        return v >= tag && static_cast<int>((v >> 16) & 0xFFFF) >= blocks;
    }

private:
    // One cache line each: members claiming the blocks of consecutive stages do not contend.
    struct alignas(64) Slot {
        std::atomic<std::uint64_t> word{0};
    };
    std::array<Slot, kSlots> slots_;
};

}  // namespace pivot
