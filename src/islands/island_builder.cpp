#include "islands/island_builder.h"

#include <algorithm>
#include <array>
#include <atomic>

#include "core/buffer.h"

namespace pivot {

namespace {

std::atomic<IslandBuilder::ContactReading> contactReading{IslandBuilder::ContactReading::Auto};

// The table reads every contact of the world once, streamed; the lists, each contact of an
// awake body twice, a miss each. The table pays once this share of the bodies is awake.
constexpr std::size_t kBodiesPerAwakeBodyForTable = 4;

}  // namespace

void IslandBuilder::setContactReading(ContactReading reading) {
    contactReading = reading;
}

void IslandBuilder::tabulateContacts(const ContactCensus& census, std::int32_t contactCapacity,
                                     std::int32_t bodyCapacity) {
    solid_.clear();
    const std::size_t bodySlots = static_cast<std::size_t>(bodyCapacity);
    resizeBuffer(tableStart_, bodySlots + 1);
    std::fill(tableStart_.begin(), tableStart_.end(), 0);
    // The census, not the contacts: a dead slot and a contact that is not solid fail the
    // same test.
    for (std::int32_t index = 0; index < contactCapacity; ++index) {
        const ContactSummary& c = census[index];
        if (!c.solid()) continue;
        // Written field by field in place: built whole on the stack and copied, the entry was
        // stored in two halves and read back as one, which the processor cannot forward (a
        // stall of about half this loop's time in large_pyramid).
        SolidContact& entry = solid_.emplace_back();
        entry.serial = c.serial;
        entry.index = index;
        entry.bodies[0] = c.bodies[0];
        entry.bodies[1] = c.bodies[1];
        ++tableStart_[static_cast<std::size_t>(c.bodies[0]) + 1];
        ++tableStart_[static_cast<std::size_t>(c.bodies[1]) + 1];
    }
    for (std::size_t b = 0; b < bodySlots; ++b) tableStart_[b + 1] += tableStart_[b];
    resizeBuffer(table_, static_cast<std::size_t>(tableStart_[bodySlots]));
    // Filled from the back in reverse slot order: where slots were taken in the order the
    // contacts were made (no churn), each body's entries come out newest first already.
    resizeBuffer(tableFill_, bodySlots);
    std::copy(tableStart_.begin() + 1, tableStart_.end(), tableFill_.begin());
    for (auto it = solid_.rbegin(); it != solid_.rend(); ++it) {
        for (int side = 0; side < 2; ++side) {
            const std::size_t body = static_cast<std::size_t>(it->bodies[side]);
            table_[static_cast<std::size_t>(--tableFill_[body])] = {
                it->serial, edgeKey(it->index, side), it->bodies[1 - side]};
        }
    }
    const auto newerFirst = [](const ContactEntry& x, const ContactEntry& y) {
        return x.serial > y.serial;
    };
    for (std::size_t b = 0; b < bodySlots; ++b) {
        const auto first = table_.begin() + tableStart_[b];
        const auto last = table_.begin() + tableStart_[b + 1];
        if (last - first > 1 && !std::is_sorted(first, last, newerFirst)) {
            std::sort(first, last, newerFirst);
        }
    }
}

void IslandBuilder::build(SolverStorage& storage, IslandSet& set) {
    SlotPool<Body>& bodies = storage.bodies;
    // Last step's awake bodies stand for this step's (the choice changes no result).
    const ContactReading reading = contactReading.load(std::memory_order_relaxed);
    useTable_ =
        reading == ContactReading::Table ||
        (reading == ContactReading::Auto && set.bodies.size() * kBodiesPerAwakeBodyForTable >=
                                                static_cast<std::size_t>(bodies.size()));
    if (useTable_) {
        tabulateContacts(storage.contactCensus, storage.contacts.capacity(), bodies.capacity());
    }

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
        // Keeps its sleep timer: it may still be at rest. Awake, it is a seed of its own next
        // step, which may list the islands in another order: the next step searches again.
        if (!body.awake) storage.islandRevision.bump();
        body.awake = true;
        const std::int32_t self = body.islandIndex;
        for (std::int32_t m = body.mouseList; m != -1; m = storage.mouseJoints[m].next) {
            set.mouseJoints.push_back(m);
            set.mouseBodies.push_back(self);
        }

        const auto touch = [&](std::int32_t key, std::int32_t otherBody) {
            const std::int32_t contactIndex = edgeOwner(key);
            const int side = edgeSide(key);
            contactVisited_[contactIndex] = 1;
            std::int32_t other = reach(otherBody, storage, set, range.bodyBegin);
            set.contacts.push_back(contactIndex);
            // In place, for the reason given in tabulateContacts.
            BodyPair& pair = set.contactBodies.emplace_back();
            pair[static_cast<std::size_t>(side)] = self;
            pair[static_cast<std::size_t>(1 - side)] = other;
        };
        if (useTable_) {
            const std::size_t b = static_cast<std::size_t>(bodyIndex);
            for (std::int32_t e = tableStart_[b]; e < tableStart_[b + 1]; ++e) {
                const ContactEntry& entry = table_[static_cast<std::size_t>(e)];
                if (!contactVisited_[edgeOwner(entry.key)]) touch(entry.key, entry.other);
            }
        } else {
            for (std::int32_t key = body.contactList; key != -1;) {
                const std::int32_t contactIndex = edgeOwner(key);
                const Contact& contact = storage.contacts[contactIndex];
                const int side = edgeSide(key);
                const std::int32_t here = key;
                key = contact.edges[side].nextKey;
                if (contactVisited_[contactIndex] || !contact.touching || contact.sensor ||
                    !contact.enabled) {
                    continue;
                }
                touch(here, contact.edges[1 - side].body);
            }
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
