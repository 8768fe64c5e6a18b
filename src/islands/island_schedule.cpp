#include "islands/island_schedule.h"

#include <algorithm>

#include "core/buffer.h"

namespace pivot {

void IslandScheduler::plan(const IslandView& island, const IslandSet::Range* members, int count,
                           const SlotPool<Body>& bodies, const SlotPool<Joint>& joints,
                           std::int32_t contactSlots, IslandSchedule& schedule) {
    const bool bundle = count > 1;
    schedule.memberCount = count;
    schedule.colored = !bundle && isColored(island);
    schedule.contactsColored = !bundle && colorsContacts(island);
    schedule.fixedCopies.clear();
    if (schedule.contactsColored) {
        resizeBuffer(fixed_, static_cast<std::size_t>(island.bodyCount));
        for (int i = 0; i < island.bodyCount; ++i) {
            fixed_[i] = bodies[island.bodies[i]].type != BodyType::Dynamic;
        }
    }
    planJoints(island, members, joints, schedule);
    planContacts(island, members, contactSlots, schedule);
    if (schedule.contactsColored) giveFixedBodiesPrivateSlots(island, schedule, schedule.colored);
    planMembers(members, count, schedule.slotCount(island), schedule);
}

void IslandScheduler::planMembers(const IslandSet::Range* members, int count, int slotCount,
                                  IslandSchedule& schedule) {
    resizeBuffer(schedule.memberSlotStart, static_cast<std::size_t>(count) + 1);
    resizeBuffer(schedule.memberContactStart, static_cast<std::size_t>(count) + 1);
    // The contacts keep the islands' order (planContacts), so their starts are the ranges'.
    for (int m = 0; m < count; ++m) {
        schedule.memberSlotStart[m] = members[m].bodyBegin - members[0].bodyBegin;
        schedule.memberContactStart[m] = members[m].contactBegin - members[0].contactBegin;
    }
    // The slots end with one island's private copies of its fixed bodies, if it has them.
    schedule.memberSlotStart[count] = slotCount;
    schedule.memberContactStart[count] = members[count - 1].contactEnd - members[0].contactBegin;
}

namespace {

// A bundle member's solver slots, moved past the islands' before it (kNoSlot stays).
template <typename Slots>
Slots movedBy(Slots slots, std::int32_t offset) {
    for (std::int32_t& slot : slots) {
        if (slot != kNoSlot) slot += offset;
    }
    return slots;
}

}  // namespace

void IslandScheduler::planJoints(const IslandView& island, const IslandSet::Range* members,
                                 const SlotPool<Joint>& joints, IslandSchedule& schedule) {
    schedule.jointsMayBreak = false;
    schedule.mostExtraSweeps = 0;
    const int memberCount = schedule.memberCount;
    schedule.jointMember.clear();
    if (island.jointCount == 0 && schedule.jointIds.empty()) {
        // As planned before, every group empty and every batch list cleared: nothing to undo
        // (most islands of a contact scene, and there are many groups).
        return;
    }
    if (memberCount > 1) {
        resizeBuffer(jointMembers_, static_cast<std::size_t>(island.jointCount));
        for (int m = 0; m < memberCount; ++m) {
            const std::int32_t begin = members[m].jointBegin - members[0].jointBegin;
            const std::int32_t end = members[m].jointEnd - members[0].jointBegin;
            for (std::int32_t j = begin; j < end; ++j) {
                jointMembers_[static_cast<std::size_t>(j)] = static_cast<std::uint8_t>(m);
            }
        }
    }
    std::array<std::int32_t, kJointGroupCount> sizes{};
    // One pass over the joints, which lie all over the pool: the groups are read from here on.
    static_assert(kJointGroupCount <= 256, "a joint's group is kept in a byte");
    resizeBuffer(jointGroups_, static_cast<std::size_t>(island.jointCount));
    for (int j = 0; j < island.jointCount; ++j) {
        const Joint& joint = joints[island.joints[j]];
        const int group = jointGroup(joint);
        jointGroups_[static_cast<std::size_t>(j)] = static_cast<std::uint8_t>(group);
        ++sizes[group];
        if (joint.breakForce > 0.0f || joint.breakTorque > 0.0f) schedule.jointsMayBreak = true;
        schedule.mostExtraSweeps = std::max(schedule.mostExtraSweeps, joint.extraPositionIterations);
    }
    schedule.groupStart[0] = 0;
    for (int g = 0; g < kJointGroupCount; ++g) {
        schedule.groupStart[g + 1] = schedule.groupStart[g] + sizes[g];
    }

    // Island positions of the joints, group by group, then (if coloured) colour by colour.
    order_.clear();
    for (int g = 0; g < kJointGroupCount; ++g) {
        std::vector<Batch>& batches = schedule.jointBatches[g];
        batches.clear();
        if (sizes[g] == 0) continue;
        items_.clear();
        for (int j = 0; j < island.jointCount; ++j) {
            if (jointGroups_[static_cast<std::size_t>(j)] == g) items_.push_back(j);
        }
        if (schedule.colored) {
            bodyRegions(island, sizes[g]);
            coloring_.color(items_.data(), sizes[g], island.jointBodies, fixed_.data(),
                            island.bodyCount, order_, batches, 0, regions_.data());
        } else if (memberCount > 1) {
            dealOut(memberCount);
            batches.push_back({0, sizes[g], true});
        } else {
            order_.insert(order_.end(), items_.begin(), items_.end());
            batches.push_back({0, sizes[g], true});
        }
    }

    resizeBuffer(schedule.jointIds, order_.size());
    resizeBuffer(schedule.jointPairs, order_.size());
    for (std::size_t k = 0; k < order_.size(); ++k) {
        schedule.jointIds[k] = island.joints[order_[k]];
        schedule.jointPairs[k] = island.jointBodies[order_[k]];
    }
    if (schedule.mostExtraSweeps > 0) {
        resizeBuffer(schedule.extraSweeps, order_.size());
        for (std::size_t k = 0; k < order_.size(); ++k) {
            schedule.extraSweeps[k] = joints[schedule.jointIds[k]].extraPositionIterations;
        }
    }
    if (memberCount > 1) {
        resizeBuffer(schedule.jointMember, order_.size());
        for (std::size_t k = 0; k < order_.size(); ++k) {
            const std::uint8_t m = jointMembers_[static_cast<std::size_t>(order_[k])];
            schedule.jointMember[k] = m;
            schedule.jointPairs[k] =
                movedBy(schedule.jointPairs[k], members[m].bodyBegin - members[0].bodyBegin);
        }
    }
}

// A team cuts each colour at its middle (Team::forBatchShares), and a member then moves the
// bodies of its share. Listed in island order, the colours of `joint_grid` (a 100 by 100 grid
// of revolute joints) were cut at different places of the grid, and 5,721 of its 10,000 bodies
// were moved by both members in one substep, their lines crossing cores between colours. Each
// colour lists its joints by region of the island's bodies (the solver slot of the joint's
// first movable body, kRegions regions), so the cuts of all colours fall near the same body.
void IslandScheduler::bodyRegions(const IslandView& island, int count) {
    resizeBuffer(regions_, static_cast<std::size_t>(count));
    // kRegions / bodyCount in 32.32 fixed point: a multiply per joint, not a division (this
    // runs on one thread, at every step where the island changed).
    const std::uint64_t scale = (std::uint64_t{GraphColoring::kRegions} << 32) /
                                static_cast<std::uint64_t>(std::max(island.bodyCount, 1));
    for (int i = 0; i < count; ++i) {
        std::int32_t slot = 0;
        for (const std::int32_t body : island.jointBodies[items_[static_cast<std::size_t>(i)]]) {
            if (body != kNoSlot && !fixed_[body]) {
                slot = body;
                break;
            }
        }
        const std::uint64_t region = (static_cast<std::uint64_t>(slot) * scale) >> 32;
        regions_[static_cast<std::size_t>(i)] =
            static_cast<std::uint8_t>(std::min<std::uint64_t>(region, GraphColoring::kRegions - 1));
    }
}

void IslandScheduler::dealOut(int memberCount) {
    // items_ holds the group's joints island by island: where each island's joints begin.
    memberItems_.fill(0);
    for (const std::int32_t j : items_) ++memberItems_[jointMembers_[j] + 1];
    for (int m = 0; m < memberCount; ++m) memberItems_[m + 1] += memberItems_[m];
    std::array<std::int32_t, kMostBundleMembers> next{};
    std::copy(memberItems_.begin(), memberItems_.begin() + memberCount, next.begin());
    const std::size_t total = items_.size();
    for (std::size_t dealt = 0; dealt < total;) {
        for (int m = 0; m < memberCount; ++m) {
            if (next[m] == memberItems_[m + 1]) continue;
            order_.push_back(items_[static_cast<std::size_t>(next[m]++)]);
            ++dealt;
        }
    }
}

void IslandScheduler::planContacts(const IslandView& island, const IslandSet::Range* members,
                                   std::int32_t contactSlots, IslandSchedule& schedule) {
    const int count = island.contactCount;
    schedule.contactBatches.clear();
    resizeBuffer(schedule.contactIds, static_cast<std::size_t>(count));
    resizeBuffer(schedule.contactPairs, static_cast<std::size_t>(count));
    if (!schedule.contactsColored) {
        for (int k = 0; k < count; ++k) {
            schedule.contactIds[k] = island.contacts[k];
            schedule.contactPairs[k] = island.contactBodies[k];
        }
        for (int m = 1; m < schedule.memberCount; ++m) {
            const IslandSet::Range& r = members[m];
            const std::int32_t offset = r.bodyBegin - members[0].bodyBegin;
            for (std::int32_t k = r.contactBegin; k < r.contactEnd; ++k) {
                BodyPair& pair = schedule.contactPairs[k - members[0].contactBegin];
                pair = movedBy(pair, offset);
            }
        }
        if (count > 0) schedule.contactBatches.push_back({0, count, true});
        return;
    }
    resizeBuffer(items_, static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) items_[k] = k;
    // The contact update shares the pool out among the workers in consecutive stretches of
    // slots (TaskPool::parallelFor). Each colour lists its contacts by stretch of the pool
    // (a region), so the member that solves a contact is mostly the worker that updated it, and
    // the contact's cache lines stay on one core. Listed in island order, a contact's lines
    // crossed cores about twice a step, at up to 250 ns each on the machine measured
    // (docs/performance.md). Regions of a power of two slots, as few as make at most kRegions
    // (a shift, not a division per contact: this runs on one thread). Only a coloured island
    // is shared by a team; one whose contacts alone are coloured is solved whole by one worker.
    const std::uint8_t* regions = nullptr;
    if (schedule.colored) {
        int shift = 0;
        while ((std::int64_t{GraphColoring::kRegions} << shift) < contactSlots) ++shift;
        resizeBuffer(regions_, static_cast<std::size_t>(count));
        for (int k = 0; k < count; ++k) {
            regions_[k] = static_cast<std::uint8_t>(
                std::min(island.contacts[k] >> shift, GraphColoring::kRegions - 1));
        }
        regions = regions_.data();
    }
    order_.clear();
    coloring_.color(items_.data(), count, island.contactBodies, fixed_.data(), island.bodyCount,
                    order_, schedule.contactBatches, 0, regions);
    for (int k = 0; k < count; ++k) {
        schedule.contactIds[k] = island.contacts[order_[k]];
        schedule.contactPairs[k] = island.contactBodies[order_[k]];
    }
}

void IslandScheduler::giveFixedBodiesPrivateSlots(const IslandView& island,
                                                  IslandSchedule& schedule, bool joints) {
    const auto privatize = [&](auto& pairs) {
        for (auto& pair : pairs) {
            for (std::int32_t& index : pair) {
                if (index != kNoSlot && index < island.bodyCount && fixed_[index]) {
                    schedule.fixedCopies.push_back(index);
                    index = island.bodyCount +
                            static_cast<std::int32_t>(schedule.fixedCopies.size()) - 1;
                }
            }
        }
    };
    if (joints) privatize(schedule.jointPairs);
    privatize(schedule.contactPairs);
}

}  // namespace pivot
