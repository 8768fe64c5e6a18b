// The contact pair map against std::map, through long random runs of inserts and erases that
// wrap clusters around the end of the table, and its promise that churn does not grow it.
#include "core/pair_map.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <map>
#include <random>

using pivot::PairMap;

TEST(PairMap, AgreesWithAnOrderedMapThroughRandomChurn) {
    std::mt19937 random(7);
    PairMap map;
    std::map<std::uint64_t, std::int32_t> truth;
    for (int op = 0; op < 200000; ++op) {
        // Few distinct shapes, so keys collide in home slots and clusters form and wrap.
        const std::int32_t a = static_cast<std::int32_t>(random() % 60);
        const std::int32_t b = static_cast<std::int32_t>(random() % 60);
        const std::uint64_t k = PairMap::key(a, b);
        ASSERT_EQ(k, PairMap::key(b, a));
        const auto found = truth.find(k);
        ASSERT_EQ(map.contains(k), found != truth.end());
        if (found == truth.end()) {
            ASSERT_EQ(map.find(k), -1);
            if (random() % 3 != 0) {
                map.insert(k, op);
                truth[k] = op;
            }
        } else {
            ASSERT_EQ(map.find(k), found->second);
            if (random() % 2 == 0) {
                map.erase(k);
                truth.erase(found);
                ASSERT_EQ(map.find(k), -1);
            }
        }
        ASSERT_EQ(map.size(), truth.size());
        if (op % 5000 == 0) {
            for (const auto& [key, value] : truth) ASSERT_EQ(map.find(key), value);
        }
    }
}

TEST(PairMap, HoldsPairsOfTheLargestIndices) {
    // The empty slot's key has both halves 2^32 - 1, beyond any index: no pair collides with it.
    PairMap map;
    const std::int32_t top = std::numeric_limits<std::int32_t>::max();
    map.insert(PairMap::key(top, top - 1), 3);
    map.insert(PairMap::key(0, top), 4);
    EXPECT_EQ(map.find(PairMap::key(top - 1, top)), 3);
    EXPECT_EQ(map.find(PairMap::key(top, 0)), 4);
    EXPECT_FALSE(map.contains(PairMap::key(top, top - 2)));
    map.erase(PairMap::key(top, top - 1));
    EXPECT_FALSE(map.contains(PairMap::key(top, top - 1)));
    EXPECT_EQ(map.size(), 1u);
}

TEST(PairMap, ErasingAnAbsentPairChangesNothing) {
    PairMap map;
    map.erase(PairMap::key(1, 2));
    map.insert(PairMap::key(1, 2), 5);
    map.erase(PairMap::key(3, 4));
    EXPECT_EQ(map.size(), 1u);
    EXPECT_EQ(map.find(PairMap::key(2, 1)), 5);
}

// Pairs that come and go for ever, never more than 40 at once: the table keeps the size it
// grew to for 40 pairs (a tombstone scheme would have to rebuild it over and over).
TEST(PairMap, ChurnDoesNotGrowTheTable) {
    PairMap map;
    std::int32_t next = 0;
    for (int i = 0; i < 40; ++i, ++next) map.insert(PairMap::key(next, next + 1), next);
    const std::size_t capacity = map.capacity();
    for (int round = 0; round < 100000; ++round, ++next) {
        map.erase(PairMap::key(next - 40, next - 39));
        map.insert(PairMap::key(next, next + 1), next);
        ASSERT_EQ(map.capacity(), capacity);
    }
    EXPECT_EQ(map.size(), 40u);
    for (std::int32_t k = next - 40; k < next; ++k) EXPECT_EQ(map.find(PairMap::key(k, k + 1)), k);
}
