// The order in which one island's constraints are solved, and which of them may be solved at
// the same time.
//
// Joints are grouped by position strategy and joint type (group g of JointGroups is joints
// [groupStart[g], groupStart[g+1]) of jointIds; joints/joint_types.h orders the groups), in the
// island's order within a group. A small
// island is solved in that order by one thread, one serial batch per array.
//
// An island with at least kColoringThreshold constraints is coloured (graph_coloring.h): within
// each group, and among the contacts, constraints are reordered colour by colour, one batch
// per colour, so a team can share it out (within a colour, contacts by region of the contact
// pool, so each stays on the core that updates it: planContacts). Every constraint that acts
// on a body that never moves (static or kinematic) then gets a private copy of that body in an
// extra solver slot, so no two members ever write one slot (a constraint's write to such a
// body adds zero, so a copy behaves exactly as the original).
//
// A smaller island with at least kWideContactThreshold contacts has its contacts coloured
// likewise (its joints keep the island's order, and their bodies their own slots): one thread
// then solves each colour several contacts at a time (constraints/contact_solver_wide.cpp).
//
// Whether an island is coloured depends only on its size, never on the number of workers: a
// world steps to the same bits with any WorldDef::workerCount. A coloured island is solved in
// a different order than Box2D 2.4.1 would, so it agrees with Box2D in behaviour, not in bits.
//
// A bundle is several small islands planned as one (solver/island_bundles.h): their bodies,
// contacts and joints side by side, each island's solver slots moved past those of the islands
// before it. Within a group the islands' joints are dealt out in turn (the first joint of each
// island, then the second of each, ...), each island's in its own order; the contacts follow
// one island after another. The islands share no body, so each is solved to the bits it would
// be alone, while one island's joint waits on the joint before it (a chain's next link) the
// processor works on the other islands' (docs/performance.md, "What the changes bought").
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/buffer.h"
#include "core/slot_pool.h"
#include "islands/graph_coloring.h"
#include "islands/island_set.h"
#include "islands/team.h"
#include "joints/joint.h"
#include "joints/joint_types.h"
#include "model/body.h"
#include "pivot/joint.h"

namespace pivot {

/// At most this many islands are planned as one bundle (a joint's island is kept in a byte).
constexpr int kMostBundleMembers = 8;

/// Islands with at least this many joints and contacts are coloured.
constexpr int kColoringThreshold = 1024;

inline bool isColored(const IslandView& island) {
    return island.jointCount + island.contactCount >= kColoringThreshold;
}

/// Islands with at least this many contacts have them coloured, whatever their size.
constexpr int kWideContactThreshold = 64;

inline bool colorsContacts(const IslandView& island) {
    return isColored(island) || island.contactCount >= kWideContactThreshold;
}

struct IslandSchedule {
    bool colored = false;                // joints and contacts (isColored)
    bool contactsColored = false;        // contacts (colorsContacts)
    std::vector<std::int32_t> jointIds;  // joint pool indices, in solving order
    std::vector<JointSlots> jointPairs;  // their solver bodies
    std::array<std::int32_t, kJointGroupCount + 1> groupStart{};
    std::array<std::vector<Batch>, kJointGroupCount> jointBatches;  // within each group
    bool jointsMayBreak = false;           // a joint of the island has a break force or torque
    // The extra NGS sweeps its joints ask for (Joint::extraPositionIterations): the most any
    // asks, and, when that is above 0, each joint's, in solving order.
    std::int32_t mostExtraSweeps = 0;
    std::vector<std::int32_t> extraSweeps;
    std::vector<std::int32_t> contactIds;  // contact pool indices, in solving order
    std::vector<BodyPair> contactPairs;
    std::vector<Batch> contactBatches;
    /// Extra solver slots after the island's bodies: the island body each one copies.
    std::vector<std::int32_t> fixedCopies;
    /// The islands of a bundle (1 for one island), and where each one's solver slots and
    /// contacts (in solving order) begin: memberCount + 1 entries each, the last the end.
    int memberCount = 1;
    std::vector<std::int32_t> memberSlotStart;
    std::vector<std::int32_t> memberContactStart;
    std::vector<std::uint8_t> jointMember;  // bundles: per joint, in solving order, its island

    /// Room for an island holding every joint and contact of the world.
    void reserve(const BufferBounds& bound) {
        jointIds.reserve(bound.joints);
        jointPairs.reserve(bound.joints);
        extraSweeps.reserve(bound.joints);
        contactIds.reserve(bound.contacts);
        contactPairs.reserve(bound.contacts);
        // A colouring makes at most one batch per colour and the overflow.
        constexpr std::size_t kMostBatches = GraphColoring::kMaxColors + 1;
        for (std::vector<Batch>& batches : jointBatches) batches.reserve(kMostBatches);
        contactBatches.reserve(kMostBatches);
        jointMember.reserve(bound.joints);
        memberSlotStart.reserve(kMostBundleMembers + 1);
        memberContactStart.reserve(kMostBundleMembers + 1);
    }

    int slotCount(const IslandView& island) const {
        return island.bodyCount + static_cast<int>(fixedCopies.size());
    }
};

class IslandScheduler {
public:
    /// Plans `island` into `schedule`. Allocates only while its buffers grow.
    /// `contactSlots`: the contact pool's capacity (which slots a worker updates, planContacts).
    void plan(const IslandView& island, const SlotPool<Body>& bodies, const SlotPool<Joint>& joints,
              std::int32_t contactSlots, IslandSchedule& schedule) {
        const IslandSet::Range whole{0, island.bodyCount,  0, island.contactCount,
                                     0, island.jointCount, 0, island.mouseCount};
        plan(island, &whole, 1, bodies, joints, contactSlots, schedule);
    }
    /// Plans the bundle of islands `members[0..count)` (their ranges in one IslandSet, which
    /// `island` spans) into `schedule`. A bundle of more than one island has no mouse joint
    /// and is not coloured, whatever its size.
    void plan(const IslandView& island, const IslandSet::Range* members, int count,
              const SlotPool<Body>& bodies, const SlotPool<Joint>& joints,
              std::int32_t contactSlots, IslandSchedule& schedule);
    /// Room to plan an island holding every body, joint and contact of the world.
    void reserve(const BufferBounds& bound) {
        fixed_.reserve(bound.bodies);
        jointGroups_.reserve(bound.joints);
        jointMembers_.reserve(bound.joints);
        items_.reserve(std::max(bound.joints, bound.contacts));
        order_.reserve(std::max(bound.joints, bound.contacts));
        regions_.reserve(std::max(bound.joints, bound.contacts));
    }

private:
    /// Where each island's solver slots and contacts begin; `slotCount`, the bundle's slots.
    void planMembers(const IslandSet::Range* members, int count, int slotCount,
                     IslandSchedule& schedule);
    void planJoints(const IslandView& island, const IslandSet::Range* members,
                    const SlotPool<Joint>& joints, IslandSchedule& schedule);
    void planContacts(const IslandView& island, const IslandSet::Range* members,
                      std::int32_t contactSlots, IslandSchedule& schedule);
    /// Appends the joints of items_ (one group's, island by island) to order_, dealt out in
    /// turn among the bundle's islands.
    void dealOut(int memberCount);
    /// regions_[i] for the joints items_[0..count) of a coloured island: which stretch of the
    /// island's bodies each moves (bodyRegions in the .cpp says why).
    void bodyRegions(const IslandView& island, int count);
    /// For the constraints of the coloured arrays: the contacts, and the joints if `joints`.
    void giveFixedBodiesPrivateSlots(const IslandView& island, IslandSchedule& schedule,
                                     bool joints);

    GraphColoring coloring_;
    std::vector<std::uint8_t> fixed_;  // per island body: never moves
    std::vector<std::int32_t> items_;
    std::vector<std::int32_t> order_;
    std::vector<std::uint8_t> regions_;  // per contact or joint: its stretch of the pool or bodies
    std::vector<std::uint8_t> jointGroups_;   // per island joint: its group, read once
    std::vector<std::uint8_t> jointMembers_;  // bundles: per island joint, its island
    std::array<std::int32_t, kMostBundleMembers + 1> memberItems_{};  // one group's, per island
};

}  // namespace pivot
