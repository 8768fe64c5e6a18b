// An engine the bench times: a bench::Builder that scenes build into, and a step. Each engine
// kind is made for one run of one scene, on a given number of threads.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/suite/builder.h"
#include "pivot/continuous_collision.h"

namespace pivot::bench {

/// Every engine steps 1/60 s.
constexpr float kTimeStep = 1.0f / 60.0f;

/// What a scene asks of the world it is built into.
struct WorldSettings {
    int threads = 1;
    bool sleep = false;      ///< bodies may sleep
    bool continuous = true;  ///< continuous collision
    /// pivot2d: continuous collision's policy for every set-up; unset, each set-up's own
    /// (Box2D 2.4.1's for those like for like with it, Box2D v3's for soft step).
    std::optional<ContinuousCollision> continuousCollision;
    bool predictiveBoxes = false;  ///< pivot2d: BroadPhaseBoxes::Predictive (others ignore it)
    /// pivot2d: its helpers run as tasks on the bench's pool of threads (engines/task_pool.h,
    /// the one Box2D v3 is given), through WorldDef::enqueueTask, not on threads of its own.
    bool sharedTasks = false;
    /// pivot2d: WorldDef::adaptWorkerCount (false: every step on all its workers).
    bool adaptWorkers = true;
    /// pivot2d: the position iterations of its set-ups of one substep (full_ngs, baumgarte);
    /// unset, each set-up's own (3). 0 leaves out the NGS position sweeps: what they cost.
    std::optional<int> positionIterations;
};

class Engine : public Builder {
public:
    virtual void step() = 0;
    /// Contacts in the world as the engine counts them: pairs whose broad-phase boxes overlap,
    /// touching or not (every engine here counts them so).
    virtual int contactCount() const = 0;
};

struct EngineKind {
    std::string name;  ///< as the bench prints it: pivot2d's set-ups, box2d_2.4.1, box2d_v3
    std::string about;
    int maxThreads = 1;    ///< Box2D 2.4.1: one
    bool isPivot = false;  ///< one of pivot2d's set-ups
    std::function<std::unique_ptr<Engine>(const WorldSettings&)> make;
};

/// pivot2d's three set-ups: full_ngs (FullNGS joints, NGS contacts, 8 velocity and 3 position
/// iterations: the default), baumgarte (Baumgarte joints, otherwise as full_ngs) and soft_step
/// (soft-step joints, soft contacts, 4 substeps of 1 velocity and 1 relax iteration: Box2D v3's
/// way of stepping).
std::vector<EngineKind> pivotEngines();
/// Box2D 2.4.1 (Debian's libbox2d), 8/3, one thread.
EngineKind box2dEngine();
/// Box2D v3 built from the source tree CMake was given (PIVOT_BOX2D_V3_SOURCE), 4 substeps, on
/// its own task callbacks served by a pool of threads; empty when it was not given.
std::vector<EngineKind> box2dV3Engines();

/// All of the above, pivot2d first.
std::vector<EngineKind> allEngines();

}  // namespace pivot::bench
