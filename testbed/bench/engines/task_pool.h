// A small pool of threads serving Box2D v3's task callbacks (b2WorldDef::enqueueTask and
// finishTask), as its benchmark app's task scheduler does: a task is a range of items cut into
// chunks of at least minRange, run by the pool's threads and by the thread that waits for it.
// Box2D v3's solver runs one task per worker that wait on each other, so a waiting thread must
// run any open task's chunks, not only its own: with n threads, n such tasks all run at once.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace pivot::bench {

class TaskPool {
public:
    using Range = void(int begin, int end, std::uint32_t worker, void* context);

    /// `threads` in all: the caller (worker 0) and threads - 1 of the pool's own.
    explicit TaskPool(int threads);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    /// Opens a task over [0, items); returns its handle, or runs it at once and returns null
    /// when it is too small to share or every slot is taken.
    void* enqueue(Range* range, int items, int minRange, void* context);
    /// Returns when the task's every chunk has run, running open chunks meanwhile.
    void finish(void* task);

private:
    struct Task {
        Range* range = nullptr;
        void* context = nullptr;
        int items = 0;
        int chunkSize = 0;
        int chunks = 0;
        int claimed = 0;           // chunks handed out, under mutex_
        std::atomic<int> done{0};  // chunks finished
    };

    bool runOneChunk(std::uint32_t worker);
    void workerLoop(std::uint32_t worker);

    static constexpr int kSlots = 256;  // open tasks at most (Box2D v3 opens a few per step)
    const int threads_;
    std::array<Task, kSlots> tasks_;
    std::mutex mutex_;
    // Under mutex_: tasks first_ .. next_ - 1 (slots taken cyclically) may have chunks left.
    int first_ = 0;
    int next_ = 0;
    std::condition_variable wake_;
    std::atomic<int> open_{0};  // tasks with chunks not yet claimed
    std::atomic<bool> stop_{false};
    std::vector<std::thread> pool_;
};

}  // namespace pivot::bench
