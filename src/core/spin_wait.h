// Waiting without a lock for something another thread does within microseconds.
#pragma once

#include <chrono>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace pivot {

/// Tells the core this is a spin-wait (lets a sibling hyperthread run, saves power).
inline void relaxCpu() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

/// Spins until ready() or until about `limit` has passed, and returns ready(). The clock is read
/// once every few dozen pauses: a pause lasts from about 10 to about 150 cycles depending on the
/// processor, so counting pauses would make the wait vary tenfold.
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

/// Spins for about `spin`, then gives the core away between looks until ready(): when the
/// thread being waited for has no core (more busy threads than cores), a spinning waiter would
/// keep it from getting one.
template <typename Ready>
void waitUntil(std::chrono::microseconds spin, Ready&& ready) {
    if (spinUntil(spin, ready)) return;
    while (!ready()) std::this_thread::yield();
}

}  // namespace pivot
