// The dynamic AABB tree: node pool and free list, insertion by the perimeter heuristic,
// removal, the rotations that keep the tree balanced, and the refit-and-rebuild way of moving
// proxies (BroadPhaseBoxes::Compact).
#include "collision/dynamic_tree.h"

#include <algorithm>
#include <cassert>
#include <limits>

#include "pivot/constants.h"

namespace pivot {

std::int32_t DynamicTree::createProxy(const AABB& tightBox, std::int32_t userData) {
    const std::int32_t proxyId = allocateNode();
    Node& leaf = nodes_[proxyId];
    leaf.box = fatten(tightBox);
    leaf.child2 = userData;  // Node::userData
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

AABB DynamicTree::fatBoxFor(const AABB& tightBox, Vec2 displacement) const {
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
    const float slack = 2.0f * kOversizeMargins * margin_;
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
    return nodes_[proxyId].userData();
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
        freeList_ = nodes_[nodeId].nextFree();
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
    nodes_[nodeId].parent = freeList_;  // Node::nextFree
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

int DynamicTree::beginRebuild() {
    if (root_ == kNullNode || !changed_[root_]) return 0;
    // A rebuild takes apart at most every internal node (one fewer than the leaves), which
    // leaves at most one part a leaf; the tasks pending and the nodes built are as few. Room
    // for that many, so a warm step never allocates here, however much of the tree it takes
    // apart.
    const auto most = static_cast<std::size_t>(proxyCount_) + 1;
    if (parts_.capacity() < most) parts_.reserve(most);
    // Grown, never shrunk: its tasks are written before they are read.
    if (buildTasks_.size() < most) buildTasks_.resize(most);
    if (buildIds_.capacity() < most) buildIds_.reserve(most);
    const AABB centres = collectParts();
    const auto count = static_cast<std::int32_t>(parts_.size());

    // collectParts freed the count - 1 internal nodes above the parts, and they head the free
    // list: the new nodes are taken from it here, all of them, in the order a depth-first
    // build takes them, so that building the subtrees in any order gives the same ids.
    buildIds_.clear();
    for (std::int32_t k = 0; k + 1 < count; ++k) buildIds_.push_back(allocateNode());

    // The first levels, depth first; each task at the last of them (or of a single part) is a
    // subtree. At most one pending task per level, and one more.
    const int levels = count >= kMinPartsToShare ? kRebuildLevels : 0;
    struct Pending {
        BuildTask task;
        int depth;
    };
    Pending pending[kRebuildLevels + 1];
    int size = 0;
    pending[size++] = {{0, count, kNullNode, 0, centres, false}, 0};
    subtreeCount_ = 0;
    topCount_ = 0;
    while (size > 0) {
        const Pending top = pending[--size];
        const BuildTask& task = top.task;
        if (top.depth == levels || task.end - task.begin == 1) {
            subtrees_[static_cast<std::size_t>(subtreeCount_++)] = task;
            continue;
        }
        const std::int32_t nodeId = buildIds_[static_cast<std::size_t>(task.first)];
        link(nodeId, task);
        topNodes_[static_cast<std::size_t>(topCount_++)] = nodeId;
        BuildTask halves[2];
        halve(task, nodeId, halves);
        pending[size++] = {halves[1], top.depth + 1};
        pending[size++] = {halves[0], top.depth + 1};
    }
    return subtreeCount_;
}

void DynamicTree::buildSubtree(int index) {
    const BuildTask& root = subtrees_[static_cast<std::size_t>(index)];
    // The second halves wait in the subtree's own stretch of buildTasks_: each holds at least
    // one of its parts, and they hold different ones.
    BuildTask* pending = buildTasks_.data() + root.begin;
    int size = 0;
    pending[size++] = root;
    while (size > 0) {
        BuildTask task = pending[--size];
        // Down the first halves without the stack (pushing a task and popping it again at once
        // was half of this loop's time).
        for (;;) {
            if (task.end - task.begin == 1) {
                link(parts_[static_cast<std::size_t>(task.begin)].node, task);
                break;
            }
            const std::int32_t nodeId = buildIds_[static_cast<std::size_t>(task.first)];
            link(nodeId, task);
            BuildTask halves[2];
            halve(task, nodeId, halves);
            pending[size++] = halves[1];
            task = halves[0];
        }
    }
    // A node's id comes before its children's: boxes and heights are set in reverse.
    for (std::int32_t k = root.first + (root.end - root.begin - 1) - 1; k >= root.first; --k) {
        refitNode(buildIds_[static_cast<std::size_t>(k)]);
    }
}

void DynamicTree::halve(const BuildTask& task, std::int32_t nodeId, BuildTask (&halves)[2]) {
    AABB centres[2];
    const std::int32_t middle = splitParts(task, centres);
    // Depth first, first halves first: the node's id, then the first half's, then the second's.
    const std::int32_t firstHalfNodes = middle - task.begin - 1;
    halves[0] = {task.begin, middle, nodeId, task.first + 1, centres[0], false};
    halves[1] = {middle, task.end, nodeId, task.first + 1 + firstHalfNodes, centres[1], true};
}

void DynamicTree::endRebuild() {
    for (int k = topCount_ - 1; k >= 0; --k) refitNode(topNodes_[static_cast<std::size_t>(k)]);
}

void DynamicTree::link(std::int32_t nodeId, const BuildTask& task) {
    nodes_[nodeId].parent = task.parent;
    if (task.parent == kNullNode) {
        root_ = nodeId;
    } else if (task.second) {
        nodes_[task.parent].child2 = nodeId;
    } else {
        nodes_[task.parent].child1 = nodeId;
    }
}

// Takes the changed nodes apart from the root down (freeing them, which also clears their
// marks) and lists what hangs below them: the unchanged subtrees and the leaves, bounding their
// centres on the way.
AABB DynamicTree::collectParts() {
    parts_.clear();
    // The second children waiting, in buildIds_ (free until the new ids are taken).
    std::vector<std::int32_t>& pending = buildIds_;
    pending.clear();
    pending.push_back(root_);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    AABB centres{{kInf, kInf}, {-kInf, -kInf}};
    while (!pending.empty()) {
        std::int32_t nodeId = pending.back();
        pending.pop_back();
        // Down the first children without the stack; the second ones wait on it.
        for (;;) {
            const Node& node = nodes_[nodeId];
            if (node.isLeaf() || !changed_[nodeId]) {
                const Vec2 centre = 0.5f * (node.box.lower + node.box.upper);
                parts_.push_back({centre, nodeId});
                centres = combine(centres, AABB{centre, centre});
                break;
            }
            const std::int32_t child1 = node.child1;
            pending.push_back(node.child2);
            freeNode(nodeId);
            nodeId = child1;
        }
    }
    return centres;
}

// Splits parts_[task.begin, task.end) in two across the longer side of the parts' centres, at
// its middle, and finds the halves' centre bounds in the same pass. Box2D v3 splits this way:
// one pass per level, where weighing cuts by the surface-area heuristic took a pass to bin the
// parts and another to partition them (12% of `spinner`'s step, whose blade reaches the root
// every step). Centres all in one place cannot be cut: the list is halved instead.
std::int32_t DynamicTree::splitParts(const BuildTask& task, AABB (&halves)[2]) {
    const std::int32_t begin = task.begin;
    const std::int32_t end = task.end;
    const AABB& centres = task.centres;
    halves[0] = centres;
    halves[1] = centres;
    const Vec2 extent = centres.upper - centres.lower;
    const bool alongX = extent.x >= extent.y;
    const float middle = alongX ? 0.5f * (centres.lower.x + centres.upper.x)
                                : 0.5f * (centres.lower.y + centres.upper.y);
    const std::int32_t half = begin + (end - begin) / 2;
    if (!((alongX ? extent.x : extent.y) > 0.0f)) return half;

    constexpr float kInf = std::numeric_limits<float>::infinity();
    AABB below{{kInf, kInf}, {-kInf, -kInf}};
    AABB above = below;
    std::int32_t i = begin;
    std::int32_t j = end;
    while (i < j) {
        const Vec2 c = parts_[i].centre;
        if ((alongX ? c.x : c.y) < middle) {
            below = combine(below, AABB{c, c});
            ++i;
        } else {
            --j;
            above = combine(above, AABB{c, c});
            std::swap(parts_[i], parts_[j]);
        }
    }
    // Only when the middle rounds onto an end of a tiny span: halve the list instead.
    if (i == begin || i == end) return half;
    halves[0] = below;
    halves[1] = above;
    return i;
}

template <typename Io, typename Tree>
void DynamicTree::describe(Io& io, Tree& tree) {
    // A node is 41 bytes of snapshot: a corrupt count cannot ask for more than there are.
    // Charged with its mark and the broad phase's mark (BroadPhase::load), and the world's copy.
    constexpr std::size_t kNodeCost = 2 * (sizeof(Node) + 2);
    if constexpr (Io::kReading) {
        const std::size_t n = io.count(41);
        io.charge(n * kNodeCost);
        tree.nodes_.assign(n, Node{});
        tree.changed_.assign(tree.nodes_.size(), 0);
    } else {
        io.count(tree.nodes_.size());
        io.charge(tree.nodes_.size() * kNodeCost);
    }
    for (auto& node : tree.nodes_) {
        // A free node's box is whatever its last use left: any bits.
        io.anyFloat(node.box.lower.x);
        io.anyFloat(node.box.lower.y);
        io.anyFloat(node.box.upper.x);
        io.anyFloat(node.box.upper.y);
        // The six links of the format, each in its own field: a leaf's second child and a free
        // node's parent are written as none, an internal node's user data as 0.
        const bool leaf = node.height == 0;
        const bool free = node.height == -1;
        std::int32_t parent = free ? kNullNode : node.parent;
        std::int32_t child2 = leaf ? kNullNode : node.child2;
        std::int32_t next = free ? node.parent : kNullNode;
        std::int32_t userData = leaf ? node.child2 : 0;
        io.value(parent);
        io.value(node.child1);
        io.value(child2);
        io.value(next);
        io.value(node.height);
        io.value(userData);
        if constexpr (Io::kReading) {
            // What the packed node cannot hold is what isValid would refuse anyway.
            if (node.height == 0 && child2 != kNullNode) {
                io.corrupt("a broad-phase leaf has a second child");
            }
            if (node.height == -1 && parent != kNullNode) {
                io.corrupt("a free broad-phase node has a parent");
            }
            node.parent = node.height == -1 ? next : parent;
            node.child2 = node.height == 0 ? userData : child2;
        }
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
    for (std::int32_t id = freeList_; id != kNullNode; id = nodes_[id].nextFree()) {
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
                if (node.height != 0 || changed_[id]) return false;
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
