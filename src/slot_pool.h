// Generational slot storage behind BodyId, ShapeId and JointId: objects live in one vector,
// freed slots are reused last-in first-out (deterministic), and each slot counts how often it
// was freed so a handle to a previous occupant is recognised as stale.
#pragma once

#include <cstdint>
#include <vector>

namespace pivot {

template <typename T>
class SlotPool {
public:
    struct Slot {
        T item{};
        std::uint32_t generation = 1;
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

    /// Frees the slot; its generation moves on so existing handles go stale.
    void erase(std::int32_t index) {
        Slot& slot = slots_[index];
        slot.item = T{};
        slot.alive = false;
        ++slot.generation;
        free_.push_back(index);
        --size_;
    }

    bool isAlive(std::int32_t index) const {
        return index >= 0 && index < capacity() && slots_[index].alive;
    }
    std::uint32_t generation(std::int32_t index) const { return slots_[index].generation; }
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

private:
    std::vector<Slot> slots_;
    std::vector<std::int32_t> free_;
    std::int32_t size_ = 0;
};

}  // namespace pivot
