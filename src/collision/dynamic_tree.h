// A dynamic AABB tree: a binary tree of fattened boxes, one leaf ("proxy") per shape.
// Leaves are inserted where they grow the tree's total perimeter least and the tree is kept
// balanced by rotations, so queries cost O(log n) and moving a proxy is cheap when its box
// stays inside its fattened box. Moved proxies can instead be refitted in place and the part of
// the tree they grew rebuilt in one go (refitProxy, rebuildChanged).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "collision/aabb.h"
#include "collision/ray_cast.h"
#include "core/snapshot_io.h"
#include "pivot/constants.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pivot {

/// overlaps(node, box) for one query box and many nodes, without a branch per side: whether a
/// node is entered is a coin toss to the branch predictor, so a query pays one misprediction
/// per node at most instead of up to four. For finite boxes (the tree's) the answers are
/// overlaps'.
class OverlapTest {
public:
#if defined(__SSE2__)
    // A node overlaps when lower <= box.upper and upper >= box.lower, side by side.
    explicit OverlapTest(const AABB& box)
        : upperBound_(_mm_setr_ps(box.upper.x, box.upper.y, kInf, kInf)),
          lowerBound_(_mm_setr_ps(-kInf, -kInf, box.lower.x, box.lower.y)) {}
#else
    explicit OverlapTest(const AABB& box) : box_(box) {}
#endif
    bool operator()(const AABB& node) const {
#if defined(__SSE2__)
        static_assert(sizeof(AABB) == 4 * sizeof(float), "lower.x, lower.y, upper.x, upper.y");
        const __m128 corners = _mm_loadu_ps(&node.lower.x);
        const __m128 inside =
            _mm_and_ps(_mm_cmple_ps(corners, upperBound_), _mm_cmpge_ps(corners, lowerBound_));
        return _mm_movemask_ps(inside) == 0xF;
#else
        return (node.lower.x <= box_.upper.x) & (node.lower.y <= box_.upper.y) &
               (box_.lower.x <= node.upper.x) & (box_.lower.y <= node.upper.y);
#endif
    }

private:
#if defined(__SSE2__)
    static constexpr float kInf = std::numeric_limits<float>::infinity();
    __m128 upperBound_;
    __m128 lowerBound_;
#else
    AABB box_;
#endif
};

/// A LIFO stack whose first N entries live inline (no allocation); it spills onto the heap
/// only beyond that, so deep traversals stay correct while the usual ones never allocate.
template <typename T, std::size_t N>
class InlineStack {
public:
    void push(const T& value) {
        if (inlineCount_ < N) {
            inline_[inlineCount_++] = value;
        } else {
            spill_.push_back(value);
        }
    }
    /// Requires !empty(). The spill only holds entries while the inline part is full, so its
    /// back is always the newest entry.
    T pop() {
        if (!spill_.empty()) {
            T value = spill_.back();
            spill_.pop_back();
            return value;
        }
        return inline_[--inlineCount_];
    }
    bool empty() const { return inlineCount_ == 0; }
    std::size_t size() const { return inlineCount_ + spill_.size(); }

private:
    std::array<T, N> inline_;
    std::size_t inlineCount_ = 0;
    std::vector<T> spill_;
};

class DynamicTree {
public:
    /// `margin`: how far every stored box reaches beyond the shape's own (kAabbMargin for
    /// Box2D 2.4.1's boxes). Not saved in snapshots: the owner sets it.
    explicit DynamicTree(float margin = kAabbMargin) : margin_(margin) {}
    float margin() const { return margin_; }

    /// Adds a leaf for `tightBox`, stored fattened by the margin. Returns the proxy id.
    std::int32_t createProxy(const AABB& tightBox, std::int32_t userData);
    void destroyProxy(std::int32_t proxyId);
    /// Updates a proxy whose shape now has `tightBox` and moved by `displacement` this step.
    /// Does nothing and returns false while the stored fat box still contains `tightBox` and is
    /// not oversized (wider or taller by more than 2 kOversizeMargins margins than the box it
    /// would get now); otherwise re-inserts the leaf with a box fattened by the margin and
    /// stretched by kAabbMotionFactor * displacement, and returns true.
    bool moveProxy(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement);
    /// Whether moveProxy would re-insert the proxy. Read-only: safe from several threads.
    bool needsMove(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement) const;

    /// The other way to move a proxy: under the same test as needsMove with no displacement,
    /// stores the box fattened by the margin only (no stretch) where the leaf is, growing the
    /// ancestors that no longer hold it and marking them for rebuildChanged; returns whether
    /// it moved the proxy. The tree stays valid, but a leaf that travelled is left among its
    /// old neighbours until rebuildChanged.
    bool refitProxy(std::int32_t proxyId, const AABB& tightBox);
    /// Rebuilds the part of the tree refitProxy grew, top down: the subtrees it did not reach
    /// are kept whole, and they and the moved leaves are grouped again, split at the middle of
    /// the longer side of their centres. Proxy ids, boxes and user data are kept; only
    /// the tree's shape changes (so the order queries visit proxies in). The same tree and
    /// moves give the same result. Nothing to do when nothing grew.
    void rebuildChanged() {
        rebuildChanged([](int count, const auto& build) {
            for (int i = 0; i < count; ++i) build(i);
        });
    }
    /// The same, with the subtrees below the rebuild's first kRebuildLevels levels built by
    /// `runTasks(count, build)`, which must call build(i) once for each i in [0, count), in any
    /// order, on any threads, and return when all have returned. Every new node's id is taken
    /// before they start, in the order the one-thread build takes them, so the tree is the same
    /// whoever builds which subtree.
    template <typename RunTasks>
    void rebuildChanged(RunTasks&& runTasks) {
        const int subtrees = beginRebuild();
        if (subtrees == 0) return;
        runTasks(subtrees, [this](int i) { buildSubtree(i); });
        endRebuild();
    }

    /// How much larger than needed (in margins, per side) a stored box may be before it is
    /// shrunk: enough slack that a shape wandering about a little never causes a re-insert.
    static constexpr float kOversizeMargins = 4.0f;

    const AABB& fatBox(std::int32_t proxyId) const;
    std::int32_t userData(std::int32_t proxyId) const;

    /// Calls `visit(proxyId)` for every proxy whose fat box overlaps `box`; `visit` returns
    /// false to stop the query early. `visit` must not create, move or destroy proxies.
    template <typename Visit>
    void query(const AABB& box, Visit&& visit) const;

    /// Calls `visit(proxyId, maxFraction)` for every proxy whose fat box the segment from
    /// `origin` to origin + maxFraction * translation touches; maxFraction starts at the given
    /// value and `visit` returns the one to go on with: 0 (or NaN) stops, a smaller value
    /// shortens the segment (and prunes the rest of the tree with it), a larger one is ignored.
    /// `visit` must not create, move or destroy proxies.
    template <typename Visit>
    void rayCast(Vec2 origin, Vec2 translation, float maxFraction, Visit&& visit) const;

    int proxyCount() const;
    /// One more than the largest id a proxy can have now (ids index the node pool).
    int idBound() const { return static_cast<int>(nodes_.size()); }
    /// Whether the id, in [0, idBound()), is a live proxy (a leaf in use).
    bool isLeafInUse(std::int32_t id) const {
        return nodes_[id].height == 0 && nodes_[id].isLeaf();
    }
    /// The sum of the internal nodes' perimeters: what the surface-area heuristic minimises (a
    /// small query's chance of entering a node grows with its perimeter). For tests and tuning.
    float cost() const;
    /// Height of the tree (0 for a single leaf, -1 when empty).
    int height() const;
    /// Checks every structural invariant (parents, heights, boxes enclosing children, free
    /// list); returns false at the first violation. For tests, and for restoring snapshots.
    bool isValid() const;

    /// The whole tree, node for node (a restored tree answers and changes exactly as this one
    /// would). load refuses (pivot::Error) a tree isValid would not accept.
    void save(SnapshotWriter& out) const;
    void load(SnapshotReader& in);
    /// Takes a loaded tree's nodes into this one's storage, keeping this one's capacity and
    /// scratch: a rollback restores into warm buffers.
    void adopt(const DynamicTree& loaded) {
        nodes_ = loaded.nodes_;
        changed_ = loaded.changed_;
        root_ = loaded.root_;
        freeList_ = loaded.freeList_;
        proxyCount_ = loaded.proxyCount_;
        margin_ = loaded.margin_;
    }

private:
    static constexpr std::int32_t kNullNode = -1;
    // A balanced tree of a million leaves is about 30 deep, and the traversal holds at most
    // one pending sibling per level, so 256 inline entries never spill in practice.
    static constexpr std::size_t kQueryStackSize = 256;

    // A leaf (child1 == kNullNode) is a proxy: its id is its index, which never changes while
    // it lives, because re-insertion after a move keeps the node and only relinks it. Free
    // nodes have height -1 and chain through nextFree, last freed first reused.
    // 32 bytes, two to a cache line and none across two (a query reads one line per node it
    // looks at): a leaf keeps its user data where an internal node keeps its second child, and a
    // free node the next free one where a node in the tree keeps its parent.
    struct alignas(32) Node {
        AABB box;
        std::int32_t parent = kNullNode;  // free nodes: the next free node
        std::int32_t child1 = kNullNode;
        std::int32_t child2 = kNullNode;  // leaves: the proxy's user data
        std::int32_t height = -1;         // -1: free; 0: a leaf

        bool isLeaf() const { return child1 == kNullNode; }
        std::int32_t userData() const { return child2; }
        std::int32_t nextFree() const { return parent; }
    };
    static_assert(sizeof(Node) == 32, "two nodes to a cache line");

    template <typename Io, typename Tree>
    static void describe(Io& io, Tree& tree);
    AABB fatten(const AABB& tightBox) const {
        return {tightBox.lower - Vec2{margin_, margin_}, tightBox.upper + Vec2{margin_, margin_}};
    }
    AABB fatBoxFor(const AABB& tightBox, Vec2 displacement) const;
    std::int32_t allocateNode();
    void freeNode(std::int32_t nodeId);
    bool isProxy(std::int32_t proxyId) const;

    void insertLeaf(std::int32_t leaf);
    void removeLeaf(std::int32_t leaf);
    std::int32_t chooseSibling(const AABB& leafBox) const;
    /// Recomputes the boxes from `nodeId` up to the root (heights unchanged), stopping where a
    /// box does not change.
    void refitBoxesUpwards(std::int32_t nodeId);
    /// Refits boxes and heights from `nodeId` to the root, rotating where a node is unbalanced.
    void refitUpwards(std::int32_t nodeId);
    /// Rotates `nodeId`'s subtree until its children's heights differ by at most one and refits
    /// it; returns the subtree's (possibly new) root, already linked in nodeId's place.
    std::int32_t balance(std::int32_t nodeId);
    std::int32_t rotateUp(std::int32_t top, std::int32_t heavy);
    void refitNode(std::int32_t nodeId);
    void replaceChild(std::int32_t parent, std::int32_t oldChild, std::int32_t newChild);

    // rebuildChanged's pieces: the kept subtrees and moved leaves it groups ("parts"), a range
    // of them still to be split under a parent, and the split itself.
    struct Part {
        Vec2 centre;  // of the part's box: the splits group parts by it
        std::int32_t node;
    };
    struct BuildTask {
        std::int32_t begin;
        std::int32_t end;
        std::int32_t parent;  ///< kNullNode for the root
        std::int32_t first;   ///< where its new nodes' ids start in buildIds_
        AABB centres;         ///< the bounds of the parts' centres
        bool second;          ///< it hangs as its parent's child2 (else child1)
    };
    // The first levels of a rebuild of at least kMinPartsToShare parts are built before the
    // rest, which is up to 2^kRebuildLevels subtrees, built by runTasks.
    static constexpr int kRebuildLevels = 3;
    static constexpr std::int32_t kMinPartsToShare = 1024;
    /// Takes the changed nodes apart, takes the new nodes' ids and builds the first levels;
    /// returns how many subtrees are left to build (0: nothing to rebuild).
    int beginRebuild();
    void buildSubtree(int index);
    /// Refits the first levels' nodes, once their subtrees are built.
    void endRebuild();
    /// Splits `task`, whose node is `nodeId`, into its two halves' tasks.
    void halve(const BuildTask& task, std::int32_t nodeId, BuildTask (&halves)[2]);
    /// Hangs `nodeId` where `task` says (its parent's child, or the root).
    void link(std::int32_t nodeId, const BuildTask& task);
    /// Returns the bounds of the parts' centres.
    AABB collectParts();
    /// Returns where the second half starts; `halves` gets the two halves' centre bounds.
    std::int32_t splitParts(const BuildTask& task, AABB (&halves)[2]);

    std::vector<Node> nodes_;
    // Per node: grown around a moved leaf since the last rebuildChanged, or above such a node
    // (so the marks are a subtree at the top). Saved with the tree.
    std::vector<std::uint8_t> changed_;
    // rebuildChanged's scratch, kept for its capacity.
    std::vector<Part> parts_;            // the centres copied, so the splits read them in order
    std::vector<BuildTask> buildTasks_;  // a subtree's pending halves in its stretch of parts
    // The new nodes' ids, in the order a depth-first build, first halves first, makes them: a
    // node's subtree of n parts takes the n - 1 ids from its own.
    std::vector<std::int32_t> buildIds_;
    std::array<BuildTask, std::size_t{1} << kRebuildLevels> subtrees_{};
    std::array<std::int32_t, (std::size_t{1} << kRebuildLevels) - 1> topNodes_{};
    int subtreeCount_ = 0;
    int topCount_ = 0;
    std::int32_t root_ = kNullNode;
    std::int32_t freeList_ = kNullNode;
    std::int32_t proxyCount_ = 0;
    float margin_;
};

template <typename Visit>
void DynamicTree::query(const AABB& box, Visit&& visit) const {
    if (root_ == kNullNode) return;
    const OverlapTest overlapsBox(box);
    if (!overlapsBox(nodes_[root_].box)) return;
    // Only nodes whose boxes overlap are pushed: a node's two children are tested together, so
    // their two loads (a cache miss each, in a big tree) overlap instead of following each other
    // through the stack. The order of the visits is unchanged.
    InlineStack<std::int32_t, kQueryStackSize> stack;
    stack.push(root_);
    while (!stack.empty()) {
        const std::int32_t nodeId = stack.pop();
        const Node& node = nodes_[nodeId];
        if (node.isLeaf()) {
            if (!visit(nodeId)) return;
            continue;
        }
        const bool second = overlapsBox(nodes_[node.child2].box);
        const bool first = overlapsBox(nodes_[node.child1].box);
        if (second) stack.push(node.child2);
        if (first) stack.push(node.child1);
    }
}

template <typename Visit>
void DynamicTree::rayCast(Vec2 origin, Vec2 translation, float maxFraction, Visit&& visit) const {
    if (root_ == kNullNode) return;
    InlineStack<std::int32_t, kQueryStackSize> stack;
    stack.push(root_);
    while (!stack.empty()) {
        const std::int32_t nodeId = stack.pop();
        const Node& node = nodes_[nodeId];
        if (!segmentOverlaps(node.box, origin, translation, maxFraction)) continue;
        if (node.isLeaf()) {
            const float next = visit(nodeId, maxFraction);
            if (!(next > 0.0f)) return;
            if (next < maxFraction) maxFraction = next;
        } else {
            stack.push(node.child2);
            stack.push(node.child1);
        }
    }
}

}  // namespace pivot
