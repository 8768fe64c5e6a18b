// Finding islands: bodies connected through joints, found by depth-first search from each
// awake non-static body. A static body joins every island that touches it (with a solver slot
// in each) but does not connect them, since nothing moves it.
//
// Seeds are taken newest body first and each body's joints newest first, so the order in
// which joints are solved is fixed by the order of creation: a run is repeatable, and a scene
// built the same way in Box2D 2.4.1 (which lists bodies and joints newest first) meets its
// joints in the same order.
#pragma once

#include <cstdint>
#include <vector>

#include "body.h"
#include "joints/revolute_joint.h"
#include "slot_pool.h"
#include "solver/island_solver.h"

namespace pivot {

class IslandBuilder {
public:
    /// Calls solve(island) for every island, in seed order. `island` is reused between calls.
    template <typename Solve>
    void forEachIsland(SlotPool<Body>& bodies, const SlotPool<RevoluteJoint>& joints,
                       Island& island, Solve&& solve) {
        bodyVisited_.assign(static_cast<std::size_t>(bodies.capacity()), 0);
        jointVisited_.assign(static_cast<std::size_t>(joints.capacity()), 0);
        for (std::int32_t seed = bodies.capacity() - 1; seed >= 0; --seed) {
            if (!bodies.isAlive(seed) || bodyVisited_[seed]) continue;
            if (bodies[seed].type == BodyType::Static) continue;
            collect(seed, bodies, joints, island);
            solve(island);
            // Static bodies may belong to the next island too.
            for (std::int32_t b : island.bodies) {
                if (bodies[b].type == BodyType::Static) bodyVisited_[b] = 0;
            }
        }
    }

private:
    void collect(std::int32_t seed, SlotPool<Body>& bodies, const SlotPool<RevoluteJoint>& joints,
                 Island& island);

    std::vector<std::uint8_t> bodyVisited_;
    std::vector<std::uint8_t> jointVisited_;
    std::vector<std::int32_t> stack_;
};

}  // namespace pivot
