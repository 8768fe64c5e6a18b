// Counts what goes through the global operator new, which counting_new.cpp replaces (with
// delete) for the whole program. It is the pivot_counting_new OBJECT library: linked as an
// object, the replacement is in every program that links it, whatever the program calls and
// whatever the order in which the linker reads archives.
#pragma once

namespace pivot::heap {

/// Bytes held by blocks from operator new not yet deleted, each counted as malloc's usable size
/// of the block (works under AddressSanitizer too). malloc alone is not counted: Box2D's
/// allocations are not.
long long liveBytes();

/// Calls of operator new (every form) since the program started.
long long allocations();

/// Bytes asked of operator new since the program started (freed or not).
long long allocatedBytes();

/// What went through operator new since it was made or reset.
class Counter {
public:
    Counter() { reset(); }
    void reset() {
        allocationsAtStart_ = heap::allocations();
        allocatedAtStart_ = heap::allocatedBytes();
        bytesAtStart_ = heap::liveBytes();
    }
    long long allocations() const { return heap::allocations() - allocationsAtStart_; }
    /// Bytes asked of operator new meanwhile, freed or not.
    long long allocatedBytes() const { return heap::allocatedBytes() - allocatedAtStart_; }
    /// Growth of the live bytes (negative when more was freed than allocated).
    long long bytes() const { return heap::liveBytes() - bytesAtStart_; }

private:
    long long allocationsAtStart_ = 0;
    long long allocatedAtStart_ = 0;
    long long bytesAtStart_ = 0;
};

}  // namespace pivot::heap
