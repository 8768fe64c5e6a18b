#include "core/task_pool.h"

#include <algorithm>
#include <utility>

#include "core/index_range.h"
#include "core/spin_wait.h"

namespace pivot {

TaskPool::TaskPool(int workers, TaskSystem tasks)
    : workerCount_(std::max(workers, 1)), tasks_(std::move(tasks)), active_(workerCount_) {
    if (tasks_.present()) {
        handles_.reserve(static_cast<std::size_t>(workerCount_ - 1));
        return;
    }
    for (int i = 1; i < workerCount_; ++i) threads_.emplace_back([this, i] { workerLoop(i); });
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
    for (int k = 0; k < stretches_; ++k) {
        const int stretch = (worker + k) % stretches_;
        const int first = shareStart(chunkCount_, stretch, stretches_);
        const int last = shareStart(chunkCount_, stretch + 1, stretches_);
        std::atomic<int>& next = cursors_[static_cast<std::size_t>(stretch)].next;
        for (int chunk; (chunk = first + next.fetch_add(1, std::memory_order_relaxed)) < last;) {
            const int begin = chunk * chunk_;
            trampoline_(context_, begin, std::min(begin + chunk_, count_), worker);
        }
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
        chunkCount_ = count < 0 ? 0 : (count + chunk_ - 1) / chunk_;
        stretches_ = std::clamp(active_, 1, std::clamp(chunkCount_, 1, kMaxStretches));
        for (int s = 0; s < stretches_; ++s) {
            cursors_[static_cast<std::size_t>(s)].next.store(0, std::memory_order_relaxed);
        }
        if (count < 0) stages_->reset(active_);
        open_ = true;
        generation_.fetch_add(1, std::memory_order_release);
    }
    if (tasks_.present()) {
        enqueueHelpers();
    } else {
        wake_.notify_all();
    }
    takeChunks(0);
    {
        // The caller has taken every chunk it could: a worker that has not joined yet finds
        // the job closed, and the caller waits only for those inside.
        std::lock_guard<std::mutex> lock(mutex_);
        open_ = false;
    }
    if (tasks_.present()) finishHelpers();
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
            if (!joinLocked(worker, seen)) continue;
        }
        takeChunks(worker);
        leave();
    }
}

bool TaskPool::join(int worker, std::uint64_t generation) {
    std::lock_guard<std::mutex> lock(mutex_);
    return joinLocked(worker, generation);
}

bool TaskPool::joinLocked(int worker, std::uint64_t generation) {
    // Joins only the job it was called for, while still open (its caller not yet past its own
    // part) and open to it.
    if (generation_.load(std::memory_order_relaxed) != generation || !open_ || worker >= active_) {
        return false;
    }
    busy_.fetch_add(1, std::memory_order_relaxed);
    return true;
}

void TaskPool::leave() {
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        // Under the lock, so a caller between its last check and its wait cannot miss it.
        std::lock_guard<std::mutex> lock(mutex_);
        done_.notify_one();
    }
}

void TaskPool::runHelper(void* context, std::uint64_t ticket) {
    TaskPool& pool = *static_cast<TaskPool*>(context);
    const int worker = static_cast<int>(ticket % kMaxWorkers);
    if (pool.join(worker, ticket / kMaxWorkers)) {
        pool.takeChunks(worker);
        pool.leave();
    }
}

void TaskPool::enqueueHelpers() {
    handles_.clear();
    const std::uint64_t generation = generation_.load(std::memory_order_relaxed);
    for (int worker = 1; worker < active_; ++worker) {
        const std::uint64_t ticket = generation * kMaxWorkers + static_cast<std::uint64_t>(worker);
        try {
            handles_.push_back(tasks_.enqueue(StepTask(&TaskPool::runHelper, this, ticket)));
        } catch (...) {
            // The caller does the job without this helper.
            holdTaskError();
        }
    }
}

void TaskPool::finishHelpers() {
    for (void* handle : handles_) {
        try {
            tasks_.finish(handle);
        } catch (...) {
            // Whether the task ran or not, its ticket keeps it out of every later job; one
            // that joined this job is waited for below, in run.
            holdTaskError();
        }
    }
    handles_.clear();
}

void TaskPool::holdTaskError() {
    if (!taskError_) taskError_ = std::current_exception();
}

}  // namespace pivot
