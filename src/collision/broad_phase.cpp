// The broad phase's bookkeeping around its tree: which proxies to re-examine at the next
// updatePairs.
#include "collision/broad_phase.h"

namespace pivot {

namespace {
constexpr int kBroadPhaseBoxesCount = 2;
}  // namespace

std::int32_t BroadPhase::createProxy(const AABB& tightBox, std::int32_t userData) {
    const std::int32_t proxyId = tree_.createProxy(tightBox, userData);
    moveBuffer_.push_back(proxyId);
    return proxyId;
}

void BroadPhase::destroyProxy(std::int32_t proxyId) {
    // Every copy goes: a proxy can be buffered more than once (moved, then touched), and its
    // id may be handed to a new proxy before the next update.
    for (std::int32_t& buffered : moveBuffer_) {
        if (buffered == proxyId) buffered = kNullProxy;
    }
    tree_.destroyProxy(proxyId);
}

void BroadPhase::moveProxy(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement) {
    const bool moved = boxes_ == BroadPhaseBoxes::Compact
                           ? tree_.refitProxy(proxyId, tightBox)
                           : tree_.moveProxy(proxyId, tightBox, displacement);
    if (moved) moveBuffer_.push_back(proxyId);
}

void BroadPhase::touchProxy(std::int32_t proxyId) {
    moveBuffer_.push_back(proxyId);
}

bool BroadPhase::testOverlap(std::int32_t proxyA, std::int32_t proxyB) const {
    return overlaps(tree_.fatBox(proxyA), tree_.fatBox(proxyB));
}

const AABB& BroadPhase::fatBox(std::int32_t proxyId) const {
    return tree_.fatBox(proxyId);
}

std::int32_t BroadPhase::userData(std::int32_t proxyId) const {
    return tree_.userData(proxyId);
}

void BroadPhase::markBuffered(std::uint8_t value) {
    if (buffered_.size() < static_cast<std::size_t>(tree_.idBound())) {
        buffered_.resize(static_cast<std::size_t>(tree_.idBound()), 0);
    }
    for (const std::int32_t proxy : moveBuffer_) {
        if (proxy != kNullProxy) buffered_[proxy] = value;
    }
}

void BroadPhase::save(SnapshotWriter& out) const {
    out.enumValue(boxes_, kBroadPhaseBoxesCount);
    tree_.save(out);
    out.sequence(moveBuffer_, [&](std::int32_t proxy) { out.value(proxy); });
}

void BroadPhase::load(SnapshotReader& in) {
    in.enumValue(boxes_, kBroadPhaseBoxesCount);
    tree_.load(in);
    in.sequence(moveBuffer_, [&](std::int32_t& proxy) { in.value(proxy); });
    for (const std::int32_t proxy : moveBuffer_) {
        if (proxy != kNullProxy &&
            (proxy < 0 || proxy >= tree_.idBound() || !tree_.isLeafInUse(proxy))) {
            in.corrupt("the broad phase's buffer names proxy " + std::to_string(proxy));
        }
    }
    buffered_.assign(static_cast<std::size_t>(tree_.idBound()), 0);
}

const DynamicTree& BroadPhase::tree() const {
    return tree_;
}

}  // namespace pivot
