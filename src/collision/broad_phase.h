// The broad phase: which shapes might touch. Keeps DynamicTrees of every shape's fat box and a
// buffer of proxies that moved (or were created) since the last update; updatePairs reports
// each overlapping pair that involves at least one of them.
//
// Two policies (pivot::BroadPhaseBoxes). Predictive, Box2D 2.4.1's: one tree; a proxy that
// leaves its box gets one stretched ahead by its displacement and is re-inserted where the
// tree's heuristic says. Compact, Box2D v3's: the box is only fattened by the margin, and a
// proxy that leaves it is refitted where it sits; the part of the tree that grew is rebuilt
// just before the next updatePairs queries it. The box covers only where the shape ended the
// step. A shape that moved further than the margin also leaves its sweep (the step's start
// and end boxes together, fattened) for the next updatePairs, which pairs it once with the
// boxes it overlaps that a second test (maySweepPair) accepts: continuous collision gets the
// pairs a fast shape passed through, and the shapes it merely flew past are not paired with
// it at every query of theirs until it next moves. Moving many proxies costs one partial
// rebuild instead of as many re-insertions (or none, while nothing that moved looks for
// pairs). Compact also keeps static bodies' proxies in a tree of their own, which moving
// proxies query beside theirs: the moving tree stays small and is rebuilt without them, and
// two static proxies are never paired (static bodies never touch). Predictive keeps one tree
// so that proxy ids, and with them the order pairs are reported in, stay Box2D 2.4.1's.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "collision/dynamic_tree.h"
#include "core/task_pool.h"
#include "pivot/broad_phase_boxes.h"

namespace pivot {

/// Under Compact, where a shape that moved further than the margin in a step looks for what its
/// sweep passed through (BroadPhase::moveProxy).
enum class SweepReach : std::uint8_t {
    None,        ///< nowhere: no sweep is kept
    StaticTree,  ///< among static bodies' proxies only
    EveryTree,
};

class BroadPhase {
public:
    /// `onStaticBody`: the shape's body is static (under Compact its proxy goes to the static
    /// tree; its id then has kStaticTag set).
    std::int32_t createProxy(const AABB& tightBox, std::int32_t userData,
                             bool onStaticBody = false);
    /// Also forgets the proxy if it is buffered, so it is never reported after this call.
    void destroyProxy(std::int32_t proxyId);
    /// For a body whose type changed: returns the proxy's id from now on, which is new (and
    /// buffered, with a box fattened from `tightBox`) when the proxy has to change trees.
    std::int32_t setOnStaticBody(std::int32_t proxyId, const AABB& tightBox, bool onStaticBody);
    /// The policy (a new broad phase is Predictive). Only while there are no proxies: the
    /// policy decides which tree each goes to.
    void setBoxes(BroadPhaseBoxes boxes);
    BroadPhaseBoxes boxes() const { return boxes_; }

    /// For a shape whose box was `from` at the start of its motion and is `to` now:
    /// DynamicTree::moveProxy with the swept box and the displacement of its centre
    /// (Predictive), or refitProxy with `to` (Compact). A proxy given a new box is buffered for
    /// updatePairs. Under Compact, if the tree's margin around `to` does not hold `from`, the
    /// swept box, fattened, is kept for the next updatePairs too, which pairs it where `reach`
    /// says.
    void moveProxy(std::int32_t proxyId, const AABB& from, const AABB& to,
                   SweepReach reach = SweepReach::EveryTree);
    /// Whether moveProxy would do anything: give the proxy a new box (and so buffer it) or
    /// keep its sweep. Read-only: thread-safe.
    bool needsMove(std::int32_t proxyId, const AABB& from, const AABB& to,
                   SweepReach reach = SweepReach::EveryTree) const;
    /// Buffers a proxy so its pairs are reported again at the next updatePairs (for example
    /// after its filter changed).
    void touchProxy(std::int32_t proxyId);

    bool testOverlap(std::int32_t proxyA, std::int32_t proxyB) const;
    const AABB& fatBox(std::int32_t proxyId) const {
        return treeOf(proxyId).fatBox(nodeOf(proxyId));
    }
    std::int32_t userData(std::int32_t proxyId) const {
        return treeOf(proxyId).userData(nodeOf(proxyId));
    }

    /// DynamicTree::query over every tree (the static one after the moving one): `visit`
    /// gets proxy ids and returns false to stop.
    template <typename Visit>
    void query(const AABB& box, Visit&& visit) const;
    /// query over the proxies of static bodies only: the static tree under Compact; under
    /// Predictive, which keeps every proxy in one tree, that tree (`visit` then meets the
    /// moving proxies too, and tells them apart by their bodies).
    template <typename Visit>
    void queryStaticBodies(const AABB& box, Visit&& visit) const;
    /// DynamicTree::rayCast over every tree, the fraction one tree's visits shortened the
    /// segment to carried into the next.
    template <typename Visit>
    void rayCast(Vec2 origin, Vec2 translation, float maxFraction, Visit&& visit) const;

    /// Set in the ids of proxies in the static tree (never under Predictive).
    static constexpr std::int32_t kStaticTag = std::int32_t{1} << 30;
    /// Whether `proxyId` names a live proxy (any int is accepted: for restoring snapshots).
    bool isProxy(std::int32_t proxyId) const;
    /// A dense index for a live proxy, below indexBound(): for tables of proxies.
    std::size_t indexOf(std::int32_t proxyId) const {
        return static_cast<std::size_t>(nodeOf(proxyId)) +
               ((proxyId & kStaticTag) ? static_cast<std::size_t>(moving_.idBound()) : 0);
    }
    std::size_t indexBound() const {
        return static_cast<std::size_t>(moving_.idBound()) +
               static_cast<std::size_t>(static_.idBound());
    }
    int proxyCount() const { return moving_.proxyCount() + static_.proxyCount(); }
    /// DynamicTree::isValid of both trees, and no static proxies under Predictive.
    bool isValid() const;

    /// Snapshots: the policy, the trees and the proxies buffered for the next update, in their
    /// order. load refuses a buffer naming anything but live proxies (or the mark of a
    /// destroyed one).
    void save(SnapshotWriter& out) const;
    void load(SnapshotReader& in);
    /// Takes a loaded broad phase's state into this one's storage, keeping this one's capacity
    /// and scratch (DynamicTree::adopt).
    void adopt(const BroadPhase& loaded) {
        boxes_ = loaded.boxes_;
        moving_.adopt(loaded.moving_);
        static_.adopt(loaded.static_);
        moveBuffer_ = loaded.moveBuffer_;
        buffered_ = loaded.buffered_;
        sweeps_.clear();
    }

    /// Calls addPair(userDataA, userDataB) once for every pair of distinct proxies whose fat
    /// boxes overlap and at least one of which was buffered since the last call, and for every
    /// pair of a kept sweep with a box it overlaps, then clears the buffer and the sweeps. Pairs
    /// are reported in a deterministic order (sorted by proxy ids), each with the smaller proxy
    /// id's user data first. It does not know which pairs already have contacts: the caller ignores
    /// pairs it already has.
    ///
    /// The buffer is emptied before the first addPair call, so proxies that addPair buffers
    /// (by touchProxy, say) wait for the next update; addPair must not destroy proxies.
    template <typename AddPair>
    void updatePairs(AddPair&& addPair);
    /// The same, with the tree queries shared among the pool's workers (the pairs are merged
    /// and sorted, so the result is the same for any number of workers), and with two
    /// read-only, thread-safe tests that skip work which could never make a contact:
    /// mayQuery(userData) false skips a buffered proxy's queries (its sweep's too), and
    /// mayPair(userDataA, userDataB) false drops a pair before it is collected. A skipped proxy
    /// can still be found by the query of another buffered proxy, where mayPair decides. A
    /// pair found by a sweep alone must pass maySweepPair(userDataA, userDataB) as well.
    template <typename MayQuery, typename MayPair, typename MaySweepPair, typename AddPair>
    void updatePairs(TaskPool& pool, MayQuery&& mayQuery, MayPair&& mayPair,
                     MaySweepPair&& maySweepPair, AddPair&& addPair);

private:
    static constexpr std::int32_t kNullProxy = -1;

    struct ProxyPair {
        std::int32_t lower;  ///< the smaller proxy id
        std::int32_t upper;
    };

    DynamicTree moving_{kAabbMargin};               // every proxy under Predictive
    DynamicTree static_{kCompactStaticAabbMargin};  // static bodies' proxies under Compact
    BroadPhaseBoxes boxes_ = BroadPhaseBoxes::Predictive;
    // Buffered proxy ids in the order they were buffered; destroyed ones are overwritten with
    // kNullProxy rather than erased, which keeps destroyProxy from shifting the rest.
    std::vector<std::int32_t> moveBuffer_;
    // Marks of the buffered moving proxies (by node) during updatePairs: a pair of two of them
    // is taken only from the query of the larger id, so it is collected once instead of twice.
    std::vector<std::uint8_t> buffered_;
    // Sweeps kept by moveProxy for the next updatePairs (Compact), in the order they were kept;
    // destroyProxy marks a destroyed proxy's with kNullProxy. Only a step makes them, and it
    // updates the pairs before it ends, so there are none between steps (nor in snapshots).
    struct Sweep {
        std::int32_t proxy;
        SweepReach reach;
        AABB box;
    };
    std::vector<Sweep> sweeps_;
    // Kept between calls for its capacity: updatePairs allocates nothing once it has grown.
    std::vector<ProxyPair> pairBuffer_;
    std::vector<std::vector<ProxyPair>> workerPairs_;  // one per worker of the pool

    static float movingMargin(BroadPhaseBoxes boxes) {
        return boxes == BroadPhaseBoxes::Compact ? kCompactAabbMargin : kAabbMargin;
    }
    /// Compact: whether a shape moved from `from` to `to` left the tree's margin around its end
    /// box (a sweep to keep).
    static bool movedPastMargin(const DynamicTree& tree, const AABB& from, const AABB& to);
    static AABB fattened(const DynamicTree& tree, const AABB& box) {
        const Vec2 margin{tree.margin(), tree.margin()};
        return {box.lower - margin, box.upper + margin};
    }

    const DynamicTree& treeOf(std::int32_t proxyId) const {
        return (proxyId & kStaticTag) ? static_ : moving_;
    }
    DynamicTree& treeOf(std::int32_t proxyId) { return (proxyId & kStaticTag) ? static_ : moving_; }
    static std::int32_t nodeOf(std::int32_t proxyId) { return proxyId & ~kStaticTag; }

    template <typename Emit>
    void queryMoved(std::int32_t queryProxy, Emit&& emit) const;
    template <typename Emit>
    void querySweep(const Sweep& sweep, Emit&& emit) const;
    void rebuildChanged();
    /// The same, the moving tree's subtrees built by the pool's workers (the same tree).
    void rebuildChanged(TaskPool& pool);
    template <typename AddPair>
    void reportSortedPairs(AddPair&& addPair);
    void markBuffered(std::uint8_t value);
};

template <typename Visit>
void BroadPhase::query(const AABB& box, Visit&& visit) const {
    bool stopped = false;
    moving_.query(box, [&](std::int32_t node) {
        stopped = !visit(node);
        return !stopped;
    });
    if (stopped) return;
    static_.query(box, [&](std::int32_t node) { return visit(node | kStaticTag); });
}

template <typename Visit>
void BroadPhase::queryStaticBodies(const AABB& box, Visit&& visit) const {
    if (boxes_ == BroadPhaseBoxes::Compact) {
        static_.query(box, [&](std::int32_t node) { return visit(node | kStaticTag); });
    } else {
        moving_.query(box, visit);
    }
}

template <typename Visit>
void BroadPhase::rayCast(Vec2 origin, Vec2 translation, float maxFraction, Visit&& visit) const {
    bool stopped = false;
    moving_.rayCast(origin, translation, maxFraction, [&](std::int32_t node, float fraction) {
        const float next = visit(node, fraction);
        if (!(next > 0.0f)) {
            stopped = true;
        } else if (next < maxFraction) {
            maxFraction = next;
        }
        return next;
    });
    if (stopped) return;
    static_.rayCast(origin, translation, maxFraction, [&](std::int32_t node, float fraction) {
        return visit(node | kStaticTag, fraction);
    });
}

template <typename Emit>
void BroadPhase::queryMoved(std::int32_t queryProxy, Emit&& emit) const {
    const AABB& box = fatBox(queryProxy);
    if (queryProxy & kStaticTag) {
        // A static proxy meets only moving ones, whose ids are all smaller.
        moving_.query(box, [&](std::int32_t other) {
            emit(ProxyPair{other, queryProxy});
            return true;
        });
        return;
    }
    moving_.query(box, [&](std::int32_t otherProxy) {
        if (otherProxy == queryProxy) return true;
        if (buffered_[otherProxy] && otherProxy > queryProxy) return true;  // its own query
        emit(ProxyPair{std::min(queryProxy, otherProxy), std::max(queryProxy, otherProxy)});
        return true;
    });
    // A buffered static proxy finds the pair too: the copies are merged when sorted.
    static_.query(box, [&](std::int32_t other) {
        emit(ProxyPair{queryProxy, other | kStaticTag});
        return true;
    });
}

template <typename Emit>
void BroadPhase::querySweep(const Sweep& sweep, Emit&& emit) const {
    const std::int32_t sweeper = sweep.proxy;
    if (sweep.reach == SweepReach::EveryTree) {
        moving_.query(sweep.box, [&](std::int32_t other) {
            if (other != sweeper) {
                emit(ProxyPair{std::min(sweeper, other), std::max(sweeper, other)});
            }
            return true;
        });
    }
    if (sweeper & kStaticTag) return;  // static proxies are never paired
    static_.query(sweep.box, [&](std::int32_t other) {
        emit(ProxyPair{sweeper, other | kStaticTag});
        return true;
    });
}

template <typename AddPair>
void BroadPhase::reportSortedPairs(AddPair&& addPair) {
    // A pair found from both of its proxies' queries (or from one buffered twice) appears more
    // than once; sorting by ids puts the copies side by side and fixes the reporting order.
    std::sort(pairBuffer_.begin(), pairBuffer_.end(), [](const ProxyPair& a, const ProxyPair& b) {
        return a.lower < b.lower || (a.lower == b.lower && a.upper < b.upper);
    });
    const std::size_t count = pairBuffer_.size();
    for (std::size_t i = 0; i < count; ++i) {
        const ProxyPair pair = pairBuffer_[i];
        if (i > 0 && pair.lower == pairBuffer_[i - 1].lower &&
            pair.upper == pairBuffer_[i - 1].upper) {
            continue;
        }
        addPair(userData(pair.lower), userData(pair.upper));
    }
}

template <typename AddPair>
void BroadPhase::updatePairs(AddPair&& addPair) {
    pairBuffer_.clear();
    if (!moveBuffer_.empty()) rebuildChanged();
    markBuffered(1);
    for (const std::int32_t queryProxy : moveBuffer_) {
        if (queryProxy == kNullProxy) continue;
        queryMoved(queryProxy, [&](ProxyPair pair) { pairBuffer_.push_back(pair); });
    }
    for (const Sweep& sweep : sweeps_) {
        if (sweep.proxy == kNullProxy) continue;
        querySweep(sweep, [&](ProxyPair pair) { pairBuffer_.push_back(pair); });
    }
    markBuffered(0);
    moveBuffer_.clear();
    sweeps_.clear();
    reportSortedPairs(addPair);
}

template <typename MayQuery, typename MayPair, typename MaySweepPair, typename AddPair>
void BroadPhase::updatePairs(TaskPool& pool, MayQuery&& mayQuery, MayPair&& mayPair,
                             MaySweepPair&& maySweepPair, AddPair&& addPair) {
    workerPairs_.resize(static_cast<std::size_t>(pool.workerCount()));
    for (std::vector<ProxyPair>& pairs : workerPairs_) {
        pairs.clear();
        // Which worker collects which pairs depends on timing: each can hold as many as all
        // of them ever collected together, so only a step with more pairs than ever allocates.
        if (pairs.capacity() < pairBuffer_.capacity()) pairs.reserve(pairBuffer_.capacity());
    }
    // A tree refitted around moved proxies answers right but slowly: it is rebuilt when it is
    // about to be searched (a grid of shapes that never look for pairs never pays for it).
    const bool anyQuery =
        std::any_of(moveBuffer_.begin(), moveBuffer_.end(),
                    [&](std::int32_t p) { return p != kNullProxy && mayQuery(userData(p)); }) ||
        std::any_of(sweeps_.begin(), sweeps_.end(), [&](const Sweep& sweep) {
            return sweep.proxy != kNullProxy && mayQuery(userData(sweep.proxy));
        });
    if (anyQuery) rebuildChanged(pool);
    markBuffered(1);
    pool.parallelFor(static_cast<int>(moveBuffer_.size()), 256,
                     [&](int begin, int end, int worker) {
                         std::vector<ProxyPair>& pairs = workerPairs_[worker];
                         for (int i = begin; i < end; ++i) {
                             const std::int32_t proxy = moveBuffer_[i];
                             if (proxy == kNullProxy || !mayQuery(userData(proxy))) continue;
                             queryMoved(proxy, [&](ProxyPair pair) {
                                 if (mayPair(userData(pair.lower), userData(pair.upper))) {
                                     pairs.push_back(pair);
                                 }
                             });
                         }
                     });
    // Few shapes outrun the margin in a step: their queries are shared out in small chunks.
    pool.parallelFor(static_cast<int>(sweeps_.size()), 16, [&](int begin, int end, int worker) {
        std::vector<ProxyPair>& pairs = workerPairs_[worker];
        for (int i = begin; i < end; ++i) {
            const std::int32_t sweeper = sweeps_[i].proxy;
            if (sweeper == kNullProxy || !mayQuery(userData(sweeper))) continue;
            querySweep(sweeps_[i], [&](ProxyPair pair) {
                const std::int32_t a = userData(pair.lower);
                const std::int32_t b = userData(pair.upper);
                if (mayPair(a, b) && maySweepPair(a, b)) pairs.push_back(pair);
            });
        }
    });
    markBuffered(0);
    moveBuffer_.clear();
    sweeps_.clear();
    pairBuffer_.clear();
    for (const std::vector<ProxyPair>& pairs : workerPairs_) {
        pairBuffer_.insert(pairBuffer_.end(), pairs.begin(), pairs.end());
    }
    reportSortedPairs(addPair);
}

}  // namespace pivot
