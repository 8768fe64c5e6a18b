// A hash map from an unordered pair of shape indices to a contact index, with open addressing
// and linear probing in one flat array. It answers "does this pair already have a contact?"
// in O(1), and nothing ever iterates it, so its layout cannot leak into the order in which the
// solver sees contacts.
//
// Erasing shifts the entries after the hole back towards their home slots instead of leaving
// tombstones. With tombstones, contacts that come and go for ever fill the table with them and
// force a rebuild (an allocation) every few dozen steps; with backward shifting the table holds
// only live entries, so it allocates only when the number of live pairs reaches a new maximum.
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
        for (std::size_t i = home(k);; i = next(i)) {
            const Slot& s = slots_[i];
            if (s.value == kEmpty) return -1;
            if (s.key == k) return s.value;
        }
    }

    /// Inserts a pair that is not present.
    void insert(std::uint64_t k, std::int32_t value) {
        if ((size_ + 1) * 4 > slots_.size() * 3) grow();
        std::size_t i = home(k);
        while (slots_[i].value != kEmpty) i = next(i);
        slots_[i] = {k, value};
        ++size_;
    }

    /// Removes a pair that is present (does nothing for one that is not).
    void erase(std::uint64_t k) {
        if (slots_.empty()) return;
        std::size_t hole = home(k);
        for (;; hole = next(hole)) {
            if (slots_[hole].value == kEmpty) return;
            if (slots_[hole].key == k) break;
        }
        // Walk the rest of the cluster. An entry may move into the hole unless its home lies
        // cyclically in (hole, i]: then a lookup starting at its home would never pass the hole.
        for (std::size_t i = next(hole); slots_[i].value != kEmpty; i = next(i)) {
            const std::size_t h = home(slots_[i].key);
            const bool homeAfterHole = hole <= i ? (hole < h && h <= i) : (hole < h || h <= i);
            if (homeAfterHole) continue;
            slots_[hole] = slots_[i];
            hole = i;
        }
        slots_[hole] = Slot{};
        --size_;
    }

    std::size_t size() const { return size_; }
    std::size_t capacity() const { return slots_.size(); }

private:
    static constexpr std::int32_t kEmpty = -1;
    struct Slot {
        std::uint64_t key = 0;
        std::int32_t value = kEmpty;
    };

    std::size_t next(std::size_t i) const { return (i + 1) & (slots_.size() - 1); }
    std::size_t home(std::uint64_t k) const {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdull;
        k ^= k >> 33;
        return static_cast<std::size_t>(k) & (slots_.size() - 1);
    }

    // Doubles the table (the first one has 64 slots) and reinserts every entry.
    void grow() {
        std::vector<Slot> old;
        old.swap(slots_);
        slots_.assign(old.empty() ? 64 : old.size() * 2, Slot{});
        size_ = 0;
        for (const Slot& s : old) {
            if (s.value != kEmpty) insert(s.key, s.value);
        }
    }

    std::vector<Slot> slots_;  // capacity is a power of two, at most three quarters full
    std::size_t size_ = 0;
};

}  // namespace pivot
