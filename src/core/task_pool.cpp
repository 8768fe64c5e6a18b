#include "core/task_pool.h"

#include <algorithm>

#include "core/spin_wait.h"

namespace pivot {

TaskPool::TaskPool(int workers) : active_(std::max(workers, 1)) {
    for (int i = 1; i < workers; ++i) threads_.emplace_back([this, i] { workerLoop(i); });
}

void TaskPool::setActiveWorkers(int count) {
    std::lock_guard<std::mutex> lock(mutex_);
    active_ = std::clamp(count, 1, workerCount());
}

TaskPool::~TaskPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void TaskPool::takeChunks(int worker) {
    if (count_ < 0) {
        trampoline_(context_, 0, 0, worker);
        return;
    }
    for (;;) {
        int begin = next_.fetch_add(chunk_, std::memory_order_relaxed);
        if (begin >= count_) return;
        trampoline_(context_, begin, std::min(begin + chunk_, count_), worker);
    }
}

void TaskPool::run(int count, int minChunk, void* context, Trampoline trampoline) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        context_ = context;
        trampoline_ = trampoline;
        count_ = count;
        // A few chunks per worker balance uneven work without much hand-off cost.
        const int target = std::max(1, count / (4 * active_));
        chunk_ = std::max(minChunk, target);
        next_.store(0, std::memory_order_relaxed);
        if (count < 0) stages_.reset();
        open_ = true;
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    takeChunks(0);
    {
        // The caller has taken every chunk it could: a worker that has not joined yet finds
        // the job closed, and the caller waits only for those inside.
        std::lock_guard<std::mutex> lock(mutex_);
        open_ = false;
    }
    if (spinUntil(kJobSpin, [this] { return busy_.load(std::memory_order_acquire) == 0; })) return;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_.load(std::memory_order_acquire) == 0; });
}

void TaskPool::workerLoop(int worker) {
    std::uint64_t seen = 0;
    for (;;) {
        // The next stage of a step usually starts within microseconds: watch for it before
        // sleeping, so that most hand-offs cost no wake-up.
        spinUntil(kJobSpin, [&] { return generation_.load(std::memory_order_acquire) != seen; });
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] {
                return stopping_ || generation_.load(std::memory_order_relaxed) != seen;
            });
            if (stopping_) return;
            seen = generation_.load(std::memory_order_relaxed);
            // Joins only a job still open (one whose caller is not yet past its own part) and
            // open to it.
            if (!open_ || worker >= active_) continue;
            busy_.fetch_add(1, std::memory_order_relaxed);
        }
        takeChunks(worker);
        if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            // Under the lock, so a caller between its last check and its wait cannot miss it.
            std::lock_guard<std::mutex> lock(mutex_);
            done_.notify_one();
        }
    }
}

}  // namespace pivot
