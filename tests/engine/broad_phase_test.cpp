// The broad phase against brute force: a contact manager's view of the pairs it reports must
// match every overlapping pair of fat boxes, through creation, motion and destruction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "collision/broad_phase.h"
#include "pivot/constants.h"

using namespace pivot;

namespace {

using UserPair = std::pair<std::int32_t, std::int32_t>;

AABB boxAt(Vec2 centre, Vec2 halfExtents) {
    return {centre - halfExtents, centre + halfExtents};
}

AABB translated(const AABB& box, Vec2 d) {
    return {box.lower + d, box.upper + d};
}

UserPair ordered(std::int32_t a, std::int32_t b) {
    return {std::min(a, b), std::max(a, b)};
}

std::vector<UserPair> update(BroadPhase& broadPhase) {
    std::vector<UserPair> pairs;
    broadPhase.updatePairs([&](std::int32_t userDataA, std::int32_t userDataB) {
        pairs.push_back({userDataA, userDataB});
    });
    return pairs;
}

// A body of the randomised scene, keyed by its user data (unique for the whole run, unlike
// proxy ids, which are reused).
struct SceneBody {
    std::int32_t proxy;
    AABB tight;
    Vec2 velocity;
    bool onStatic;       // a static body's: moves only by a jump now and then
    bool swept = false;  // this round, under Compact: moved further than its tree's margin
    AABB sweep;          // then: its start and end boxes together, fattened by that margin
};

AABB fattened(const AABB& box, float margin) {
    return {box.lower - Vec2{margin, margin}, box.upper + Vec2{margin, margin}};
}

// Plays a contact manager over a random scene for `rounds` rounds and checks after each
// update that the pairs it knows are exactly the overlapping pairs of live fat boxes (under
// Compact, but for pairs of two static bodies' proxies, which it never reports), together with
// (under Compact) the pairs of a sweep made this round with a fat box it overlaps.
// Returns the number of pairs reported, so callers can check the scene was not trivial.
std::size_t runRandomScene(std::uint32_t seed, int rounds,
                           BroadPhaseBoxes boxes = BroadPhaseBoxes::Predictive) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> symmetric(-1.0f, 1.0f);
    const float worldHalfWidth = 25.0f;
    auto randomTight = [&]() {
        const Vec2 centre{worldHalfWidth * symmetric(rng), worldHalfWidth * symmetric(rng)};
        return boxAt(centre, {0.1f + 1.5f * unit(rng), 0.1f + 1.5f * unit(rng)});
    };

    BroadPhase broadPhase;
    broadPhase.setBoxes(boxes);
    std::map<std::int32_t, SceneBody> bodies;
    std::set<UserPair> known;  // (smaller user data, larger user data)
    std::int32_t nextUserData = 1000;
    std::size_t reported = 0;

    for (int round = 0; round < rounds; ++round) {
        // Create a few bodies (more at the start, to fill the scene).
        const int creations = round < 10 ? 30 : static_cast<int>(unit(rng) * 6.0f);
        for (int i = 0; i < creations; ++i) {
            const AABB tight = randomTight();
            const std::int32_t userData = nextUserData++;
            const Vec2 velocity{symmetric(rng), symmetric(rng)};
            const bool onStatic = unit(rng) < 0.25f;
            bodies[userData] = {broadPhase.createProxy(tight, userData, onStatic),
                                tight,
                                velocity,
                                onStatic,
                                false,
                                AABB{}};
        }
        const bool staticPairs = boxes == BroadPhaseBoxes::Predictive;
        auto reportable = [&](const SceneBody& a, const SceneBody& b) {
            return staticPairs || !(a.onStatic && b.onStatic);
        };

        // Now and then a body changes type (its proxy may change trees, and id).
        for (auto& [userData, body] : bodies) {
            if (unit(rng) < 0.005f) {
                body.onStatic = !body.onStatic;
                const std::int32_t before = body.proxy;
                body.proxy = broadPhase.setOnStaticBody(body.proxy, body.tight, body.onStatic);
                EXPECT_EQ(body.proxy != before, boxes == BroadPhaseBoxes::Compact);
            }
        }

        // Destroy a few, with their contacts.
        for (auto it = bodies.begin(); it != bodies.end();) {
            if (unit(rng) < 0.02f) {
                broadPhase.destroyProxy(it->second.proxy);
                const std::int32_t gone = it->first;
                for (auto k = known.begin(); k != known.end();) {
                    k = (k->first == gone || k->second == gone) ? known.erase(k) : std::next(k);
                }
                it = bodies.erase(it);
            } else {
                ++it;
            }
        }

        // Move most of them: a random walk at varied speeds, and now and then a jump.
        for (auto& [userData, body] : bodies) {
            const float r = unit(rng);
            if (r < 0.2f || (body.onStatic && r > 0.21f)) continue;  // resting
            Vec2 d;
            if (r < 0.22f) {
                const AABB target = randomTight();
                d = 0.5f * ((target.lower + target.upper) - (body.tight.lower + body.tight.upper));
            } else {
                body.velocity += 0.2f * Vec2{symmetric(rng), symmetric(rng)};
                const float speed = r < 0.8f ? 0.05f : 0.6f;
                d = speed * body.velocity;
            }
            const AABB from = body.tight;
            body.tight = translated(body.tight, d);
            body.swept = false;
            // Keep the scene dense: wrap bodies that drift far off back to the other side.
            const Vec2 centre = 0.5f * (body.tight.lower + body.tight.upper);
            if (centre.x > 2.0f * worldHalfWidth || centre.x < -2.0f * worldHalfWidth) {
                body.tight = translated(body.tight, {-centre.x, 0.0f});
            }
            if (centre.y > 2.0f * worldHalfWidth || centre.y < -2.0f * worldHalfWidth) {
                body.tight = translated(body.tight, {0.0f, -centre.y});
            }
            broadPhase.moveProxy(body.proxy, from, body.tight);
            if (boxes == BroadPhaseBoxes::Compact) {
                const float margin = body.onStatic ? kCompactStaticAabbMargin : kCompactAabbMargin;
                body.swept = !contains(fattened(body.tight, margin), from);
                body.sweep = fattened(combine(from, body.tight), margin);
            }
        }

        // Now and then a filter change asks for a body's pairs again.
        for (auto& [userData, body] : bodies) {
            if (unit(rng) < 0.01f) broadPhase.touchProxy(body.proxy);
        }

        // Whether the broad phase owes a and b a pair this round.
        auto pairedNow = [&](const SceneBody& a, const SceneBody& b) {
            const AABB& fatA = broadPhase.fatBox(a.proxy);
            const AABB& fatB = broadPhase.fatBox(b.proxy);
            return reportable(a, b) &&
                   (overlaps(fatA, fatB) || (a.swept && overlaps(a.sweep, fatB)) ||
                    (b.swept && overlaps(b.sweep, fatA)));
        };

        // The contact manager drops contacts whose fat boxes parted (or that became static)...
        for (auto k = known.begin(); k != known.end();) {
            const SceneBody& a = bodies.at(k->first);
            const SceneBody& b = bodies.at(k->second);
            const bool keep = broadPhase.testOverlap(a.proxy, b.proxy) && reportable(a, b);
            k = keep ? std::next(k) : known.erase(k);
        }

        // ...and adds the new ones the broad phase finds.
        std::vector<std::pair<std::int32_t, std::int32_t>> callProxies;
        std::set<UserPair> thisCall;
        for (const UserPair& pair : update(broadPhase)) {
            const SceneBody& a = bodies.at(pair.first);
            const SceneBody& b = bodies.at(pair.second);
            EXPECT_LT(a.proxy, b.proxy) << "userDataA must come from the smaller proxy id";
            EXPECT_TRUE(pairedNow(a, b)) << "neither the fat boxes nor a sweep overlap";
            EXPECT_TRUE(reportable(a, b)) << "two static bodies' proxies paired";
            EXPECT_TRUE(thisCall.insert(ordered(pair.first, pair.second)).second)
                << "pair reported twice in one call";
            callProxies.push_back({a.proxy, b.proxy});
            known.insert(ordered(pair.first, pair.second));
        }
        EXPECT_TRUE(std::is_sorted(callProxies.begin(), callProxies.end()));
        reported += callProxies.size();

        std::set<UserPair> expected;
        for (auto a = bodies.begin(); a != bodies.end(); ++a) {
            for (auto b = std::next(a); b != bodies.end(); ++b) {
                if (pairedNow(a->second, b->second)) expected.insert({a->first, b->first});
            }
        }
        for (auto& [userData, body] : bodies) body.swept = false;
        if (known != expected) {
            ADD_FAILURE() << "seed " << seed << " round " << round << ": " << known.size()
                          << " pairs known, " << expected.size() << " overlapping";
            return reported;
        }
        if (round % 50 == 0 && !broadPhase.isValid()) {
            ADD_FAILURE() << "seed " << seed << " round " << round << ": invalid tree";
            return reported;
        }
    }
    EXPECT_EQ(broadPhase.proxyCount(), static_cast<int>(bodies.size()));
    return reported;
}

}  // namespace

TEST(BroadPhase, ReportsExactlyTheBruteForcePairsInRandomisedScenes) {
    for (std::uint32_t seed : {1u, 7u, 42u, 2024u}) {
        const std::size_t reported = runRandomScene(seed, 300);
        EXPECT_GT(reported, 1000u) << "seed " << seed << ": the scene hardly had any pairs";
    }
}

TEST(BroadPhase, CompactBoxesReportExactlyTheBruteForcePairsToo) {
    for (std::uint32_t seed : {1u, 7u, 42u, 2024u}) {
        const std::size_t reported = runRandomScene(seed, 300, BroadPhaseBoxes::Compact);
        EXPECT_GT(reported, 1000u) << "seed " << seed << ": the scene hardly had any pairs";
    }
}

TEST(BroadPhase, ReportsEachNewPairOnceWithTheSmallerProxysUserDataFirst) {
    BroadPhase broadPhase;
    const std::int32_t first = broadPhase.createProxy(boxAt({0, 0}, {1, 1}), 100);
    const std::int32_t second = broadPhase.createProxy(boxAt({1, 0}, {1, 1}), 5);
    broadPhase.createProxy(boxAt({10, 0}, {1, 1}), 6);  // touches nothing
    ASSERT_LT(first, second);
    // Both proxies are new, so the pair is found from each side: still reported once.
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{100, 5}}));
    // Nothing moved since: nothing to report.
    EXPECT_TRUE(update(broadPhase).empty());
}

TEST(BroadPhase, SmallMovesAreNotBufferedAndLargeOnesAre) {
    BroadPhase broadPhase;
    broadPhase.createProxy(boxAt({0, 0}, {1, 1}), 1);
    const AABB tight = boxAt({1.5f, 0}, {1, 1});
    const std::int32_t mover = broadPhase.createProxy(tight, 2);
    ASSERT_EQ(update(broadPhase).size(), 1u);

    const Vec2 small{0.05f, 0.0f};
    broadPhase.moveProxy(mover, tight, translated(tight, small));
    EXPECT_TRUE(update(broadPhase).empty());  // still inside its fat box: not re-examined

    const Vec2 large{-0.5f, 0.0f};
    broadPhase.moveProxy(mover, translated(tight, small), translated(tight, large));
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{1, 2}}));
}

// Compact keeps a shape's box around where it ended the step. A fast shape's sweep is paired
// once with what it passed, so continuous collision finds it, and is then forgotten.
TEST(BroadPhase, CompactBoxesCoverTheEndOfAMoveAndAFastOnesSweepIsPairedOnce) {
    BroadPhase broadPhase;
    broadPhase.setBoxes(BroadPhaseBoxes::Compact);
    const AABB start = boxAt({0, 0}, {1, 1});
    const std::int32_t proxy = broadPhase.createProxy(start, 1);
    const Vec2 margin{kCompactAabbMargin, kCompactAabbMargin};
    EXPECT_EQ(broadPhase.fatBox(proxy).lower, start.lower - margin);
    // A wall the shape will pass through, and a box beyond its sweep.
    broadPhase.createProxy(boxAt({2.5f, 0}, {0.1f, 2}), 2, true);
    broadPhase.createProxy(boxAt({4.1f, 5}, {0.1f, 1}), 3);
    EXPECT_TRUE(update(broadPhase).empty());

    // Two small steps: the first stays in the box, the second leaves it but moved less than the
    // margin: the end box, fattened, and no sweep.
    const AABB halfway = translated(start, {0.05f, 0.0f});
    EXPECT_FALSE(broadPhase.needsMove(proxy, start, halfway));
    broadPhase.moveProxy(proxy, start, halfway);
    EXPECT_EQ(broadPhase.fatBox(proxy).lower, start.lower - margin);
    const AABB nudged = translated(halfway, {0.05f, 0.0f});
    EXPECT_TRUE(broadPhase.needsMove(proxy, halfway, nudged));
    broadPhase.moveProxy(proxy, halfway, nudged);
    EXPECT_EQ(broadPhase.fatBox(proxy).lower, nudged.lower - margin);
    EXPECT_EQ(broadPhase.fatBox(proxy).upper, nudged.upper + margin);
    EXPECT_TRUE(update(broadPhase).empty());

    // Through the wall in one step: the box is the end box, fattened; the sweep finds the wall
    // once, and not the box it never reached.
    const AABB far = translated(nudged, {4.0f, 0.0f});
    broadPhase.moveProxy(proxy, nudged, far);
    EXPECT_EQ(broadPhase.fatBox(proxy).lower, far.lower - margin);
    EXPECT_EQ(broadPhase.fatBox(proxy).upper, far.upper + margin);
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{1, 2}}));
    EXPECT_TRUE(update(broadPhase).empty());

    // Back, without a sweep kept (a body left out of continuous collision): nothing met.
    EXPECT_FALSE(broadPhase.needsMove(proxy, far, far, SweepReach::None));
    broadPhase.moveProxy(proxy, far, nudged, SweepReach::None);
    EXPECT_TRUE(update(broadPhase).empty());

    // Up through the moving box, its sweep kept among static proxies only: nothing met. The
    // same sweep with every tree in reach meets it.
    const AABB up = translated(far, {0.0f, 10.0f});
    broadPhase.moveProxy(proxy, far, up, SweepReach::StaticTree);
    EXPECT_TRUE(update(broadPhase).empty());
    broadPhase.moveProxy(proxy, far, up, SweepReach::EveryTree);
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{1, 3}}));

    // A sweep whose proxy is destroyed before the update is never reported.
    broadPhase.moveProxy(proxy, nudged, far);
    broadPhase.destroyProxy(proxy);
    EXPECT_TRUE(update(broadPhase).empty());

    // A static shape's box gets the smaller static margin.
    const std::int32_t wall = broadPhase.createProxy(start, 4, true);
    const Vec2 staticMargin{kCompactStaticAabbMargin, kCompactStaticAabbMargin};
    EXPECT_EQ(broadPhase.fatBox(wall).lower, start.lower - staticMargin);
}

TEST(BroadPhase, TouchProxyReportsExistingPairsAgain) {
    BroadPhase broadPhase;
    const std::int32_t a = broadPhase.createProxy(boxAt({0, 0}, {1, 1}), 10);
    broadPhase.createProxy(boxAt({1, 1}, {1, 1}), 20);
    broadPhase.createProxy(boxAt({-1, 0}, {1, 1}), 30);
    broadPhase.createProxy(boxAt({50, 0}, {1, 1}), 40);
    EXPECT_EQ(update(broadPhase).size(), 3u);
    EXPECT_TRUE(update(broadPhase).empty());

    broadPhase.touchProxy(a);
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{10, 20}, {10, 30}}));
    EXPECT_TRUE(update(broadPhase).empty());

    // Touched twice and moved as well: each pair still once.
    broadPhase.touchProxy(a);
    broadPhase.touchProxy(a);
    const Vec2 d{0.0f, 0.5f};
    broadPhase.moveProxy(a, boxAt({0, 0}, {1, 1}), boxAt(d, {1, 1}));
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{10, 20}, {10, 30}}));
}

TEST(BroadPhase, AProxyDestroyedAfterAMoveIsNeverReported) {
    BroadPhase broadPhase;
    broadPhase.createProxy(boxAt({0, 0}, {1, 1}), 1);
    const std::int32_t doomed = broadPhase.createProxy(boxAt({5, 0}, {1, 1}), 2);
    EXPECT_TRUE(update(broadPhase).empty());

    broadPhase.moveProxy(doomed, boxAt({5, 0}, {1, 1}), boxAt({1, 0}, {1, 1}));
    broadPhase.touchProxy(doomed);
    broadPhase.destroyProxy(doomed);
    EXPECT_TRUE(update(broadPhase).empty());

    // A new proxy that inherits the destroyed one's id is reported under its own user data.
    const std::int32_t created = broadPhase.createProxy(boxAt({1, 0}, {1, 1}), 3);
    EXPECT_EQ(created, doomed);
    EXPECT_EQ(update(broadPhase), (std::vector<UserPair>{{1, 3}}));

    // Created and destroyed between two updates: never seen at all.
    const std::int32_t brief = broadPhase.createProxy(boxAt({0, 0}, {1, 1}), 4);
    broadPhase.destroyProxy(brief);
    EXPECT_TRUE(update(broadPhase).empty());
}

TEST(BroadPhase, TheSameCallsReportTheSameSequence) {
    auto record = [](std::uint32_t seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> position(-20.0f, 20.0f);
        std::uniform_real_distribution<float> step(-0.8f, 0.8f);
        BroadPhase broadPhase;
        std::vector<std::int32_t> proxies;
        std::vector<AABB> tight;
        std::vector<UserPair> sequence;
        for (int round = 0; round < 60; ++round) {
            for (int i = 0; i < 5; ++i) {
                tight.push_back(boxAt({position(rng), position(rng)}, {1.0f, 0.7f}));
                proxies.push_back(broadPhase.createProxy(tight.back(), round * 10 + i));
            }
            for (std::size_t i = 0; i < proxies.size(); ++i) {
                const Vec2 d{step(rng), step(rng)};
                const AABB from = tight[i];
                tight[i] = translated(tight[i], d);
                broadPhase.moveProxy(proxies[i], from, tight[i]);
            }
            if (round % 4 == 3) {
                broadPhase.destroyProxy(proxies[round % proxies.size()]);
                proxies.erase(proxies.begin() + round % static_cast<int>(proxies.size()));
                tight.erase(tight.begin() + round % static_cast<int>(tight.size()));
            }
            broadPhase.updatePairs([&](std::int32_t a, std::int32_t b) {
                sequence.push_back({a, b});
            });
            sequence.push_back({-1, round});  // marks where each update ended
        }
        return sequence;
    };
    const std::vector<UserPair> first = record(9);
    EXPECT_GT(first.size(), 60u + 100u);  // plenty of pairs, not just the markers
    EXPECT_EQ(first, record(9));
    EXPECT_NE(first, record(10));  // the comparison can tell different runs apart
}
