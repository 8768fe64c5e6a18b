// A small pool of worker threads for the parallel stages of World::step. parallelFor splits an
// index range into chunks that the workers and the calling thread take in turn; it returns once
// every chunk is done. Stages only use it where the chunks are independent, and merge their
// results in index order afterwards, so results never depend on the number of workers or on
// scheduling.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "core/stage_board.h"

namespace pivot {

class TaskPool {
public:
    /// `workers` threads in all, the caller included (1: everything runs on the caller).
    explicit TaskPool(int workers);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int workerCount() const { return static_cast<int>(threads_.size()) + 1; }

    /// Workers the next jobs may use, the caller included, in [1, workerCount()]: the others stay
    /// out of them (and sleep once their spin runs out). Set between jobs, by the caller.
    void setActiveWorkers(int count);
    int activeWorkers() const { return active_; }

    /// Calls body(begin, end, worker) over [0, count) in chunks of at least minChunk indices;
    /// `worker` is in [0, workerCount()) and identifies per-worker scratch. Allocates nothing.
    template <typename Body>
    void parallelFor(int count, int minChunk, Body&& body) {
        if (count <= 0) return;
        if (active_ == 1 || count <= minChunk) {
            body(0, count, 0);
            return;
        }
        run(count, minChunk, &body, [](void* context, int begin, int end, int worker) {
            (*static_cast<Body*>(context))(begin, end, worker);
        });
    }

    /// Runs body(worker) on the caller (worker 0) and on every worker that joins while the
    /// caller is still in its own body(0), and returns when all of them have returned. Inside,
    /// members share out stages through stages() (islands/team.h): the island solver solves
    /// one graph colour at a time that way, with whoever is there.
    template <typename Body>
    void region(Body&& body) {
        if (active_ == 1) {
            body(0);
            return;
        }
        run(-1, 1, &body,
            [](void* context, int, int, int worker) { (*static_cast<Body*>(context))(worker); });
    }

    /// Inside region(): where its members claim the blocks of its stages (cleared for each).
    StageBoard& stages() { return stages_; }

private:
    using Trampoline = void (*)(void*, int, int, int);
    /// count < 0: a region, the trampoline called once per worker.
    void run(int count, int minChunk, void* context, Trampoline trampoline);
    void workerLoop(int worker);
    void takeChunks(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    // The current job. generation_ counts jobs, so a worker can tell a new job from a spurious
    // wake-up; busy_ counts workers inside the job (joined while it was open_: a worker that
    // wakes after the caller has done its part stays out, so it never holds the caller up).
    // Both are atomic so that a worker can watch for the next job, and the caller for the end
    // of this one, without the lock.
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<int> busy_{0};
    bool open_ = false;
    bool stopping_ = false;
    int active_ = 1;  // workers with an index below it join jobs (written under the lock)
    void* context_ = nullptr;
    Trampoline trampoline_ = nullptr;
    int count_ = 0;
    int chunk_ = 1;
    std::atomic<int> next_{0};
    // How long a waiting thread spins before it sleeps. The stages of a step follow each other
    // within tens of microseconds, less than a wake-up costs, so a worker waiting for the next
    // job, or the caller for the end of one, watches for about kJobSpin.
    static constexpr std::chrono::microseconds kJobSpin{100};
    StageBoard stages_;
};

}  // namespace pivot
