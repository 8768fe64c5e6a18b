#include "bench/engines/task_pool.h"

#include <algorithm>

namespace pivot::bench {

namespace {

// The pool thread's worker index; the thread that made the pool (and every other) is 0.
thread_local std::uint32_t currentWorker = 0;

// How long an idle pool thread spins before it sleeps: a step opens tasks every few
// microseconds, and waking a sleeping thread costs more than that.
constexpr int kSpinsBeforeSleep = 20000;

}  // namespace

TaskPool::TaskPool(int threads) : threads_(std::max(1, threads)) {
    for (int i = 1; i < threads_; ++i) {
        pool_.emplace_back([this, i] { workerLoop(static_cast<std::uint32_t>(i)); });
    }
}

TaskPool::~TaskPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : pool_) thread.join();
}

void* TaskPool::enqueue(Range* range, int items, int minRange, void* context) {
    const int chunks =
        std::min((items + std::max(1, minRange) - 1) / std::max(1, minRange), 4 * threads_);
    if (threads_ == 1) {
        range(0, items, currentWorker, context);
        return nullptr;
    }
    Task* task = nullptr;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (first_ == next_ && next_ >= (1 << 30)) first_ = next_ = next_ % kSlots;
        Task& slot = tasks_[static_cast<std::size_t>(next_ % kSlots)];
        const bool windowFull = next_ - first_ >= kSlots;
        if (!windowFull && slot.done.load(std::memory_order_acquire) == slot.chunks) {
            slot.range = range;
            slot.context = context;
            slot.items = items;
            slot.chunks = std::max(1, chunks);
            slot.chunkSize = (items + slot.chunks - 1) / slot.chunks;
            slot.claimed = 0;
            slot.done.store(0, std::memory_order_relaxed);
            ++next_;
            open_.fetch_add(slot.chunks, std::memory_order_release);
            task = &slot;
        }
    }
    if (task == nullptr) {  // no free slot: run it here
        range(0, items, currentWorker, context);
        return nullptr;
    }
    wake_.notify_all();
    return task;
}

void TaskPool::finish(void* handle) {
    if (handle == nullptr) return;
    const Task& task = *static_cast<Task*>(handle);
    while (task.done.load(std::memory_order_acquire) < task.chunks) {
        if (!runOneChunk(currentWorker)) std::this_thread::yield();
    }
}

bool TaskPool::runOneChunk(std::uint32_t worker) {
    if (open_.load(std::memory_order_acquire) == 0) return false;
    Task* task = nullptr;
    int chunk = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (int s = first_; s < next_; ++s) {
            Task& candidate = tasks_[static_cast<std::size_t>(s % kSlots)];
            if (candidate.claimed < candidate.chunks) {
                task = &candidate;
                chunk = candidate.claimed++;
                open_.fetch_sub(1, std::memory_order_relaxed);
                break;
            }
            if (s == first_) ++first_;  // every chunk of the oldest handed out
        }
    }
    if (task == nullptr) return false;
    const int begin = chunk * task->chunkSize;
    const int end = std::min(task->items, begin + task->chunkSize);
    if (begin < end) task->range(begin, end, worker, task->context);
    task->done.fetch_add(1, std::memory_order_acq_rel);
    return true;
}

void TaskPool::workerLoop(std::uint32_t worker) {
    currentWorker = worker;
    int idle = 0;
    while (!stop_.load(std::memory_order_acquire)) {
        if (runOneChunk(worker)) {
            idle = 0;
            continue;
        }
        if (++idle < kSpinsBeforeSleep) continue;
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stop_.load() || open_.load() > 0; });
        idle = 0;
    }
}

}  // namespace pivot::bench
