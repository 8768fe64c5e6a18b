// What the passes over every contact slot ask first, kept beside the contact pool: is the slot
// alive, whose bodies, touching, a sensor, enabled, due for re-filtering, and the contact's
// serial. A contact's pool slot is 144 bytes, its alive flag at the far end; a census entry is
// 24. The island search's table, continuous collision's first pass and the contact update's
// skip of sleeping pairs read the census and load a contact only when it matters to them: in a
// scene of 40,000 contacts of which 7,000 touch (smash), each pass streamed 6 MB of contacts
// to find what 1 MB says.
//
// The contact manager keeps it true: every change to these fields of a contact goes through
// ContactManager, which records the contact again (record); a loaded snapshot rebuilds it; and
// matches() checks the whole census against the pool (ContactManager::setCensusChecks, for
// tests and pivot-fuzz --verify-census).
#pragma once

#include <cstdint>
#include <vector>

#include "core/buffer.h"
#include "core/slot_pool.h"
#include "model/contact.h"

namespace pivot {

struct ContactSummary {
    enum : std::uint8_t {
        kAlive = 1,
        kTouching = 2,
        kSensor = 4,
        kEnabled = 8,
        kNeedsFiltering = 16,
    };
    std::uint64_t serial = 0;
    std::int32_t bodies[2] = {-1, -1};
    std::uint8_t flags = 0;

    bool alive() const { return (flags & kAlive) != 0; }
    /// Joins islands and reaches the solver: touching, not a sensor, enabled.
    bool solid() const {
        return (flags & (kTouching | kSensor | kEnabled)) == (kTouching | kEnabled);
    }
    /// Can stop a body: not a sensor, enabled (touching or not).
    bool blocking() const { return (flags & (kSensor | kEnabled)) == kEnabled; }
    bool needsFiltering() const { return (flags & kNeedsFiltering) != 0; }

    static ContactSummary of(const Contact& c) {
        ContactSummary s;
        s.serial = c.serial;
        s.bodies[0] = c.bodyA();
        s.bodies[1] = c.bodyB();
        s.flags = static_cast<std::uint8_t>(kAlive | (c.touching ? kTouching : 0) |
                                            (c.sensor ? kSensor : 0) | (c.enabled ? kEnabled : 0) |
                                            (c.needsFiltering ? kNeedsFiltering : 0));
        return s;
    }
    bool operator==(const ContactSummary& o) const {
        return serial == o.serial && bodies[0] == o.bodies[0] && bodies[1] == o.bodies[1] &&
               flags == o.flags;
    }
};

class ContactCensus {
public:
    /// The contact in `index` is new or changed. Thread-safe for distinct indices once the
    /// census covers the slot (grow first, outside any parallel pass). An entry that already
    /// says the same is not written: the contact update records every contact it updates, and
    /// most are as they were, so their cache lines stay clean (shared by two workers' blocks
    /// at the edges, and not written back).
    void record(std::int32_t index, const Contact& c) {
        const ContactSummary summary = ContactSummary::of(c);
        ContactSummary& entry = entries_[slot(index)];
        if (!(entry == summary)) entry = summary;
    }
    void forget(std::int32_t index) { entries_[slot(index)] = ContactSummary{}; }
    /// Covers every slot of a pool of this capacity (new slots dead).
    void grow(std::int32_t capacity) { resizeBuffer(entries_, static_cast<std::size_t>(capacity)); }
    /// Every slot again, from the pool (after a snapshot is loaded).
    void rebuild(const SlotPool<Contact>& contacts) {
        entries_.assign(static_cast<std::size_t>(contacts.capacity()), ContactSummary{});
        contacts.forEach([&](std::int32_t index, const Contact& c) { record(index, c); });
    }
    /// Whether every slot of the pool is described as it is.
    bool matches(const SlotPool<Contact>& contacts) const {
        if (entries_.size() < static_cast<std::size_t>(contacts.capacity())) return false;
        for (std::int32_t index = 0; index < contacts.capacity(); ++index) {
            const ContactSummary expected =
                contacts.isAlive(index) ? ContactSummary::of(contacts[index]) : ContactSummary{};
            if (!(entries_[slot(index)] == expected)) return false;
        }
        return true;
    }

    /// Valid for the slots below the pool's capacity.
    const ContactSummary& operator[](std::int32_t index) const { return entries_[slot(index)]; }

private:
    static std::size_t slot(std::int32_t index) { return static_cast<std::size_t>(index); }
    std::vector<ContactSummary> entries_;
};

}  // namespace pivot
