// The fuzz's re-entry checks (docs/reliability.md, "Who may call in"): changing calls made where
// the world must refuse them, from a step's task callbacks, from other threads during a step,
// and from query callbacks.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "random.h"

namespace pivot::fuzz {

/// Ids a changing call may take: some live, some not (the call must be refused either way).
struct Targets {
    BodyId body;
    ShapeId shape;
    JointId joint;
    std::vector<std::uint8_t> snapshot;  ///< for restore
};

/// What a changing call would change: Structure is refused in a query's callback as well
/// (world_access.h).
enum class ChangeKind { State, Structure };

/// Makes one changing call, picked at random from every family of them (create, destroy,
/// teleport, type, sensor, velocities, impulses, user data, materials, joints, world settings,
/// restore, step), or with `structureOnly` from the structural ones, on `world` with `targets`.
/// Returns its kind; throws what the call throws.
ChangeKind makeRandomChange(World& world, Random& random, const Targets& targets,
                            bool structureOnly = false);

/// A crowd of 465 boxes (over 1,024 contacts: every step hands work to helpers) stepped on a
/// game's task system whose callbacks meddle: each callback of an armed step makes changing
/// calls on the stepping thread and from a thread of its own, and reads the world, all of which
/// must be refused. A twin stepped without meddling must hash the same afterwards.
class MeddlingCrowd {
public:
    MeddlingCrowd();
    ~MeddlingCrowd();
    MeddlingCrowd(const MeddlingCrowd&) = delete;
    MeddlingCrowd& operator=(const MeddlingCrowd&) = delete;

    /// Steps the crowd and its twin once, meddling `calls` times from each task callback; any
    /// call that was not refused, or a twin that then hashes differently, is added to
    /// `failures`. Returns the calls refused.
    int step(Random& random, int calls, std::vector<std::string>& failures);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace pivot::fuzz
