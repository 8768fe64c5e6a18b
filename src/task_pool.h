// A small pool of worker threads for the parallel stages of World::step. parallelFor splits an
// index range into chunks that the workers and the calling thread take in turn; it returns once
// every chunk is done. Stages only use it where the chunks are independent, and merge their
// results in index order afterwards, so results never depend on the number of workers or on
// scheduling.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace pivot {

class TaskPool {
public:
    /// `workers` threads in all, the caller included (1: everything runs on the caller).
    explicit TaskPool(int workers);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int workerCount() const { return static_cast<int>(threads_.size()) + 1; }

    /// Calls body(begin, end, worker) over [0, count) in chunks of at least minChunk indices;
    /// `worker` is in [0, workerCount()) and identifies per-worker scratch. Allocates nothing.
    template <typename Body>
    void parallelFor(int count, int minChunk, Body&& body) {
        if (count <= 0) return;
        if (threads_.empty() || count <= minChunk) {
            body(0, count, 0);
            return;
        }
        run(count, minChunk, &body, [](void* context, int begin, int end, int worker) {
            (*static_cast<Body*>(context))(begin, end, worker);
        });
    }

private:
    using Trampoline = void (*)(void*, int, int, int);
    void run(int count, int minChunk, void* context, Trampoline trampoline);
    void workerLoop(int worker);
    void takeChunks(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    // The current job. generation_ counts jobs, so a worker can tell a new job from a spurious
    // wake-up; busy_ counts workers still inside the job.
    std::uint64_t generation_ = 0;
    int busy_ = 0;
    bool stopping_ = false;
    void* context_ = nullptr;
    Trampoline trampoline_ = nullptr;
    int count_ = 0;
    int chunk_ = 1;
    std::atomic<int> next_{0};
};

}  // namespace pivot
