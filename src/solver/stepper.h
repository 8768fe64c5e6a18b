// Solving one step's islands: finds them (or keeps the last step's, and their plans, when
// nothing the search reads has changed: model/island_revision.h), shares them out among the
// workers (a coloured island to the whole team, the others whole to one worker each, small ones
// in bundles: island_bundles.h) and adds
// up what they report. Owns the island buffers and the workspaces, reserved so that a warm step
// allocates nothing (docs/architecture.md, "One step").
#pragma once

#include <cstdint>
#include <vector>

#include "constraints/step_context.h"
#include "core/buffer.h"
#include "core/task_pool.h"
#include "islands/island_builder.h"
#include "islands/island_set.h"
#include "islands/solver_storage.h"
#include "solver/island_bundles.h"
#include "solver/island_solver.h"

namespace pivot {

/// What the step's islands did, summed.
struct StepTotals {
    int islands = 0;
    int bodies = 0;
    int joints = 0;
    int translationClamps = 0;
    int rotationClamps = 0;
    int letGoJoints = 0;
    int edgeBodies = 0;
    int discardedBodies = 0;
    int positionIterations = 0;  // the most any island ran
    int extraPositionSolves = 0;
};

class Stepper {
public:
    explicit Stepper(TaskPool& pool) : pool_(pool), workspaces_(pool.workerCount()) {}

    /// Builds and solves every island of the awake bodies.
    StepTotals solve(SolverStorage& storage, const StepContext& context);

    /// The islands of the last solve, and each one's report.
    const IslandSet& islands() const { return islands_; }
    const IslandReport& report(int island) const { return reports_[island]; }

    /// How a step comes by its islands, process-wide (for tests): Keep takes last step's when
    /// nothing the search reads has changed since (IslandRevision), and their plans with them;
    /// Search searches and plans every step; Verify searches every step and counts the steps
    /// where keeping would have solved other islands than the search found (islandsMisKept).
    enum class IslandReuse { Keep, Search, Verify };
    static void setIslandReuse(IslandReuse reuse);
    static std::uint64_t islandsMisKept();
    /// Steps, process-wide, in which nothing the search reads had changed (whatever the mode).
    static std::uint64_t stepsWithIslandsUnchanged();

    /// Sizes the island set for the world's pool capacities, when they grew (each solve does;
    /// World::restore too, for the snapshot's pools).
    void reserveStepBuffers(const SolverStorage& storage);

private:
    /// Sizes the workspaces for this step's island totals, when they passed the last record.
    void reserveWorkspaces();

    TaskPool& pool_;
    IslandBuilder builder_;
    IslandSet islands_;
    std::vector<IslandWorkspace> workspaces_;  // one per worker
    std::vector<IslandReport> reports_;        // one per island of the current step
    std::vector<int> smallIslands_;            // islands solved whole by one worker
    std::vector<IslandRun> runs_;              // those, alone or in bundles (island_bundles.h)
    BufferBounds reservedFor_;                 // the pool capacities the island set was sized for
    BufferBounds reservedWorkspaceFor_;        // the island totals the workspaces were sized for
    // The IslandRevision count islands_ was searched at, if it was searched.
    bool searched_ = false;
    std::uint64_t searchedAt_ = 0;
    IslandSet verified_;  // IslandReuse::Verify: the islands that would have been kept
};

}  // namespace pivot
