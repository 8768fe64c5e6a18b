// The dynamic AABB tree: structure after random edits, queries against brute force, balance,
// fat boxes and re-insertion on move, node reuse, rebuilds shared among threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

#include "collision/dynamic_tree.h"
#include "pivot/constants.h"

using namespace pivot;

namespace {

AABB boxAt(Vec2 centre, Vec2 halfExtents) {
    return {centre - halfExtents, centre + halfExtents};
}

AABB randomBox(std::mt19937& rng, float worldHalfWidth, float maxHalfExtent) {
    std::uniform_real_distribution<float> position(-worldHalfWidth, worldHalfWidth);
    std::uniform_real_distribution<float> extent(0.05f, maxHalfExtent);
    return boxAt({position(rng), position(rng)}, {extent(rng), extent(rng)});
}

AABB translated(const AABB& box, Vec2 d) {
    return {box.lower + d, box.upper + d};
}

std::vector<std::int32_t> queryIds(const DynamicTree& tree, const AABB& box) {
    std::vector<std::int32_t> ids;
    tree.query(box, [&](std::int32_t id) {
        ids.push_back(id);
        return true;
    });
    return ids;
}

std::vector<std::int32_t> bruteForceIds(const DynamicTree& tree,
                                        const std::vector<std::int32_t>& live, const AABB& box) {
    std::vector<std::int32_t> ids;
    for (std::int32_t id : live) {
        if (overlaps(tree.fatBox(id), box)) ids.push_back(id);
    }
    return ids;
}

// The balance bound the tests hold the tree to; an AVL tree stays below 1.44 log2(n + 2).
int heightBound(int proxyCount) {
    return static_cast<int>(2.0 * std::log2(static_cast<double>(proxyCount))) + 2;
}

void expectBoxEq(const AABB& actual, const AABB& expected) {
    EXPECT_EQ(actual.lower, expected.lower);
    EXPECT_EQ(actual.upper, expected.upper);
}

}  // namespace

TEST(DynamicTree, EmptyTree) {
    DynamicTree tree;
    EXPECT_EQ(tree.proxyCount(), 0);
    EXPECT_EQ(tree.height(), -1);
    EXPECT_TRUE(tree.isValid());
    EXPECT_TRUE(queryIds(tree, boxAt({0, 0}, {1e6f, 1e6f})).empty());
}

TEST(DynamicTree, CreateStoresTheBoxGrownByTheMarginAndTheUserData) {
    DynamicTree tree;
    const AABB tight{{1.0f, -2.0f}, {3.0f, 0.5f}};
    const std::int32_t id = tree.createProxy(tight, 42);
    const Vec2 margin{kAabbMargin, kAabbMargin};
    expectBoxEq(tree.fatBox(id), {tight.lower - margin, tight.upper + margin});
    EXPECT_EQ(tree.userData(id), 42);
    EXPECT_EQ(tree.proxyCount(), 1);
    EXPECT_EQ(tree.height(), 0);
    EXPECT_TRUE(tree.isValid());

    const std::int32_t other = tree.createProxy(boxAt({10, 10}, {1, 1}), 7);
    EXPECT_NE(other, id);
    EXPECT_EQ(tree.userData(other), 7);
    EXPECT_EQ(tree.userData(id), 42);
    EXPECT_EQ(tree.height(), 1);
    EXPECT_TRUE(tree.isValid());
}

TEST(DynamicTree, SmallMovesInsideTheFatBoxAreIgnored) {
    DynamicTree tree;
    const AABB tight = boxAt({0, 0}, {0.5f, 0.5f});
    const std::int32_t id = tree.createProxy(tight, 0);
    const AABB fat = tree.fatBox(id);

    // Anything up to the margin stays inside; the box must not change at all.
    for (Vec2 d : {Vec2{0.05f, 0.0f}, Vec2{-0.09f, 0.09f}, Vec2{0.0f, -0.1f}}) {
        EXPECT_FALSE(tree.moveProxy(id, translated(tight, d), d)) << d.x << " " << d.y;
        expectBoxEq(tree.fatBox(id), fat);
    }
    // A tight box that shrinks is still contained.
    EXPECT_FALSE(tree.moveProxy(id, boxAt({0, 0}, {0.1f, 0.1f}), Vec2{}));
    expectBoxEq(tree.fatBox(id), fat);
}

TEST(DynamicTree, LeavingTheFatBoxReinsertsStretchedAlongTheMotion) {
    DynamicTree tree;
    const std::int32_t id = tree.createProxy(boxAt({0, 0}, {0.5f, 0.5f}), 3);
    tree.createProxy(boxAt({5, 5}, {0.5f, 0.5f}), 4);  // so that re-insertion relinks nodes

    // Moving left and up: the box grows to the left (lower x) and upwards (upper y) only.
    const Vec2 d{-0.3f, 0.2f};
    const AABB tight = translated(boxAt({0, 0}, {0.5f, 0.5f}), d);
    EXPECT_TRUE(tree.moveProxy(id, tight, d));
    const Vec2 margin{kAabbMargin, kAabbMargin};
    const Vec2 ahead = kAabbMotionFactor * d;
    AABB expected{tight.lower - margin, tight.upper + margin};
    expected.lower.x += ahead.x;
    expected.upper.y += ahead.y;
    expectBoxEq(tree.fatBox(id), expected);
    EXPECT_EQ(tree.userData(id), 3);
    EXPECT_TRUE(tree.isValid());

    // Moving right and down: upper x and lower y.
    const Vec2 back{2.0f, -1.0f};
    const AABB tight2 = translated(tight, back);
    EXPECT_TRUE(tree.moveProxy(id, tight2, back));
    AABB expected2{tight2.lower - margin, tight2.upper + margin};
    expected2.upper.x += kAabbMotionFactor * back.x;
    expected2.lower.y += kAabbMotionFactor * back.y;
    expectBoxEq(tree.fatBox(id), expected2);
    EXPECT_TRUE(tree.isValid());

    // The stretched box covers the predicted path: the next step of the same motion is free.
    EXPECT_FALSE(tree.moveProxy(id, translated(tight2, back), back));
}

TEST(DynamicTree, ADestroyedProxysNodeIsReused) {
    DynamicTree tree;
    std::vector<std::int32_t> ids;
    for (int i = 0; i < 8; ++i) {
        ids.push_back(tree.createProxy(boxAt({2.0f * static_cast<float>(i), 0}, {0.5f, 0.5f}), i));
    }
    const std::int32_t maxId = *std::max_element(ids.begin(), ids.end());

    tree.destroyProxy(ids[3]);
    EXPECT_EQ(tree.proxyCount(), 7);
    EXPECT_TRUE(tree.isValid());
    const std::int32_t reused = tree.createProxy(boxAt({-3, 4}, {1, 1}), 99);
    EXPECT_EQ(reused, ids[3]);
    EXPECT_EQ(tree.userData(reused), 99);
    EXPECT_EQ(tree.proxyCount(), 8);
    EXPECT_TRUE(tree.isValid());

    // Freed nodes are reused last in, first out, so the pool never grows while the number of
    // proxies stays the same.
    for (int round = 0; round < 50; ++round) {
        const std::size_t slot = static_cast<std::size_t>(round % 8);
        const std::int32_t old = ids[slot];
        tree.destroyProxy(old);
        ids[slot] = tree.createProxy(boxAt({static_cast<float>(round), 1}, {0.5f, 0.5f}), round);
        EXPECT_EQ(ids[slot], old);
        EXPECT_LE(ids[slot], maxId);
        ASSERT_TRUE(tree.isValid());
    }
}

TEST(DynamicTree, RandomCreatesMovesAndDestroysKeepTheTreeValid) {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> action(0, 9);
        std::uniform_real_distribution<float> step(-1.0f, 1.0f);
        DynamicTree tree;
        std::vector<std::int32_t> live;
        std::vector<AABB> tight;  // by position in `live`
        int reinserted = 0;
        for (int op = 0; op < 3000; ++op) {
            const int a = action(rng);
            if (live.empty() || a < 3) {
                const AABB box = randomBox(rng, 40.0f, 2.0f);
                live.push_back(tree.createProxy(box, op));
                tight.push_back(box);
            } else if (a < 5) {
                std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
                const std::size_t i = pick(rng);
                tree.destroyProxy(live[i]);
                live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
                tight.erase(tight.begin() + static_cast<std::ptrdiff_t>(i));
            } else {
                std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
                const std::size_t i = pick(rng);
                const float scale = a == 9 ? 20.0f : 0.3f;
                const Vec2 d{scale * step(rng), scale * step(rng)};
                tight[i] = translated(tight[i], d);
                if (tree.moveProxy(live[i], tight[i], d)) ++reinserted;
                ASSERT_TRUE(contains(tree.fatBox(live[i]), tight[i]));
            }
            ASSERT_TRUE(tree.isValid()) << "seed " << seed << " op " << op;
            ASSERT_EQ(tree.proxyCount(), static_cast<int>(live.size()));
        }
        EXPECT_GT(reinserted, 100) << "seed " << seed;
        // Every proxy's fat box still holds its current tight box.
        for (std::size_t i = 0; i < live.size(); ++i) {
            EXPECT_TRUE(contains(tree.fatBox(live[i]), tight[i]));
        }
        // Emptying the tree returns every node to the free list.
        for (std::int32_t id : live) tree.destroyProxy(id);
        EXPECT_EQ(tree.proxyCount(), 0);
        EXPECT_EQ(tree.height(), -1);
        EXPECT_TRUE(tree.isValid());
    }
}

TEST(DynamicTree, QueriesMatchABruteForceScan) {
    for (std::uint32_t seed : {11u, 12u, 13u}) {
        std::mt19937 rng(seed);
        DynamicTree tree;
        std::vector<std::int32_t> live;
        std::vector<AABB> tight;
        for (int i = 0; i < 600; ++i) {
            tight.push_back(randomBox(rng, 50.0f, 3.0f));
            live.push_back(tree.createProxy(tight.back(), i));
        }
        std::uniform_real_distribution<float> step(-2.0f, 2.0f);
        for (std::size_t i = 0; i < live.size(); i += 2) {
            const Vec2 d{step(rng), step(rng)};
            tight[i] = translated(tight[i], d);
            tree.moveProxy(live[i], tight[i], d);
        }
        for (std::size_t i = 0; i < live.size(); i += 7) tree.destroyProxy(live[i]);
        std::vector<std::int32_t> remaining;
        for (std::size_t i = 0; i < live.size(); ++i) {
            if (i % 7 != 0) remaining.push_back(live[i]);
        }
        ASSERT_TRUE(tree.isValid());

        std::size_t totalHits = 0;
        for (int q = 0; q < 300; ++q) {
            const AABB box = randomBox(rng, 55.0f, q % 10 == 0 ? 20.0f : 4.0f);
            std::vector<std::int32_t> found = queryIds(tree, box);
            std::vector<std::int32_t> expected = bruteForceIds(tree, remaining, box);
            std::sort(found.begin(), found.end());
            std::sort(expected.begin(), expected.end());
            // Equal sorted lists also rule out a proxy being visited twice.
            ASSERT_EQ(found, expected) << "seed " << seed << " query " << q;
            totalHits += found.size();
        }
        EXPECT_GT(totalHits, 300u);  // the queries do find things
    }
}

TEST(DynamicTree, AQueryStopsWhenVisitReturnsFalse) {
    DynamicTree tree;
    for (int i = 0; i < 20; ++i) tree.createProxy(boxAt({0, 0}, {1, 1}), i);
    int visits = 0;
    tree.query(boxAt({0, 0}, {0.5f, 0.5f}), [&](std::int32_t) {
        ++visits;
        return visits < 3;
    });
    EXPECT_EQ(visits, 3);
}

TEST(DynamicTree, StaysBalancedForRandomProxies) {
    std::mt19937 rng(5);
    DynamicTree tree;
    std::vector<std::int32_t> ids;
    for (int i = 0; i < 4000; ++i) ids.push_back(tree.createProxy(randomBox(rng, 100, 2), i));
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));

    // Removing every other proxy must rebalance too.
    for (std::size_t i = 0; i < ids.size(); i += 2) tree.destroyProxy(ids[i]);
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));
}

TEST(DynamicTree, StaysBalancedForProxiesInsertedInOrderAlongALine) {
    // Sorted insertion is the classic way to degrade an unbalanced tree into a list.
    DynamicTree tree;
    std::vector<std::int32_t> ids;
    for (int i = 0; i < 4000; ++i) {
        ids.push_back(tree.createProxy(boxAt({static_cast<float>(i), 0}, {0.4f, 0.4f}), i));
        if (i % 500 == 0) {
            ASSERT_LE(tree.height(), heightBound(i + 1)) << i;
        }
    }
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));

    // And moving them all one after another along the line, far enough to be re-inserted.
    for (std::int32_t id : ids) {
        const AABB box = tree.fatBox(id);
        const Vec2 d{0.0f, 3.0f};
        const AABB tight{box.lower + Vec2{kAabbMargin, kAabbMargin} + d,
                         box.upper - Vec2{kAabbMargin, kAabbMargin} + d};
        ASSERT_TRUE(tree.moveProxy(id, tight, d));
    }
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));
}

TEST(DynamicTree, StaysBalancedForIdenticalBoxes) {
    // Every insertion costs the same everywhere, so the heuristic alone would build a chain.
    DynamicTree tree;
    for (int i = 0; i < 2000; ++i) tree.createProxy(boxAt({1, 1}, {1, 1}), i);
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));
    EXPECT_EQ(queryIds(tree, boxAt({1, 1}, {0.1f, 0.1f})).size(), 2000u);
}

TEST(DynamicTree, StaysBalancedWhenEachNewBoxEnclosesAllBefore) {
    // Each new leaf is cheapest paired with the root itself, so one rotation per level is not
    // enough: the new root starts out a whole tree taller on one side.
    DynamicTree tree;
    for (int i = 0; i < 2000; ++i) {
        const float half = 1.0f + 0.01f * static_cast<float>(i);
        tree.createProxy(boxAt({0.001f * static_cast<float>(i), 0}, {half, half}), i);
        if (i % 250 == 0) {
            ASSERT_TRUE(tree.isValid()) << i;
        }
    }
    EXPECT_TRUE(tree.isValid());
    EXPECT_LE(tree.height(), heightBound(tree.proxyCount()));
}

TEST(InlineStack, SpillsBeyondItsInlineCapacityAndStaysLastInFirstOut) {
    InlineStack<int, 4> stack;
    EXPECT_TRUE(stack.empty());
    for (int i = 0; i < 10; ++i) stack.push(i);
    EXPECT_EQ(stack.size(), 10u);
    for (int i = 9; i >= 6; --i) EXPECT_EQ(stack.pop(), i);
    // Interleaving across the boundary between the inline part and the spill.
    stack.push(100);
    stack.push(101);
    EXPECT_EQ(stack.pop(), 101);
    EXPECT_EQ(stack.pop(), 100);
    for (int i = 5; i >= 0; --i) EXPECT_EQ(stack.pop(), i);
    EXPECT_TRUE(stack.empty());
    // Refilling after the spill emptied uses the inline part first, then spills again.
    for (int i = 0; i < 6; ++i) stack.push(20 + i);
    for (int i = 5; i >= 0; --i) EXPECT_EQ(stack.pop(), 20 + i);
    EXPECT_TRUE(stack.empty());
}

TEST(DynamicTree, ABoxStretchedByAFastMoveShrinksOnceTheShapeSlows) {
    DynamicTree tree;
    const AABB tight = boxAt({0, 0}, {0.5f, 0.5f});
    const std::int32_t id = tree.createProxy(tight, 1);
    // A fast move stretches the box 4 x 3 m ahead.
    const Vec2 fast{3.0f, 0.0f};
    const AABB moved = translated(tight, fast);
    ASSERT_TRUE(tree.moveProxy(id, moved, fast));
    const float stretchedWidth = tree.fatBox(id).upper.x - tree.fatBox(id).lower.x;
    EXPECT_GT(stretchedWidth, 12.0f);
    // The shape stops inside the stretched box: the box is now oversized and is shrunk.
    const AABB still = translated(moved, {0.1f, 0.0f});
    EXPECT_TRUE(tree.moveProxy(id, still, {0.1f, 0.0f}));
    const AABB& shrunk = tree.fatBox(id);
    EXPECT_LT(shrunk.upper.x - shrunk.lower.x, 2.0f);
    EXPECT_TRUE(tree.isValid());
    // Small moves inside a right-sized box are still free.
    EXPECT_FALSE(tree.moveProxy(id, translated(still, {0.02f, 0.0f}), {0.02f, 0.0f}));
}

// --- refitProxy and rebuildChanged (BroadPhaseBoxes::Compact) ----------------------------------

TEST(DynamicTree, RefitMovesAndPartialRebuildsKeepTheTreeValidAndQueriesExact) {
    for (std::uint32_t seed : {5u, 6u, 7u}) {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> action(0, 19);
        std::uniform_real_distribution<float> step(-1.0f, 1.0f);
        DynamicTree tree;
        std::vector<std::int32_t> live;
        std::vector<AABB> tight;
        int moved = 0;
        for (int op = 0; op < 3000; ++op) {
            const int a = action(rng);
            if (live.empty() || a < 4) {
                const AABB box = randomBox(rng, 40.0f, 2.0f);
                live.push_back(tree.createProxy(box, op));
                tight.push_back(box);
            } else if (a < 6) {
                std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
                const std::size_t i = pick(rng);
                tree.destroyProxy(live[i]);
                live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
                tight.erase(tight.begin() + static_cast<std::ptrdiff_t>(i));
            } else if (a == 6) {
                tree.rebuildChanged();
            } else {
                std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
                const std::size_t i = pick(rng);
                const float scale = a >= 17 ? 20.0f : 0.3f;
                tight[i] = translated(tight[i], {scale * step(rng), scale * step(rng)});
                if (tree.refitProxy(live[i], tight[i])) ++moved;
                ASSERT_TRUE(contains(tree.fatBox(live[i]), tight[i]));
            }
            // Creations and destructions between refits and rebuilds (their rotations too) must
            // keep the marks a subtree at the top, which isValid checks.
            ASSERT_TRUE(tree.isValid()) << "seed " << seed << " op " << op;
        }
        EXPECT_GT(moved, 300) << "seed " << seed;
        std::size_t hits = 0;
        for (int q = 0; q < 200; ++q) {
            const AABB box = randomBox(rng, 45.0f, q % 10 == 0 ? 20.0f : 4.0f);
            std::vector<std::int32_t> found = queryIds(tree, box);
            std::vector<std::int32_t> expected = bruteForceIds(tree, live, box);
            std::sort(found.begin(), found.end());
            std::sort(expected.begin(), expected.end());
            ASSERT_EQ(found, expected) << "seed " << seed << " query " << q;
            hits += found.size();
        }
        EXPECT_GT(hits, 200u);
    }
}

TEST(DynamicTree, ARebuildRegroupsLeavesThatTravelled) {
    std::mt19937 rng(3);
    DynamicTree tree;
    std::vector<std::int32_t> ids;
    std::vector<AABB> tight;
    for (int i = 0; i < 500; ++i) {
        tight.push_back(randomBox(rng, 50.0f, 0.5f));
        ids.push_back(tree.createProxy(tight.back(), i));
    }
    const float settled = tree.cost();
    // Every leaf jumps somewhere else: refitted in place, the groups now span the whole world.
    for (std::size_t i = 0; i < ids.size(); ++i) {
        tight[i] = randomBox(rng, 50.0f, 0.5f);
        ASSERT_TRUE(tree.refitProxy(ids[i], tight[i]));
    }
    const float scattered = tree.cost();
    EXPECT_GT(scattered, 5.0f * settled);
    tree.rebuildChanged();
    ASSERT_TRUE(tree.isValid());
    EXPECT_LT(tree.cost(), 1.5f * settled);
    EXPECT_LE(tree.height(), 3 * heightBound(500));
    for (std::size_t i = 0; i < ids.size(); ++i)
        EXPECT_TRUE(contains(tree.fatBox(ids[i]), tight[i]));
}

// A rebuild whose subtrees are built by other threads, in another order, must make the tree the
// one-thread rebuild makes, node for node: the broad phase shares it out among a world's
// workers, and a world's results may not depend on how many it has.
TEST(DynamicTree, ASharedRebuildMakesTheTreeTheOneThreadRebuildMakes) {
    for (const int count : {300, 3000, 20000}) {
        std::mt19937 rng(static_cast<std::uint32_t>(count));
        DynamicTree alone;
        DynamicTree shared;
        std::vector<std::int32_t> ids;
        std::vector<AABB> tight;
        for (int i = 0; i < count; ++i) {
            tight.push_back(randomBox(rng, 200.0f, 0.5f));
            ids.push_back(alone.createProxy(tight.back(), i));
            ASSERT_EQ(shared.createProxy(tight.back(), i), ids.back());
        }
        for (int round = 0; round < 3; ++round) {
            // Some leaves jump far, most stay: the rebuild keeps the subtrees they left alone.
            std::uniform_int_distribution<int> jump(0, 3);
            for (std::size_t i = 0; i < ids.size(); ++i) {
                if (jump(rng) != 0) continue;
                tight[i] = randomBox(rng, 200.0f, 0.5f);
                ASSERT_EQ(alone.refitProxy(ids[i], tight[i]), shared.refitProxy(ids[i], tight[i]));
            }
            alone.rebuildChanged();
            int subtrees = 0;
            shared.rebuildChanged([&](int n, const auto& build) {
                subtrees = n;
                // Last first: every second subtree from the last on another thread, the rest here.
                std::thread other([&] {
                    for (int i = n - 1; i >= 0; i -= 2) build(i);
                });
                for (int i = n - 2; i >= 0; i -= 2) build(i);
                other.join();
            });
            // Big rebuilds are shared out; small ones stay whole.
            if (count >= 3000) {
                EXPECT_GT(subtrees, 1) << count;
            } else {
                EXPECT_EQ(subtrees, 1) << count;
            }
            ASSERT_TRUE(shared.isValid());
            SnapshotWriter a;
            SnapshotWriter b;
            alone.save(a);
            shared.save(b);
            ASSERT_EQ(a.bytes(), b.bytes()) << count << " round " << round;
        }
    }
}

TEST(DynamicTree, ALeafMovingInsideItsGroupsBoxLeavesTheTreeAsItWas) {
    DynamicTree tree;
    // Two leaves far apart: their parent's box spans the gap, so the first can move about in
    // it without growing anything.
    const AABB a = boxAt({0, 0}, {0.5f, 0.5f});
    const std::int32_t first = tree.createProxy(a, 1);
    tree.createProxy(boxAt({10, 0}, {0.5f, 0.5f}), 2);
    const float before = tree.cost();
    ASSERT_TRUE(tree.refitProxy(first, translated(a, {5.0f, 0.0f})));
    tree.rebuildChanged();
    EXPECT_EQ(tree.cost(), before);  // the parent's box was not refitted to its children
    // Moving beyond the group grows the parent (to x = 20.6) and marks it; the rebuild fits it
    // to its children again (from x = 9.4).
    ASSERT_TRUE(tree.refitProxy(first, translated(a, {20.0f, 0.0f})));
    EXPECT_GT(tree.cost(), before);
    tree.rebuildChanged();
    EXPECT_TRUE(tree.isValid());
    const float m = kAabbMargin;
    EXPECT_FLOAT_EQ(tree.cost(), perimeter(boxAt({15.0f, 0.0f}, {5.5f + m, 0.5f + m})));
}
