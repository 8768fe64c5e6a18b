// Generational slot storage behind BodyId, ShapeId and JointId: objects live in one vector,
// freed slots are reused last-in first-out (deterministic), and each slot counts how often it
// was freed so a handle to a previous occupant is recognised as stale.
//
// A generation never wraps: a slot freed at the last generation its counter can hold is
// retired, never reused, because a wrapped counter would make every handle to its earliest
// occupants valid again. With 32-bit generations that costs one slot per 2^32 - 1 objects
// created in it. The counter's width is a parameter so that the tests can reach the end of it.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pivot {

template <typename T, typename Generation = std::uint32_t>
class SlotPool {
public:
    static constexpr Generation kLastGeneration = std::numeric_limits<Generation>::max();

    struct Slot {
        T item{};
        Generation generation = 1;
        bool alive = false;
    };

    /// Stores item and returns its slot index.
    std::int32_t insert(const T& item) {
        std::int32_t index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = static_cast<std::int32_t>(slots_.size());
            slots_.emplace_back();
        }
        slots_[index].item = item;
        slots_[index].alive = true;
        ++size_;
        return index;
    }

    /// Frees the slot; its generation moves on so existing handles go stale. A slot at its
    /// last generation is retired instead.
    void erase(std::int32_t index) {
        Slot& slot = slots_[index];
        slot.item = T{};
        slot.alive = false;
        --size_;
        if (slot.generation == kLastGeneration) {
            ++retired_;
            return;
        }
        ++slot.generation;
        free_.push_back(index);
    }

    bool isAlive(std::int32_t index) const {
        return index >= 0 && index < capacity() && slots_[index].alive;
    }
    Generation generation(std::int32_t index) const { return slots_[index].generation; }
    /// Slots retired because their generation reached kLastGeneration.
    std::int32_t retiredCount() const { return retired_; }
    std::int32_t capacity() const { return static_cast<std::int32_t>(slots_.size()); }
    std::int32_t size() const { return size_; }

    T& operator[](std::int32_t index) { return slots_[index].item; }
    const T& operator[](std::int32_t index) const { return slots_[index].item; }

    /// Calls f(index, item) for every live item in slot order.
    template <typename F>
    void forEach(F&& f) {
        for (std::int32_t i = 0; i < capacity(); ++i) {
            if (slots_[i].alive) f(i, slots_[i].item);
        }
    }
    template <typename F>
    void forEach(F&& f) const {
        for (std::int32_t i = 0; i < capacity(); ++i) {
            if (slots_[i].alive) f(i, slots_[i].item);
        }
    }

    /// Snapshots (core/snapshot_io.h): every slot's generation and liveness, the live items
    /// (through `item(io, T&)`), and the free list in its order, so a restored pool hands out the
    /// same slots and generations. Reading checks the free list names dead slots once each. Each
    /// slot is charged its own size and `bytesPerSlot` more (what restore sizes by the pool).
    template <typename Io, typename Pool, typename Item>
    static void describe(Io& io, Pool& pool, Item&& item, std::size_t bytesPerSlot) {
        if constexpr (Io::kReading) {
            const std::size_t n = io.count(sizeof(Generation) + 1);
            io.charge(n * (sizeof(Slot) + bytesPerSlot));
            pool.slots_.assign(n, Slot{});
        } else {
            io.count(pool.slots_.size());
            io.charge(pool.slots_.size() * (sizeof(Slot) + bytesPerSlot));
        }
        for (auto& slot : pool.slots_) {
            io.value(slot.generation);
            io.value(slot.alive);
            if (slot.alive) item(io, slot.item);
        }
        io.sequence(pool.free_, [&](auto& index) { io.value(index); });
        io.value(pool.retired_);
        if constexpr (Io::kReading) {
            pool.size_ = 0;
            for (const Slot& slot : pool.slots_) pool.size_ += slot.alive ? 1 : 0;
            std::vector<bool> listed(pool.slots_.size(), false);
            for (const std::int32_t index : pool.free_) {
                if (index < 0 || index >= pool.capacity() || pool.slots_[index].alive ||
                    listed[static_cast<std::size_t>(index)]) {
                    io.corrupt("a free list names slot " + std::to_string(index));
                }
                listed[static_cast<std::size_t>(index)] = true;
            }
            const auto dead = static_cast<std::size_t>(pool.capacity() - pool.size_);
            if (pool.retired_ < 0 || dead != pool.free_.size() + std::size_t(pool.retired_)) {
                io.corrupt("a pool's free and retired slots do not add up");
            }
        }
    }

private:
    std::vector<Slot> slots_;
    std::vector<std::int32_t> free_;
    std::int32_t size_ = 0;
    std::int32_t retired_ = 0;
};

}  // namespace pivot
