// The broad phase's bookkeeping around its trees: which tree a proxy lives in, and which
// proxies to re-examine at the next updatePairs.
#include "collision/broad_phase.h"

#include <cassert>
#include <string>

namespace pivot {

namespace {
constexpr int kBroadPhaseBoxesCount = 2;

// Predictive stretches a box ahead by how far the shape's box moved.
Vec2 centreShift(const AABB& from, const AABB& to) {
    return 0.5f * (to.lower + to.upper) - 0.5f * (from.lower + from.upper);
}
}  // namespace

std::int32_t BroadPhase::createProxy(const AABB& tightBox, std::int32_t userData,
                                     bool onStaticBody) {
    const bool inStaticTree = onStaticBody && boxes_ == BroadPhaseBoxes::Compact;
    DynamicTree& tree = inStaticTree ? static_ : moving_;
    const std::int32_t node = tree.createProxy(tightBox, userData);
    // 2^30 nodes would take 40 GiB of tree before the tag could clash.
    assert(node < kStaticTag);
    const std::int32_t proxyId = inStaticTree ? node | kStaticTag : node;
    moveBuffer_.push_back(proxyId);
    return proxyId;
}

std::int32_t BroadPhase::setOnStaticBody(std::int32_t proxyId, const AABB& tightBox,
                                         bool onStaticBody) {
    const bool inStaticTree = (proxyId & kStaticTag) != 0;
    if (inStaticTree == (onStaticBody && boxes_ == BroadPhaseBoxes::Compact)) return proxyId;
    const std::int32_t data = userData(proxyId);
    destroyProxy(proxyId);
    return createProxy(tightBox, data, onStaticBody);
}

void BroadPhase::setBoxes(BroadPhaseBoxes boxes) {
    assert(proxyCount() == 0);
    boxes_ = boxes;
    moving_ = DynamicTree{movingMargin(boxes)};
}

void BroadPhase::destroyProxy(std::int32_t proxyId) {
    // Every copy goes: a proxy can be buffered more than once (moved, then touched), and its
    // id may be handed to a new proxy before the next update.
    for (std::int32_t& buffered : moveBuffer_) {
        if (buffered == proxyId) buffered = kNullProxy;
    }
    for (Sweep& sweep : sweeps_) {
        if (sweep.proxy == proxyId) sweep.proxy = kNullProxy;
    }
    treeOf(proxyId).destroyProxy(nodeOf(proxyId));
}

bool BroadPhase::movedPastMargin(const DynamicTree& tree, const AABB& from, const AABB& to) {
    // Within the margin, the end box fattened covers the sweep as well as the swept box would.
    return !contains(fattened(tree, to), from);
}

bool BroadPhase::needsMove(std::int32_t proxyId, const AABB& from, const AABB& to,
                           SweepReach reach) const {
    const DynamicTree& tree = treeOf(proxyId);
    if (boxes_ == BroadPhaseBoxes::Compact) {
        return tree.needsMove(nodeOf(proxyId), to, Vec2{0.0f, 0.0f}) ||
               (reach != SweepReach::None && movedPastMargin(tree, from, to));
    }
    return tree.needsMove(nodeOf(proxyId), combine(from, to), centreShift(from, to));
}

void BroadPhase::moveProxy(std::int32_t proxyId, const AABB& from, const AABB& to,
                           SweepReach reach) {
    DynamicTree& tree = treeOf(proxyId);
    if (boxes_ == BroadPhaseBoxes::Compact) {
        if (tree.refitProxy(nodeOf(proxyId), to)) moveBuffer_.push_back(proxyId);
        if (reach != SweepReach::None && movedPastMargin(tree, from, to)) {
            sweeps_.push_back({proxyId, reach, fattened(tree, combine(from, to))});
        }
        return;
    }
    if (tree.moveProxy(nodeOf(proxyId), combine(from, to), centreShift(from, to))) {
        moveBuffer_.push_back(proxyId);
    }
}

void BroadPhase::touchProxy(std::int32_t proxyId) {
    moveBuffer_.push_back(proxyId);
}

bool BroadPhase::testOverlap(std::int32_t proxyA, std::int32_t proxyB) const {
    return overlaps(fatBox(proxyA), fatBox(proxyB));
}

bool BroadPhase::isProxy(std::int32_t proxyId) const {
    if (proxyId < 0) return false;
    const DynamicTree& tree = treeOf(proxyId);
    const std::int32_t node = nodeOf(proxyId);
    return node < tree.idBound() && tree.isLeafInUse(node);
}

bool BroadPhase::isValid() const {
    return moving_.isValid() && static_.isValid() &&
           (boxes_ == BroadPhaseBoxes::Compact || static_.proxyCount() == 0);
}

void BroadPhase::rebuildChanged() {
    moving_.rebuildChanged();
    static_.rebuildChanged();  // only after a static body was moved by hand
}

void BroadPhase::rebuildChanged(TaskPool& pool) {
    // The rebuild is work the caller did alone while the other workers waited: on two workers,
    // sharing the subtrees took a third of it off the caller (`spinner` and `smash` soft step,
    // whose blade or flying bricks reach the root every step; docs/performance.md).
    moving_.rebuildChanged([&](int count, const auto& build) {
        pool.parallelFor(count, 1, [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i) build(i);
        });
    });
    static_.rebuildChanged();
}

void BroadPhase::markBuffered(std::uint8_t value) {
    if (buffered_.size() < static_cast<std::size_t>(moving_.idBound())) {
        buffered_.resize(static_cast<std::size_t>(moving_.idBound()), 0);
    }
    for (const std::int32_t proxy : moveBuffer_) {
        if (proxy != kNullProxy && !(proxy & kStaticTag)) buffered_[proxy] = value;
    }
}

// The static tree is written only under Compact, so Predictive's snapshots hold what they did
// when there was one tree.
void BroadPhase::save(SnapshotWriter& out) const {
    assert(sweeps_.empty());
    out.enumValue(boxes_, kBroadPhaseBoxesCount);
    moving_.save(out);
    if (boxes_ == BroadPhaseBoxes::Compact) static_.save(out);
    out.sequence(moveBuffer_, [&](std::int32_t proxy) { out.value(proxy); });
}

void BroadPhase::load(SnapshotReader& in) {
    in.enumValue(boxes_, kBroadPhaseBoxesCount);
    moving_ = DynamicTree{movingMargin(boxes_)};
    moving_.load(in);
    static_ = DynamicTree{kCompactStaticAabbMargin};
    if (boxes_ == BroadPhaseBoxes::Compact) static_.load(in);
    in.sequence(moveBuffer_, [&](std::int32_t& proxy) { in.value(proxy); });
    sweeps_.clear();
    for (const std::int32_t proxy : moveBuffer_) {
        if (proxy != kNullProxy && !isProxy(proxy)) {
            in.corrupt("the broad phase's buffer names proxy " + std::to_string(proxy));
        }
    }
    buffered_.assign(static_cast<std::size_t>(moving_.idBound()), 0);
}

}  // namespace pivot
