// Finding islands: bodies connected through touching contacts and joints, found by depth-first
// search from each awake non-static body. A static body joins every island that touches it
// (with a solver slot in each) but does not connect them, since nothing moves it. A sleeping
// body reached from an awake one is woken: something is pushing or pulling it.
//
// Seeds are taken newest body first, and each body's contacts and joints newest first, so the
// order in which constraints are solved is fixed by the order of creation: a run is
// repeatable, and a scene built the same way in Box2D 2.4.1 (which lists bodies, contacts and
// joints newest first) meets its joints in the same order.
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
    /// Room for a search over every body of the world.
    void reserve(const BufferBounds& bound) { stack_.reserve(bound.bodies); }

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
};

}  // namespace pivot
