// A hash map from an unordered pair of shape indices to a contact index, with open addressing
// and linear probing in one flat array. It answers "does this pair already have a contact?"
// in O(1) without allocating once grown, and nothing ever iterates it, so its layout cannot
// leak into the order in which the solver sees contacts.
#pragma once

#include <cstdint>
#include <vector>

namespace pivot {

class PairMap {
public:
    static std::uint64_t key(std::int32_t a, std::int32_t b) {
        std::uint32_t lo = static_cast<std::uint32_t>(a < b ? a : b);
        std::uint32_t hi = static_cast<std::uint32_t>(a < b ? b : a);
        return (std::uint64_t(hi) << 32) | lo;
    }

    /// The value stored for the pair, or -1.
    std::int32_t find(std::uint64_t k) const {
        if (slots_.empty()) return -1;
        for (std::size_t i = home(k);; i = (i + 1) & mask()) {
            const Slot& s = slots_[i];
            if (s.value == kEmpty) return -1;
            if (s.value != kTombstone && s.key == k) return s.value;
        }
    }

    /// Inserts a pair that is not present.
    void insert(std::uint64_t k, std::int32_t value) {
        if ((used_ + 1) * 4 > slots_.size() * 3) rehash(slots_.empty() ? 64 : slots_.size() * 2);
        std::size_t i = home(k);
        while (slots_[i].value >= 0) i = (i + 1) & mask();
        if (slots_[i].value == kEmpty) ++used_;
        slots_[i] = {k, value};
        ++size_;
    }

    /// Removes a pair that is present.
    void erase(std::uint64_t k) {
        for (std::size_t i = home(k);; i = (i + 1) & mask()) {
            Slot& s = slots_[i];
            if (s.value == kEmpty) return;
            if (s.value != kTombstone && s.key == k) {
                s.value = kTombstone;
                --size_;
                return;
            }
        }
    }

    std::size_t size() const { return size_; }

private:
    static constexpr std::int32_t kEmpty = -1;
    static constexpr std::int32_t kTombstone = -2;
    struct Slot {
        std::uint64_t key = 0;
        std::int32_t value = kEmpty;
    };

    std::size_t mask() const { return slots_.size() - 1; }
    std::size_t home(std::uint64_t k) const {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdull;
        k ^= k >> 33;
        return static_cast<std::size_t>(k) & mask();
    }

    // Grows (or just clears tombstones) by reinserting every live entry.
    void rehash(std::size_t capacity) {
        if (size_ * 2 < slots_.size() && !slots_.empty()) capacity = slots_.size();
        std::vector<Slot> old;
        old.swap(slots_);
        slots_.assign(capacity, Slot{});
        used_ = 0;
        size_ = 0;
        for (const Slot& s : old) {
            if (s.value >= 0) insert(s.key, s.value);
        }
    }

    std::vector<Slot> slots_;  // capacity is a power of two
    std::size_t used_ = 0;     // live entries plus tombstones
    std::size_t size_ = 0;     // live entries
};

}  // namespace pivot
