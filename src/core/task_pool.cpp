#include "core/task_pool.h"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace pivot {

namespace {

// Tells the core this is a spin-wait (lets a sibling hyperthread run, saves power).
inline void relaxCpu() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

// Spins until ready() or until about `limit` has passed, and returns ready(). The clock is read
// once every few dozen pauses: a pause lasts from about 10 to about 150 cycles depending on the
// processor, so counting pauses would make the wait vary tenfold.
template <typename Ready>
bool spinUntil(std::chrono::microseconds limit, Ready&& ready) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point until = Clock::now() + limit;
    for (;;) {
        for (int i = 0; i < 32; ++i) {
            if (ready()) return true;
            relaxCpu();
        }
        if (Clock::now() >= until) return ready();
    }
}

}  // namespace

TaskPool::TaskPool(int workers) {
    for (int i = 1; i < workers; ++i) threads_.emplace_back([this, i] { workerLoop(i); });
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

void TaskPool::barrier() {
    const int workers = workerCount();
    if (workers == 1) return;
    const std::uint64_t round = round_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == workers) {
        arrived_.store(0, std::memory_order_relaxed);
        {
            // Under the lock, so a member between its last check and its wait cannot miss it.
            std::lock_guard<std::mutex> lock(barrierMutex_);
            round_.fetch_add(1, std::memory_order_acq_rel);
        }
        barrierWake_.notify_all();
        return;
    }
    // The others are usually a few microseconds behind: spin that long. If they are not (the
    // machine has more busy threads than cores, and one of ours is waiting for a core), sleep
    // and give the core away rather than burn the time slice it needs.
    if (spinUntil(kBarrierSpin, [&] { return round_.load(std::memory_order_acquire) != round; })) {
        return;
    }
    std::unique_lock<std::mutex> lock(barrierMutex_);
    barrierWake_.wait(lock, [&] { return round_.load(std::memory_order_acquire) != round; });
}

void TaskPool::run(int count, int minChunk, void* context, Trampoline trampoline) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        context_ = context;
        trampoline_ = trampoline;
        count_ = count;
        // A few chunks per worker balance uneven work without much hand-off cost.
        const int target = std::max(1, count / (4 * workerCount()));
        chunk_ = std::max(minChunk, target);
        next_.store(0, std::memory_order_relaxed);
        busy_.store(static_cast<int>(threads_.size()), std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    takeChunks(0);
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
