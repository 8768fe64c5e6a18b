// The workers solving one island together. Every member runs the same sequence of stages (the
// island solver's program); a stage gives each member its share of an index range, and members
// meet at sync() before a stage that reads what another member wrote. A team of one is the
// plain sequential solver: its share is everything and sync() is free.
//
// Shares are fixed by the member's number, never by timing, and constraints solved in the same
// stage are independent (a batch of one graph colour), so the result does not depend on the
// size of the team.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/index_range.h"
#include "core/task_pool.h"

namespace pivot {

/// Constraints [begin, end) of one array that may be solved in any order, or, if serial, only
/// in order (on member 0).
struct Batch {
    std::int32_t begin = 0;
    std::int32_t end = 0;
    bool serial = true;
};

class Team {
public:
    /// A team of one, on the calling thread.
    Team() = default;
    Team(TaskPool& pool, int member) : pool_(&pool), member_(member), size_(pool.workerCount()) {}

    int member() const { return member_; }
    int size() const { return size_; }
    bool leader() const { return member_ == 0; }

    /// Waits for every member (after a stage whose results the next one reads).
    void sync() const {
        if (size_ > 1) pool_->barrier();
    }

    /// This member's share of [0, count), for work on independent items.
    IndexRange share(int count) const { return share({0, count, false}); }

    /// This member's share of a batch. A small batch goes whole to the leader: splitting it
    /// would cost more in cache traffic than it saves.
    IndexRange share(const Batch& batch) const {
        const int count = batch.end - batch.begin;
        if (size_ == 1 || batch.serial || count < kMinSplit) {
            return leader() ? IndexRange{batch.begin, batch.end}
                            : IndexRange{batch.begin, batch.begin};
        }
        const auto at = [&](int m) {
            return batch.begin + static_cast<int>(static_cast<std::int64_t>(count) * m / size_);
        };
        return {at(member_), at(member_ + 1)};
    }

private:
    static constexpr int kMinSplit = 32;
    TaskPool* pool_ = nullptr;
    int member_ = 0;
    int size_ = 1;
};

/// Runs f(range, independent) on this member's share of each batch in turn, syncing after
/// each; `independent` says the batch is one colour (no two of its constraints share a solver
/// slot), which lets f solve several of them at once.
template <typename F>
void forEachBatchSaying(const Team& team, const std::vector<Batch>& batches, F&& f) {
    for (const Batch& batch : batches) {
        f(team.share(batch), !batch.serial);
        team.sync();
    }
}

/// Runs f(range) on this member's share of each batch in turn, syncing after each.
template <typename F>
void forEachBatch(const Team& team, const std::vector<Batch>& batches, F&& f) {
    for (const Batch& batch : batches) {
        f(team.share(batch));
        team.sync();
    }
}

}  // namespace pivot
