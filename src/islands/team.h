// The workers solving one island together. Every member runs the same sequence of stages (the
// island solver's program); a stage cuts its index range into blocks, each done by whichever
// member claims it first (core/stage_board.h), and members wait with sync() before a stage that
// reads what another stage wrote. A member without a core for a while holds nobody up: the
// others take its blocks. A team of one is the plain sequential solver: its stage is one
// range and sync() is free.
//
// Blocks are fixed by the item count, never by timing, and the items of a stage are
// independent (constraints of one graph colour, distinct bodies), so the result depends neither
// on the size of the team nor on who solved which block. Work that is summed per member (the
// island report) is summed the same whatever the split; nothing else is kept per member.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/index_range.h"
#include "core/spin_wait.h"
#include "core/stage_board.h"
#include "core/task_pool.h"

namespace pivot {

class Team {
public:
    /// A team of one, on the calling thread.
    Team() = default;
    Team(TaskPool& pool, int member)
        : board_(&pool.stages()), member_(member), size_(pool.activeWorkers()) {}

    int member() const { return member_; }
    int size() const { return size_; }
    bool leader() const { return member_ == 0; }

    /// A stage of work on [0, count) whose items are independent: f(range) runs on the blocks
    /// this member claims (the blocks depend on count, minBlock and alignment only; each but
    /// the first starts at a multiple of `alignment`). Returns once no block is left to claim,
    /// not once all are done: sync() waits for that.
    template <typename F>
    void forBlocks(int count, int minBlock, F&& f, int alignment = 1) const {
        if (count <= 0) return;
        if (size_ == 1) {
            f(IndexRange{0, count});
            return;
        }
        const int blocks = blockCount(count, minBlock);
        claimBlocks(blocks, [&](int b) {
            f(IndexRange{blockStart(count, blocks, b, alignment),
                         blockStart(count, blocks, b + 1, alignment)});
        });
    }

    /// A stage over bodies or constraints [0, count) in blocks of at least kMinBlock.
    template <typename F>
    void forBlocks(int count, F&& f) const {
        forBlocks(count, kMinBlock, std::forward<F>(f));
    }

    /// A stage over one batch: a serial batch is one block, so one member solves it in order;
    /// an independent one is cut at multiples of kBatchAlignment from its start.
    template <typename F>
    void forBlocks(const Batch& batch, F&& f) const {
        const int count = batch.end - batch.begin;
        const auto shifted = [&](IndexRange r) {
            f(IndexRange{batch.begin + r.begin, batch.begin + r.end});
        };
        forBlocks(count, batch.serial ? count : kMinBlock, shifted, kBatchAlignment);
    }

    /// A stage over the constraints of `batches` (consecutive, batch after batch) in which a
    /// member's own blocks are, in every batch, the share that forBlocks(batch) gives it first:
    /// a pass over the whole array (a set-up, a store) then touches the constraints, and the
    /// bodies, that the member's colour-by-colour sweeps touch, on its own core. Any batch is
    /// cut this way, a serial one too (for work that is independent per constraint).
    template <typename F>
    void forBatchShares(const std::vector<Batch>& batches, F&& f) const {
        if (batches.empty()) return;
        if (size_ == 1) {
            f(IndexRange{batches.front().begin, batches.back().end});
            return;
        }
        const int batchCount = static_cast<int>(batches.size());
        claimBlocks(size_ * batchCount, [&](int b) {
            const Batch& batch = batches[static_cast<std::size_t>(b % batchCount)];
            const IndexRange share = shareOf(batch.end - batch.begin, b / batchCount);
            if (share.begin < share.end) {
                f(IndexRange{batch.begin + share.begin, batch.begin + share.end});
            }
        });
    }

    /// Work for one member (whichever gets there first), as a stage of one block.
    template <typename F>
    void once(F&& f) const {
        forBlocks(1, 1, [&](IndexRange) { f(); });
    }

    /// Waits until every stage this member has taken part in since its last sync is done
    /// (before a stage that reads what those wrote).
    void sync() const {
        for (int k = 0; k < openCount_; ++k) {
            const Open stage = open_[k];
            waitUntil(kSyncSpin, [&] { return board_->finished(stage.number, stage.blocks); });
        }
        openCount_ = 0;
    }

private:
    struct Open {
        std::uint32_t number;
        int blocks;
    };

    /// forBlocks' cut of [0, count): how many blocks, and where block k starts (each but the
    /// first at a multiple of `alignment`; k == blocks gives the end).
    int blockCount(int count, int minBlock) const {
        return std::clamp(count / std::max(minBlock, 1), 1,
                          std::min(kBlocksPerMember * size_, StageBoard::kMaxBlocks));
    }
    static int blockStart(int count, int blocks, int k, int alignment) {
        if (k == blocks) return count;
        const auto even = static_cast<int>(static_cast<std::int64_t>(count) * k / blocks);
        return even / alignment * alignment;
    }

    /// The part of [0, count) that forBlocks(count, kMinBlock, f, kBatchAlignment) deals to
    /// `member`'s own segment (StageBoard::claim), empty for a member without one.
    IndexRange shareOf(int count, int member) const {
        const int blocks = blockCount(count, kMinBlock);
        const int segments = StageBoard::segmentCount(blocks, size_);
        if (member >= segments) return {0, 0};
        const IndexRange own = StageBoard::segmentBlocks(blocks, member, segments);
        return {blockStart(count, blocks, own.begin, kBatchAlignment),
                blockStart(count, blocks, own.end, kBatchAlignment)};
    }

    template <typename Run>
    void claimBlocks(int blocks, Run&& run) const {
        // A board slot is reused kSlots stages on: syncing before then keeps the stages this
        // member has open apart from the ones it will open.
        if (openCount_ == kMaxOpen) sync();
        const std::uint32_t number = nextStage_++;
        open_[openCount_++] = {number, blocks};
        if (!board_->enter(number)) return;
        for (int b; (b = board_->claim(number, blocks, member_, size_)) >= 0;) {
            run(b);
            board_->finish(number);
        }
    }

    // A stage is cut into up to this many blocks per member: enough for a member that finds
    // the others slow to take their share, few enough that claiming costs little.
    static constexpr int kBlocksPerMember = 4;
    // Below this, a block costs more in hand-off and cache traffic than it saves.
    static constexpr int kMinBlock = 32;
    static constexpr int kMaxOpen = 8;
    static_assert(kMaxOpen < StageBoard::kSlots, "open stages must not share a slot");
    // Members that all have a core finish a stage within microseconds of each other.
    static constexpr std::chrono::microseconds kSyncSpin{25};

    StageBoard* board_ = nullptr;
    int member_ = 0;
    int size_ = 1;
    mutable std::uint32_t nextStage_ = 1;  // numbered alike by every member: same program
    mutable Open open_[kMaxOpen] = {};
    mutable int openCount_ = 0;
};

/// Runs f(range, independent) on the blocks this member claims of each batch in turn, syncing
/// after each; `independent` says the batch is one colour (no two of its constraints share a
/// solver slot), which lets f solve several of them at once.
template <typename F>
void forEachBatchSaying(const Team& team, const std::vector<Batch>& batches, F&& f) {
    for (const Batch& batch : batches) {
        team.forBlocks(batch, [&](IndexRange range) { f(range, !batch.serial); });
        team.sync();
    }
}

/// Runs f(range) on the blocks this member claims of each batch in turn, syncing after each.
template <typename F>
void forEachBatch(const Team& team, const std::vector<Batch>& batches, F&& f) {
    for (const Batch& batch : batches) {
        team.forBlocks(batch, f);
        team.sync();
    }
}

}  // namespace pivot
