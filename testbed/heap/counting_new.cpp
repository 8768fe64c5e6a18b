#include "heap/counting_new.h"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
// Constant-initialised, so they count from before any static constructor runs.
std::atomic<long long> gLiveBytes{0};
std::atomic<long long> gAllocations{0};
std::atomic<long long> gAllocatedBytes{0};
}  // namespace

namespace pivot::heap {

long long liveBytes() {
    return gLiveBytes.load();
}

long long allocations() {
    return gAllocations.load();
}

long long allocatedBytes() {
    return gAllocatedBytes.load();
}

}  // namespace pivot::heap

void* operator new(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (!p) throw std::bad_alloc();
    gLiveBytes += static_cast<long long>(malloc_usable_size(p));
    gAllocatedBytes += static_cast<long long>(size);
    ++gAllocations;
    return p;
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return operator new(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size) {
    return operator new(size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
    return operator new(size, tag);
}
void operator delete(void* p) noexcept {
    if (!p) return;
    gLiveBytes -= static_cast<long long>(malloc_usable_size(p));
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    operator delete(p);
}
void operator delete[](void* p) noexcept {
    operator delete(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    operator delete(p);
}
