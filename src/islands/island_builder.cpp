#include "islands/island_builder.h"

#include <algorithm>
#include <array>

#include "core/buffer.h"

namespace pivot {

void IslandBuilder::build(SolverStorage& storage, IslandSet& set) {
    SlotPool<Body>& bodies = storage.bodies;
    set.clear();
    // Cleared, and grown (at least twofold, buffer.h) when the pools have grown.
    const auto clear = [](std::vector<std::uint8_t>& marks, std::int32_t size) {
        std::fill(marks.begin(), marks.end(), std::uint8_t{0});
        resizeBuffer(marks, static_cast<std::size_t>(size), std::uint8_t{0});
    };
    clear(bodyVisited_, bodies.capacity());
    clear(jointVisited_, storage.joints.capacity());
    clear(contactVisited_, storage.contacts.capacity());
    // A gear is listed by its bodies A and B only, yet it moves C and D too: whoever reaches
    // one of its joints must reach the gear (collect), or C or D could end up in another island
    // (a D joined only to a static B is never reached from B).
    gearLinks_.clear();
    storage.joints.forEach([&](std::int32_t index, const Joint& joint) {
        if (const auto* gear = std::get_if<GearJoint>(&joint.data)) {
            gearLinks_.push_back({gear->side1.joint, index});
            gearLinks_.push_back({gear->side2.joint, index});
        }
    });
    for (std::int32_t seed = bodies.capacity() - 1; seed >= 0; --seed) {
        if (!bodies.isAlive(seed) || bodyVisited_[seed]) continue;
        const Body& body = bodies[seed];
        if (body.type == BodyType::Static || !body.awake) continue;
        collect(seed, storage, set);
        // Static bodies may belong to the next island too.
        const IslandSet::Range& r = set.ranges.back();
        for (std::int32_t i = r.bodyBegin; i < r.bodyEnd; ++i) {
            if (bodies[set.bodies[i]].type == BodyType::Static) bodyVisited_[set.bodies[i]] = 0;
        }
    }
}

std::int32_t IslandBuilder::reach(std::int32_t body, SolverStorage& storage, IslandSet& set,
                                  std::int32_t bodyBegin) {
    Body& b = storage.bodies[body];
    if (!bodyVisited_[body]) {
        bodyVisited_[body] = 1;
        b.islandIndex = static_cast<std::int32_t>(set.bodies.size()) - bodyBegin;
        set.bodies.push_back(body);
        stack_.push_back(body);
    }
    return b.islandIndex;
}

void IslandBuilder::collect(std::int32_t seed, SolverStorage& storage, IslandSet& set) {
    IslandSet::Range range{};
    range.bodyBegin = static_cast<std::int32_t>(set.bodies.size());
    range.contactBegin = static_cast<std::int32_t>(set.contacts.size());
    range.jointBegin = static_cast<std::int32_t>(set.joints.size());
    range.mouseBegin = static_cast<std::int32_t>(set.mouseJoints.size());
    stack_.clear();
    reach(seed, storage, set, range.bodyBegin);

    while (!stack_.empty()) {
        std::int32_t bodyIndex = stack_.back();
        stack_.pop_back();
        Body& body = storage.bodies[bodyIndex];
        if (body.type == BodyType::Static) continue;  // does not connect islands
        body.awake = true;  // keeps its sleep timer: it may still be at rest
        const std::int32_t self = body.islandIndex;
        for (std::int32_t m = body.mouseList; m != -1; m = storage.mouseJoints[m].next) {
            set.mouseJoints.push_back(m);
            set.mouseBodies.push_back(self);
        }

        for (std::int32_t key = body.contactList; key != -1;) {
            std::int32_t contactIndex = edgeOwner(key);
            const Contact& contact = storage.contacts[contactIndex];
            int side = edgeSide(key);
            key = contact.edges[side].nextKey;
            if (contactVisited_[contactIndex] || !contact.touching || contact.sensor ||
                !contact.enabled) {
                continue;
            }
            contactVisited_[contactIndex] = 1;
            std::int32_t other = reach(contact.edges[1 - side].body, storage, set, range.bodyBegin);
            set.contacts.push_back(contactIndex);
            set.contactBodies.push_back(side == 0 ? BodyPair{self, other} : BodyPair{other, self});
        }

        for (std::int32_t key = body.jointList; key != -1;) {
            std::int32_t jointIndex = edgeOwner(key);
            const Joint& joint = storage.joints[jointIndex];
            int side = edgeSide(key);
            key = joint.edges[side].nextKey;
            if (jointVisited_[jointIndex]) continue;
            // A let-go joint is not solved (World::isJointLetGo), and connects nothing unless a
            // gear is built on it: the gear moves both of its bodies, so they stay in one
            // island with the gear's.
            if (joint.letGo && joint.gearCount == 0) continue;
            jointVisited_[jointIndex] = 1;
            std::int32_t other = reach(joint.edges[1 - side].body, storage, set, range.bodyBegin);
            if (joint.gearCount > 0) {
                for (const GearLink& link : gearLinks_) {
                    if (link.joint != jointIndex) continue;
                    const Joint& gear = storage.joints[link.gear];
                    reach(gear.bodyA(), storage, set, range.bodyBegin);
                    reach(gear.bodyB(), storage, set, range.bodyBegin);
                }
            }
            if (joint.letGo) continue;
            JointSlots slots = side == 0 ? JointSlots{self, other, kNoSlot, kNoSlot}
                                         : JointSlots{other, self, kNoSlot, kNoSlot};
            // A gear's C and D: its joints join them to this island (let go or not, and
            // reached from either end: see gearLinks_); reached here for their slots.
            const std::array<std::int32_t, 2> extra = joint.extraBodies();
            for (int k = 0; k < 2; ++k) {
                if (extra[k] != -1) slots[2 + k] = reach(extra[k], storage, set, range.bodyBegin);
            }
            set.joints.push_back(jointIndex);
            set.jointBodies.push_back(slots);
        }
    }
    range.bodyEnd = static_cast<std::int32_t>(set.bodies.size());
    range.contactEnd = static_cast<std::int32_t>(set.contacts.size());
    range.jointEnd = static_cast<std::int32_t>(set.joints.size());
    range.mouseEnd = static_cast<std::int32_t>(set.mouseJoints.size());
    set.ranges.push_back(range);
}

}  // namespace pivot
