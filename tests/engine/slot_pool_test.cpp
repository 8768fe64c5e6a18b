// Generational slots: a handle to an object that was destroyed must stay stale for ever, even
// after its slot has been reused more times than the generation counter can count. The World
// uses 32-bit generations (2^32 create/destroy cycles of one slot take minutes); the same pool
// with 8- and 16-bit counters reaches the end of them in a few hundred or thousand cycles.
#include "core/slot_pool.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <utility>

using pivot::SlotPool;

namespace {

// Creates and destroys one object at a time, so the last-in first-out free list hands the
// same slot back every time, until it is retired; returns every (index, generation) issued.
template <typename Generation>
std::set<std::pair<std::int32_t, Generation>> cycle(SlotPool<int, Generation>& pool, int cycles) {
    std::set<std::pair<std::int32_t, Generation>> issued;
    for (int i = 0; i < cycles; ++i) {
        const std::int32_t index = pool.insert(i);
        const bool fresh = issued.insert({index, pool.generation(index)}).second;
        EXPECT_TRUE(fresh) << "handle (" << index << ", " << +pool.generation(index)
                           << ") issued twice at cycle " << i;
        pool.erase(index);
    }
    return issued;
}

}  // namespace

TEST(SlotPool, ASlotIsRetiredInsteadOfWrappingItsGeneration) {
    SlotPool<int, std::uint8_t> pool;
    // Generations 1 to 255 of slot 0, then slot 1 takes over.
    const auto issued = cycle(pool, 300);
    EXPECT_EQ(issued.size(), 300u);
    EXPECT_EQ(pool.retiredCount(), 1);
    EXPECT_EQ(pool.capacity(), 2);
    EXPECT_FALSE(pool.isAlive(0));
    EXPECT_EQ(pool.generation(0), 255);
    // The first handle of slot 0, (0, 1), can never match again: slot 0 is never reused.
    for (int i = 0; i < 1000; ++i) {
        const std::int32_t index = pool.insert(i);
        EXPECT_NE(index, 0);
        pool.erase(index);
    }
}

TEST(SlotPool, EveryHandleIsUniqueThroughSeveralWraps) {
    SlotPool<int, std::uint16_t> pool;
    const auto issued = cycle(pool, 3 * 65535 + 10);
    EXPECT_EQ(issued.size(), 3u * 65535u + 10u);
    EXPECT_EQ(pool.retiredCount(), 3);
    EXPECT_EQ(pool.size(), 0);
}

TEST(SlotPool, RetiringKeepsTheOtherSlotsInLastInFirstOutOrder) {
    SlotPool<int, std::uint8_t> pool;
    const std::int32_t a = pool.insert(1);
    const std::int32_t b = pool.insert(2);
    for (int i = 0; i < 254; ++i) {  // slot a reaches generation 255
        pool.erase(a);
        ASSERT_EQ(pool.insert(1), a);
    }
    ASSERT_EQ(pool.generation(a), 255);
    pool.erase(b);
    pool.erase(a);  // retired: b is the only free slot
    EXPECT_EQ(pool.insert(3), b);
    EXPECT_EQ(pool.insert(4), 2);  // a new slot, not a
}
