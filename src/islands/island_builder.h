// Finding islands: bodies connected through touching contacts and joints, found by depth-first
// search from each awake non-static body. A static body joins every island that touches it
// (with a solver slot in each) but does not connect them, since nothing moves it. A sleeping
// body reached from an awake one is woken: something is pushing or pulling it.
//
// Seeds are taken newest body first, and each body's contacts and joints newest first, so the
// order in which constraints are solved is fixed by the order of creation: a run is
// repeatable, and a scene built the same way in Box2D 2.4.1 (which lists bodies, contacts and
// joints newest first) meets its joints in the same order.
//
// A body's contacts are a list threaded through the contacts themselves, and following it is a
// cache miss per contact, one after another. When many bodies are awake the search reads them
// from a table instead: one pass over the contact census (model/contact_census.h) in slot
// order (which the memory system streams) lists each body's touching contacts, newest first
// by Contact::serial, which is the lists' own order (a contact is linked at the front of its
// bodies' lists when made, and snapshots are checked to keep that order). Both ways find the same
// islands in the same order.
#pragma once

#include <cstdint>
#include <vector>

#include "core/buffer.h"
#include "islands/island_set.h"
#include "islands/solver_storage.h"

namespace pivot {

class IslandBuilder {
public:
    /// Finds every island of the awake bodies and records them in `set` (cleared first), in
    /// seed order.
    void build(SolverStorage& storage, IslandSet& set);
    /// Room for a search over every body and contact of the world.
    void reserve(const BufferBounds& bound) {
        stack_.reserve(bound.bodies);
        tableStart_.reserve(bound.bodies + 1);
        tableFill_.reserve(bound.bodies);
        table_.reserve(2 * bound.contacts);
        solid_.reserve(bound.contacts);
    }

    /// How the search reads the bodies' touching contacts: chosen by the number of awake
    /// bodies (Auto), or forced, for tests (the islands are the same either way).
    enum class ContactReading { Auto, Lists, Table };
    static void setContactReading(ContactReading reading);

private:
    void collect(std::int32_t seed, SolverStorage& storage, IslandSet& set);
    /// The island-local index of a body reached from the island being collected, adding it to
    /// the island (and to the search) the first time.
    std::int32_t reach(std::int32_t body, SolverStorage& storage, IslandSet& set,
                       std::int32_t bodyBegin);

    /// A gear and one of the two joints it is built on.
    struct GearLink {
        std::int32_t joint;
        std::int32_t gear;
    };
    std::vector<GearLink> gearLinks_;  // every gear's two, rebuilt each build
    std::vector<std::uint8_t> bodyVisited_;
    std::vector<std::uint8_t> jointVisited_;
    std::vector<std::uint8_t> contactVisited_;
    std::vector<std::int32_t> stack_;

    /// Lists every body's touching contacts (solid: not sensors, enabled) in its list's order.
    void tabulateContacts(const ContactCensus& census, std::int32_t contactCapacity,
                          std::int32_t bodyCapacity);
    /// A touching contact as one of its bodies sees it: its edge key on that body's side and
    /// the body on the other side.
    struct ContactEntry {
        std::uint64_t serial;  // the contact's, for the ordering
        std::int32_t key;
        std::int32_t other;
    };
    bool useTable_ = false;
    std::vector<std::int32_t> tableStart_;  // per body: its entries are [start[b], start[b + 1])
    std::vector<std::int32_t> tableFill_;
    std::vector<ContactEntry> table_;
    struct SolidContact {
        std::uint64_t serial;
        std::int32_t index;
        std::int32_t bodies[2];
    };
    std::vector<SolidContact> solid_;  // the touching contacts, in slot order
};

}  // namespace pivot
