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

#include "solver/island_solver.h"

namespace pivot {

class IslandBuilder {
public:
    /// Calls solve(island) for every island, in seed order. `island` is reused between calls.
    template <typename Solve>
    void forEachIsland(SolverStorage& storage, Island& island, Solve&& solve) {
        SlotPool<Body>& bodies = storage.bodies;
        bodyVisited_.assign(static_cast<std::size_t>(bodies.capacity()), 0);
        jointVisited_.assign(static_cast<std::size_t>(storage.joints.capacity()), 0);
        contactVisited_.assign(static_cast<std::size_t>(storage.contacts.capacity()), 0);
        for (std::int32_t seed = bodies.capacity() - 1; seed >= 0; --seed) {
            if (!bodies.isAlive(seed) || bodyVisited_[seed]) continue;
            const Body& body = bodies[seed];
            if (body.type == BodyType::Static || !body.awake) continue;
            collect(seed, storage, island);
            solve(island);
            // Static bodies may belong to the next island too.
            for (std::int32_t b : island.bodies) {
                if (bodies[b].type == BodyType::Static) bodyVisited_[b] = 0;
            }
        }
    }

private:
    void collect(std::int32_t seed, SolverStorage& storage, Island& island);
    void reach(std::int32_t other);

    std::vector<std::uint8_t> bodyVisited_;
    std::vector<std::uint8_t> jointVisited_;
    std::vector<std::uint8_t> contactVisited_;
    std::vector<std::int32_t> stack_;
};

}  // namespace pivot
