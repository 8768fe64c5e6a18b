// The dynamic AABB tree: node pool and free list, insertion by the perimeter heuristic,
// removal, the rotations that keep the tree balanced, and the refit-and-rebuild way of moving
// proxies (BroadPhaseBoxes::Compact).
#include "collision/dynamic_tree.h"

#include <algorithm>
#include <cassert>

#include "pivot/constants.h"

namespace pivot {

namespace {

AABB fatten(const AABB& tightBox) {
    const Vec2 margin{kAabbMargin, kAabbMargin};
    return {tightBox.lower - margin, tightBox.upper + margin};
}

}  // namespace

std::int32_t DynamicTree::createProxy(const AABB& tightBox, std::int32_t userData) {
    const std::int32_t proxyId = allocateNode();
    Node& leaf = nodes_[proxyId];
    leaf.box = fatten(tightBox);
    leaf.userData = userData;
    leaf.height = 0;
    insertLeaf(proxyId);
    ++proxyCount_;
    return proxyId;
}

void DynamicTree::destroyProxy(std::int32_t proxyId) {
    assert(isProxy(proxyId));
    removeLeaf(proxyId);
    // Freed after its old parent, so the next createProxy reuses this id first.
    freeNode(proxyId);
    --proxyCount_;
}

AABB DynamicTree::fatBoxFor(const AABB& tightBox, Vec2 displacement) {
    // Stretch only the side the shape is heading towards: the box then covers where it will
    // be over the next few steps without growing behind it.
    AABB box = fatten(tightBox);
    const Vec2 ahead = kAabbMotionFactor * displacement;
    if (ahead.x < 0.0f) {
        box.lower.x += ahead.x;
    } else {
        box.upper.x += ahead.x;
    }
    if (ahead.y < 0.0f) {
        box.lower.y += ahead.y;
    } else {
        box.upper.y += ahead.y;
    }
    return box;
}

bool DynamicTree::needsMove(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement) const {
    assert(isProxy(proxyId));
    // Still inside its box: nothing to do, unless the box has become far larger than the one
    // the shape would get now (stretched by a fast move that has since slowed or stopped). A
    // bloated box costs a query and spurious pairs whenever anything near it moves, so it is
    // shrunk. Sizes are compared, not positions, so a box stretched ahead of a steady motion
    // keeps serving until the shape leaves it.
    const AABB& stored = nodes_[proxyId].box;
    if (!contains(stored, tightBox)) return true;
    const AABB box = fatBoxFor(tightBox, displacement);
    const float slack = 2.0f * kOversizeMargins * kAabbMargin;
    bool wider = stored.upper.x - stored.lower.x > box.upper.x - box.lower.x + slack;
    bool taller = stored.upper.y - stored.lower.y > box.upper.y - box.lower.y + slack;
    return wider || taller;
}

bool DynamicTree::moveProxy(std::int32_t proxyId, const AABB& tightBox, Vec2 displacement) {
    if (!needsMove(proxyId, tightBox, displacement)) return false;
    const AABB box = fatBoxFor(tightBox, displacement);
    // A proxy whose new box is centred inside its old one has only shifted (a swinging grid, a
    // settling pile): it keeps its place in the tree, and its ancestors' boxes are refitted, a
    // walk to the root instead of a removal and a search for the best sibling. One that went
    // further is re-inserted, so the tree keeps grouping proxies that are near each other. The
    // tree's shape never changes which pairs are found, nor their order (they are sorted).
    if (contains(nodes_[proxyId].box, 0.5f * (box.lower + box.upper))) {
        nodes_[proxyId].box = box;
        refitBoxesUpwards(nodes_[proxyId].parent);
        return true;
    }
    removeLeaf(proxyId);
    nodes_[proxyId].box = box;
    insertLeaf(proxyId);
    return true;
}

void DynamicTree::refitBoxesUpwards(std::int32_t nodeId) {
    for (; nodeId != kNullNode; nodeId = nodes_[nodeId].parent) {
        Node& node = nodes_[nodeId];
        const AABB box = combine(nodes_[node.child1].box, nodes_[node.child2].box);
        if (box.lower == node.box.lower && box.upper == node.box.upper) return;  // nor above
        node.box = box;
    }
}

const AABB& DynamicTree::fatBox(std::int32_t proxyId) const {
    assert(isProxy(proxyId));
    return nodes_[proxyId].box;
}

std::int32_t DynamicTree::userData(std::int32_t proxyId) const {
    assert(isProxy(proxyId));
    return nodes_[proxyId].userData;
}

int DynamicTree::proxyCount() const {
    return proxyCount_;
}

float DynamicTree::cost() const {
    float sum = 0.0f;
    for (const Node& node : nodes_) {
        if (node.height > 0) sum += perimeter(node.box);
    }
    return sum;
}

int DynamicTree::height() const {
    return root_ == kNullNode ? -1 : nodes_[root_].height;
}

std::int32_t DynamicTree::allocateNode() {
    std::int32_t nodeId;
    if (freeList_ != kNullNode) {
        nodeId = freeList_;
        freeList_ = nodes_[nodeId].next;
        nodes_[nodeId] = Node{};
    } else {
        nodeId = static_cast<std::int32_t>(nodes_.size());
        nodes_.emplace_back();
        changed_.push_back(0);
    }
    nodes_[nodeId].height = 0;
    return nodeId;
}

void DynamicTree::freeNode(std::int32_t nodeId) {
    nodes_[nodeId] = Node{};
    changed_[nodeId] = 0;
    nodes_[nodeId].next = freeList_;
    freeList_ = nodeId;
}

bool DynamicTree::isProxy(std::int32_t proxyId) const {
    return proxyId >= 0 && proxyId < static_cast<std::int32_t>(nodes_.size()) &&
           nodes_[proxyId].height == 0;
}

void DynamicTree::insertLeaf(std::int32_t leaf) {
    if (root_ == kNullNode) {
        root_ = leaf;
        nodes_[leaf].parent = kNullNode;
        return;
    }

    const AABB leafBox = nodes_[leaf].box;
    const std::int32_t sibling = chooseSibling(leafBox);
    const std::int32_t oldParent = nodes_[sibling].parent;
    const std::int32_t newParent = allocateNode();  // may reallocate nodes_: no references held

    changed_[newParent] = changed_[sibling];  // keeps refitProxy's marks a subtree at the top
    Node& parent = nodes_[newParent];
    parent.parent = oldParent;
    parent.child1 = sibling;
    parent.child2 = leaf;
    nodes_[sibling].parent = newParent;
    nodes_[leaf].parent = newParent;
    if (oldParent == kNullNode) {
        root_ = newParent;
    } else {
        replaceChild(oldParent, sibling, newParent);
    }
    // The new parent itself may be unbalanced when the sibling is a tall subtree.
    refitUpwards(newParent);
}

void DynamicTree::removeLeaf(std::int32_t leaf) {
    if (leaf == root_) {
        root_ = kNullNode;
        return;
    }

    const std::int32_t parent = nodes_[leaf].parent;
    const std::int32_t grandParent = nodes_[parent].parent;
    const std::int32_t sibling =
        nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;

    nodes_[sibling].parent = grandParent;
    if (grandParent == kNullNode) {
        root_ = sibling;
    } else {
        replaceChild(grandParent, parent, sibling);
    }
    freeNode(parent);
    nodes_[leaf].parent = kNullNode;
    refitUpwards(grandParent);
}

// The cost of a tree is the sum of its internal nodes' perimeters (a query's chance of
// entering a node grows with its size). Pairing the new leaf with node N creates a parent the
// size of combine(N, leaf) and grows every ancestor of N; that growth is the "inherited" cost
// carried down the walk. Descending into a child costs at least the inherited cost plus the
// child's own growth plus a new parent no smaller than the leaf, so the walk stops where
// pairing is cheaper than the cheapest such bound.
std::int32_t DynamicTree::chooseSibling(const AABB& leafBox) const {
    const float leafPerimeter = perimeter(leafBox);
    auto descentBound = [&](std::int32_t childId) {
        const Node& child = nodes_[childId];
        const float paired = perimeter(combine(child.box, leafBox));
        if (child.isLeaf()) return paired;
        return std::min(paired, paired - perimeter(child.box) + leafPerimeter);
    };

    std::int32_t nodeId = root_;
    float inherited = 0.0f;
    while (!nodes_[nodeId].isLeaf()) {
        const Node& node = nodes_[nodeId];
        const float combined = perimeter(combine(node.box, leafBox));
        const float pairCost = combined + inherited;
        const float childInherited = inherited + (combined - perimeter(node.box));
        const float cost1 = descentBound(node.child1) + childInherited;
        const float cost2 = descentBound(node.child2) + childInherited;

        // Ties go down, and to the shorter child: a leaf placed low unbalances the tree least.
        if (pairCost < cost1 && pairCost < cost2) break;
        if (cost1 < cost2) {
            nodeId = node.child1;
        } else if (cost2 < cost1) {
            nodeId = node.child2;
        } else {
            nodeId = nodes_[node.child1].height <= nodes_[node.child2].height ? node.child1
                                                                              : node.child2;
        }
        inherited = childInherited;
    }
    return nodeId;
}

void DynamicTree::refitUpwards(std::int32_t nodeId) {
    while (nodeId != kNullNode) {
        nodeId = balance(nodeId);
        nodeId = nodes_[nodeId].parent;
    }
}

std::int32_t DynamicTree::balance(std::int32_t nodeId) {
    const Node& node = nodes_[nodeId];
    if (node.isLeaf()) return nodeId;
    const std::int32_t height1 = nodes_[node.child1].height;
    const std::int32_t height2 = nodes_[node.child2].height;
    if (height2 > height1 + 1) return rotateUp(nodeId, node.child2);
    if (height1 > height2 + 1) return rotateUp(nodeId, node.child1);
    refitNode(nodeId);
    return nodeId;
}

// `heavy` (a child of `top`, at least two taller than its sibling) takes top's place. It keeps
// its taller child and hands the other to `top`, which takes that child's slot under heavy.
// When a leaf was paired with a tall subtree (the heuristic may choose any node, not just a
// leaf), the imbalance is larger than one rotation can absorb: `top` then still leans the same
// way and is balanced in turn, which carries the leaf down one level per rotation.
std::int32_t DynamicTree::rotateUp(std::int32_t top, std::int32_t heavy) {
    const std::int32_t first = nodes_[heavy].child1;
    const std::int32_t second = nodes_[heavy].child2;
    const std::int32_t given = nodes_[first].height >= nodes_[second].height ? second : first;

    const std::int32_t above = nodes_[top].parent;
    nodes_[heavy].parent = above;
    if (above == kNullNode) {
        root_ = heavy;
    } else {
        replaceChild(above, top, heavy);
    }

    replaceChild(heavy, given, top);
    nodes_[top].parent = heavy;
    replaceChild(top, heavy, given);
    nodes_[given].parent = top;
    // refitProxy's marks stay a subtree at the top: a marked node's new parent is marked too.
    changed_[top] |= changed_[given];
    changed_[heavy] |= changed_[top];

    balance(top);  // relinks its result under `heavy` itself
    refitNode(heavy);
    return heavy;
}

void DynamicTree::refitNode(std::int32_t nodeId) {
    Node& node = nodes_[nodeId];
    if (node.isLeaf()) return;
    const Node& child1 = nodes_[node.child1];
    const Node& child2 = nodes_[node.child2];
    node.box = combine(child1.box, child2.box);
    node.height = 1 + std::max(child1.height, child2.height);
}

void DynamicTree::replaceChild(std::int32_t parent, std::int32_t oldChild, std::int32_t newChild) {
    Node& node = nodes_[parent];
    if (node.child1 == oldChild) {
        node.child1 = newChild;
    } else {
        assert(node.child2 == oldChild);
        node.child2 = newChild;
    }
}

bool DynamicTree::refitProxy(std::int32_t proxyId, const AABB& tightBox) {
    if (!needsMove(proxyId, tightBox, Vec2{0.0f, 0.0f})) return false;
    const AABB box = fatten(tightBox);
    nodes_[proxyId].box = box;
    // Ancestors only grow, and only those that must to hold the new box are marked: a leaf that
    // moved inside its group's box leaves the tree as good as it was. (A box left larger than its
    // children needs is still a valid bound; rebuildChanged makes it tight again.)
    std::int32_t nodeId = nodes_[proxyId].parent;
    if (nodeId == kNullNode || contains(nodes_[nodeId].box, box)) return true;
    for (; nodeId != kNullNode && !contains(nodes_[nodeId].box, box);
         nodeId = nodes_[nodeId].parent) {
        nodes_[nodeId].box = combine(nodes_[nodeId].box, box);
        changed_[nodeId] = 1;
    }
    // The marks must form a subtree at the top, which rebuildChanged takes apart from the root
    // down: the rest of the way up is marked too, as far as the first node already marked.
    for (; nodeId != kNullNode && !changed_[nodeId]; nodeId = nodes_[nodeId].parent) {
        changed_[nodeId] = 1;
    }
    return true;
}

void DynamicTree::rebuildChanged() {
    if (root_ == kNullNode || !changed_[root_]) return;
    const AABB centres = collectParts();

    builtNodes_.clear();
    buildTasks_.push_back({0, static_cast<std::int32_t>(parts_.size()), kNullNode, centres});
    while (!buildTasks_.empty()) {
        const BuildTask task = buildTasks_.back();
        buildTasks_.pop_back();
        std::int32_t nodeId;
        if (task.end - task.begin == 1) {
            nodeId = parts_[task.begin].node;
        } else {
            nodeId = allocateNode();
            builtNodes_.push_back(nodeId);
            AABB halves[2];
            const std::int32_t middle = splitParts(task, halves);
            buildTasks_.push_back({middle, task.end, nodeId, halves[1]});
            buildTasks_.push_back({task.begin, middle, nodeId, halves[0]});
        }
        nodes_[nodeId].parent = task.parent;
        if (task.parent == kNullNode) {
            root_ = nodeId;
        } else if (nodes_[task.parent].child1 == kNullNode) {
            nodes_[task.parent].child1 = nodeId;
        } else {
            nodes_[task.parent].child2 = nodeId;
        }
    }
    // A node was made before its children: boxes and heights are set in reverse.
    for (auto it = builtNodes_.rbegin(); it != builtNodes_.rend(); ++it) refitNode(*it);
}

// Takes the changed nodes apart from the root down (freeing them, which also clears their
// marks) and lists what hangs below them: the unchanged subtrees and the leaves.
AABB DynamicTree::collectParts() {
    parts_.clear();
    buildTasks_.clear();
    buildTasks_.push_back({root_, 0, kNullNode, {}});
    while (!buildTasks_.empty()) {
        const std::int32_t nodeId = buildTasks_.back().begin;
        buildTasks_.pop_back();
        const Node node = nodes_[nodeId];
        if (node.isLeaf() || !changed_[nodeId]) {
            parts_.push_back({node.box, 0.5f * (node.box.lower + node.box.upper), nodeId});
            continue;
        }
        buildTasks_.push_back({node.child2, 0, kNullNode, {}});
        buildTasks_.push_back({node.child1, 0, kNullNode, {}});
        freeNode(nodeId);
    }
    AABB centres{parts_[0].centre, parts_[0].centre};
    for (const Part& part : parts_) centres = combine(centres, AABB{part.centre, part.centre});
    return centres;
}

// Splits parts_[task.begin, task.end) in two. The cut is across the longer side of the parts'
// centres, at one of up to kMaxBins evenly spaced places: the one with the least
// perimeter-times-count on its two sides (the cost of querying the two new children). Centres
// all in one place cannot be cut: the list is halved instead. The halves' centre bounds come
// from the bins', which spares every level of the build a pass over its parts.
std::int32_t DynamicTree::splitParts(const BuildTask& task, AABB (&halves)[2]) {
    constexpr int kMaxBins = 16;
    const std::int32_t begin = task.begin;
    const std::int32_t end = task.end;
    if (end - begin == 2) {
        halves[0] = {parts_[begin].centre, parts_[begin].centre};
        halves[1] = {parts_[begin + 1].centre, parts_[begin + 1].centre};
        return begin + 1;
    }
    // Most splits are of a few parts, where fewer bins do as well and cost less to sum.
    const int bins = std::min(kMaxBins, end - begin);
    const AABB& centres = task.centres;
    halves[0] = centres;
    halves[1] = centres;
    const Vec2 extent = centres.upper - centres.lower;
    const bool alongX = extent.x >= extent.y;
    const float low = alongX ? centres.lower.x : centres.lower.y;
    const float width = alongX ? extent.x : extent.y;
    const std::int32_t half = begin + (end - begin) / 2;
    if (!(width > 0.0f)) return half;

    const float binsPerMetre = static_cast<float>(bins) / width;
    auto binOf = [&](const Part& part) {
        const Vec2 c = part.centre;
        const int bin = static_cast<int>(((alongX ? c.x : c.y) - low) * binsPerMetre);
        return std::min(bins - 1, std::max(0, bin));
    };
    std::array<AABB, kMaxBins> boxes;
    std::array<AABB, kMaxBins> binCentres;
    std::array<int, kMaxBins> counts{};
    for (std::int32_t i = begin; i < end; ++i) {
        const Part& part = parts_[i];
        const int bin = binOf(part);
        const AABB centre{part.centre, part.centre};
        if (counts[bin] == 0) {
            boxes[bin] = part.box;
            binCentres[bin] = centre;
        } else {
            boxes[bin] = combine(boxes[bin], part.box);
            binCentres[bin] = combine(binCentres[bin], centre);
        }
        ++counts[bin];
    }
    // aboveCost[k]: the cost of what lies in the bins after k.
    std::array<float, kMaxBins> aboveCost;
    AABB above{};
    int aboveCount = 0;
    for (int k = bins - 1; k > 0; --k) {
        if (counts[k] > 0) {
            above = aboveCount == 0 ? boxes[k] : combine(above, boxes[k]);
            aboveCount += counts[k];
        }
        aboveCost[k - 1] = aboveCount == 0 ? 0.0f : perimeter(above) * aboveCount;
    }
    AABB below{};
    int belowCount = 0;
    int bestCut = -1;
    float bestCost = 0.0f;
    for (int k = 0; k < bins - 1; ++k) {
        if (counts[k] > 0) {
            below = belowCount == 0 ? boxes[k] : combine(below, boxes[k]);
            belowCount += counts[k];
        }
        if (belowCount == 0 || belowCount == end - begin) continue;
        const float cost = perimeter(below) * belowCount + aboveCost[k];
        if (bestCut < 0 || cost < bestCost) {
            bestCut = k;
            bestCost = cost;
        }
    }
    if (bestCut < 0) return half;
    bool first[2] = {true, true};
    for (int k = 0; k < bins; ++k) {
        if (counts[k] == 0) continue;
        const int side = k <= bestCut ? 0 : 1;
        halves[side] = first[side] ? binCentres[k] : combine(halves[side], binCentres[k]);
        first[side] = false;
    }
    const auto cut = std::partition(parts_.begin() + begin, parts_.begin() + end,
                                    [&](const Part& part) { return binOf(part) <= bestCut; });
    return static_cast<std::int32_t>(cut - parts_.begin());
}

template <typename Io, typename Tree>
void DynamicTree::describe(Io& io, Tree& tree) {
    // A node is 41 bytes of snapshot: a corrupt count cannot ask for more than there are.
    if constexpr (Io::kReading) {
        tree.nodes_.assign(io.count(41), Node{});
        tree.changed_.assign(tree.nodes_.size(), 0);
    } else {
        io.count(tree.nodes_.size());
    }
    for (auto& node : tree.nodes_) {
        // A free node's box is whatever its last use left: any bits.
        io.anyFloat(node.box.lower.x);
        io.anyFloat(node.box.lower.y);
        io.anyFloat(node.box.upper.x);
        io.anyFloat(node.box.upper.y);
        io.value(node.parent);
        io.value(node.child1);
        io.value(node.child2);
        io.value(node.next);
        io.value(node.height);
        io.value(node.userData);
    }
    for (std::size_t i = 0; i < tree.nodes_.size(); ++i) {
        bool changed = tree.changed_[i] != 0;
        io.value(changed);
        if constexpr (Io::kReading) tree.changed_[i] = changed ? 1 : 0;
    }
    io.value(tree.root_);
    io.value(tree.freeList_);
    io.value(tree.proxyCount_);
}

void DynamicTree::save(SnapshotWriter& out) const {
    describe(out, *this);
}

void DynamicTree::load(SnapshotReader& in) {
    describe(in, *this);
    if (!isValid()) in.corrupt("the broad phase's tree is not a valid tree");
    // Boxes of nodes in use hold real coordinates (free nodes keep any bits).
    for (const Node& node : nodes_) {
        if (node.height >= 0 && !(isFinite(node.box.lower) && isFinite(node.box.upper))) {
            in.corrupt("a broad-phase box is not finite");
        }
    }
}

bool DynamicTree::isValid() const {
    const auto nodeCount = static_cast<std::int32_t>(nodes_.size());
    auto inPool = [&](std::int32_t id) { return id >= 0 && id < nodeCount; };

    // Free list: in range, marked free, no cycles (it cannot be longer than the pool).
    std::vector<bool> seen(nodes_.size(), false);
    std::int32_t freeCount = 0;
    for (std::int32_t id = freeList_; id != kNullNode; id = nodes_[id].next) {
        if (!inPool(id) || seen[id] || nodes_[id].height != -1 || changed_[id]) return false;
        seen[id] = true;
        ++freeCount;
    }

    std::int32_t usedCount = 0;
    std::int32_t leafCount = 0;
    if (root_ != kNullNode) {
        if (!inPool(root_) || nodes_[root_].parent != kNullNode) return false;
        std::vector<std::int32_t> stack{root_};
        while (!stack.empty()) {
            const std::int32_t id = stack.back();
            stack.pop_back();
            if (seen[id]) return false;  // a free node in the tree, or a node reached twice
            seen[id] = true;
            ++usedCount;

            const Node& node = nodes_[id];
            // rebuildChanged finds marks from the root down: a mark below an unmarked node
            // would never be cleared.
            if (changed_[id] && node.parent != kNullNode && !changed_[node.parent]) return false;
            if (node.isLeaf()) {
                if (node.child2 != kNullNode || node.height != 0 || changed_[id]) return false;
                ++leafCount;
                continue;
            }
            for (std::int32_t child : {node.child1, node.child2}) {
                if (!inPool(child) || nodes_[child].parent != id) return false;
                if (!contains(node.box, nodes_[child].box)) return false;
            }
            if (node.child1 == node.child2) return false;
            const std::int32_t expectedHeight =
                1 + std::max(nodes_[node.child1].height, nodes_[node.child2].height);
            if (node.height != expectedHeight) return false;
            stack.push_back(node.child1);
            stack.push_back(node.child2);
        }
    }

    return leafCount == proxyCount_ && usedCount + freeCount == nodeCount;
}

}  // namespace pivot
