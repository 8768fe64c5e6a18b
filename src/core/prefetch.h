// A hint to the CPU to start loading memory that will be read soon, so that a loop walking
// scattered records (contacts in colour order, their bodies and shapes) overlaps its cache
// misses instead of waiting for each in turn. A hint only: it never faults and changes no result.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pivot {

constexpr std::size_t kCacheLine = 64;

/// Starts loading every cache line of the `bytes` bytes at `p`.
inline void prefetch(const void* p, std::size_t bytes = 1) {
#if defined(__GNUC__) || defined(__clang__)
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(p) & ~(kCacheLine - 1);
    const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(p) + bytes - 1;
    for (std::uintptr_t line = first; line <= last; line += kCacheLine) {
        __builtin_prefetch(reinterpret_cast<const void*>(line));
    }
#else
    (void)p;
    (void)bytes;
#endif
}

}  // namespace pivot
