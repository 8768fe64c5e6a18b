#include "islands/island_schedule.h"

#include "core/buffer.h"

namespace pivot {

void IslandScheduler::plan(const IslandView& island, const SlotPool<Body>& bodies,
                           const SlotPool<Joint>& joints, IslandSchedule& schedule) {
    schedule.colored = isColored(island);
    schedule.contactsColored = colorsContacts(island);
    schedule.fixedCopies.clear();
    if (schedule.contactsColored) {
        resizeBuffer(fixed_, static_cast<std::size_t>(island.bodyCount));
        for (int i = 0; i < island.bodyCount; ++i) {
            fixed_[i] = bodies[island.bodies[i]].type != BodyType::Dynamic;
        }
    }
    planJoints(island, joints, schedule);
    planContacts(island, schedule);
    if (schedule.contactsColored) giveFixedBodiesPrivateSlots(island, schedule, schedule.colored);
}

void IslandScheduler::planJoints(const IslandView& island, const SlotPool<Joint>& joints,
                                 IslandSchedule& schedule) {
    schedule.jointsMayBreak = false;
    if (island.jointCount == 0 && schedule.jointIds.empty()) {
        // As planned before, every group empty and every batch list cleared: nothing to undo
        // (most islands of a contact scene, and there are many groups).
        return;
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
            coloring_.color(items_.data(), sizes[g], island.jointBodies, fixed_.data(),
                            island.bodyCount, order_, batches, 0);
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
}

void IslandScheduler::planContacts(const IslandView& island, IslandSchedule& schedule) {
    const int count = island.contactCount;
    schedule.contactBatches.clear();
    resizeBuffer(schedule.contactIds, static_cast<std::size_t>(count));
    resizeBuffer(schedule.contactPairs, static_cast<std::size_t>(count));
    if (!schedule.contactsColored) {
        for (int k = 0; k < count; ++k) {
            schedule.contactIds[k] = island.contacts[k];
            schedule.contactPairs[k] = island.contactBodies[k];
        }
        if (count > 0) schedule.contactBatches.push_back({0, count, true});
        return;
    }
    resizeBuffer(items_, static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) items_[k] = k;
    order_.clear();
    coloring_.color(items_.data(), count, island.contactBodies, fixed_.data(), island.bodyCount,
                    order_, schedule.contactBatches, 0);
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
