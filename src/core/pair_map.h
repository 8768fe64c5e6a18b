// A hash map from an unordered pair of shape indices to a contact index, with open addressing
// and linear probing in two flat arrays (keys, values). It answers "does this pair already have
// a contact?" in O(1), and nothing ever iterates it, so its layout cannot leak into the order in
// which the solver sees contacts.
//
// Erasing shifts the entries after the hole back towards their home slots instead of leaving
// tombstones. With tombstones, contacts that come and go for ever fill the table with them and
// force a rebuild (an allocation) every few dozen steps; with backward shifting the table holds
// only live entries, so it allocates only when the number of live pairs reaches a new maximum.
#pragma once

#include <algorithm>
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
        const std::size_t slot = slotOf(k);
        return slot == kNone ? -1 : values_[slot];
    }

    /// Whether the pair is present: reads the keys only (the broad phase asks this of most
    /// pairs its queries report, and the answer is usually yes).
    bool contains(std::uint64_t k) const { return slotOf(k) != kNone; }

    /// Inserts a pair that is not present.
    void insert(std::uint64_t k, std::int32_t value) {
        if ((size_ + 1) * 4 > keys_.size() * 3) grow();
        std::size_t i = home(k);
        while (keys_[i] != kEmpty) i = next(i);
        keys_[i] = k;
        values_[i] = value;
        ++size_;
    }

    /// Removes a pair that is present (does nothing for one that is not).
    void erase(std::uint64_t k) {
        std::size_t hole = slotOf(k);
        if (hole == kNone) return;
        // Walk the rest of the cluster. An entry may move into the hole unless its home lies
        // cyclically in (hole, i]: then a lookup starting at its home would never pass the hole.
        for (std::size_t i = next(hole); keys_[i] != kEmpty; i = next(i)) {
            const std::size_t h = home(keys_[i]);
            const bool homeAfterHole = hole <= i ? (hole < h && h <= i) : (hole < h || h <= i);
            if (homeAfterHole) continue;
            keys_[hole] = keys_[i];
            values_[hole] = values_[i];
            hole = i;
        }
        keys_[hole] = kEmpty;
        --size_;
    }

    /// Empties the map, keeping its table.
    void clear() {
        std::fill(keys_.begin(), keys_.end(), kEmpty);
        size_ = 0;
    }

    std::size_t size() const { return size_; }
    std::size_t capacity() const { return keys_.size(); }

private:
    // No pair has this key: both halves would be 2^32 - 1, and shape indices are below 2^31.
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    static constexpr std::size_t kNone = ~std::size_t{0};

    std::size_t slotOf(std::uint64_t k) const {
        if (keys_.empty()) return kNone;
        for (std::size_t i = home(k);; i = next(i)) {
            if (keys_[i] == k) return i;
            if (keys_[i] == kEmpty) return kNone;
        }
    }

    std::size_t next(std::size_t i) const { return (i + 1) & (keys_.size() - 1); }
    std::size_t home(std::uint64_t k) const {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdull;
        k ^= k >> 33;
        return static_cast<std::size_t>(k) & (keys_.size() - 1);
    }

    // Doubles the table (the first one has 64 slots) and reinserts every entry.
    void grow() {
        std::vector<std::uint64_t> oldKeys;
        std::vector<std::int32_t> oldValues;
        oldKeys.swap(keys_);
        oldValues.swap(values_);
        const std::size_t slots = oldKeys.empty() ? 64 : oldKeys.size() * 2;
        keys_.assign(slots, kEmpty);
        values_.assign(slots, -1);
        size_ = 0;
        for (std::size_t i = 0; i < oldKeys.size(); ++i) {
            if (oldKeys[i] != kEmpty) insert(oldKeys[i], oldValues[i]);
        }
    }

    // Keys and values apart: a look-up walks the keys, eight to a cache line, and reads a value
    // only once it has found its key. Capacity is a power of two, at most three quarters full.
    std::vector<std::uint64_t> keys_;
    std::vector<std::int32_t> values_;
    std::size_t size_ = 0;
};

}  // namespace pivot
