// Solving one island: a set of awake bodies connected by joints and touching contacts,
// independent of every other island for this step. The stages run in the order of
// docs/position-correction.md. Islands share nothing they write, so several can be solved at
// once, each in its own workspace; a big island can also be solved by a team of workers
// together (team.h), colour by colour (island_schedule.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "constraints/contact_solver.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "core/slot_pool.h"
#include "islands/island_schedule.h"
#include "islands/island_set.h"
#include "islands/solver_storage.h"
#include "islands/team.h"
#include "joints/mouse_joint.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/shape.h"
#include "solver/body_motion.h"
#include "solver/island_report.h"
#include "strategies/joint_groups.h"
#include "strategies/position_phase.h"
#include "strategies/velocity_phase.h"

namespace pivot {

/// The solver's arrays for one island at a time. One per worker, reused for every island of
/// every step, so after the first steps solving allocates nothing.
struct IslandWorkspace {
    IslandScheduler scheduler;
    IslandSchedule schedule;
    // The island `schedule` was planned for, and the IslandRevision count its islands were
    // searched at: the same island at the same count has the same plan.
    static constexpr std::uint64_t kNeverPlanned = ~std::uint64_t{0};
    int plannedIsland = -1;  // the first island of the bundle planned
    int plannedCount = 0;
    std::uint64_t plannedAt = kNeverPlanned;
    std::vector<SolverVelocity> velocities;  // one per solver slot
    std::vector<SolverPose> positions;
    std::vector<SolverBodyInputs> bodyInputs;  // loaded with the bodies, for the contacts' set-up
    std::vector<VelocityDrive> drives;  // loaded with the bodies, for every substep's integration
    // Contacts built once a step (soft): the poses the step started from, and each slot's
    // motion since, measured at every later substep.
    std::vector<SolverPose> stepStart;
    std::vector<SolverMotion> motion;
    std::vector<Rot> rotations;  // Rot(positions[i].a), for the contacts' set-up
    JointGroups groups;
    // Per joint, in schedule order: let go this step (so later substeps keep its constraint
    // inert without reading the joint).
    std::vector<std::uint8_t> jointLetGo;
    std::vector<MouseConstraint> mouseConstraints;
    ContactSolver contactSolver;
    PositionPhaseScratch positionScratch;
    std::vector<IslandReport> memberReports;  // per team member, one per island of the bundle
};

/// Makes room in `workspace` for an island holding every body, contact and mouse joint of the
/// world (joint constraints, larger and rarely churning, grow as needed, at least twofold).
void reserveWorkspace(IslandWorkspace& workspace, const BufferBounds& bound);

/// Before a team solves islands [first, first + count) (one island, or a bundle of several
/// solved together on one thread: island_bundles.h), on one thread: plans their schedule
/// (unless `workspace` holds the plan of the same islands at the same `islandRevision`, a count
/// of IslandRevision's, or IslandWorkspace::kNeverPlanned to plan anyway) and sizes every array
/// of `workspace` for a team of `teamSize`.
void planIsland(const IslandSet& set, int first, int count, IslandWorkspace& workspace,
                const SolverStorage& storage, const StepContext& step, int teamSize,
                std::uint64_t islandRevision);

/// One member's part of advancing the planned islands [first, first + count) by one step: every
/// member of the team calls it with the same arguments. Stores the joints' and contacts'
/// impulses and updates the bodies' sleep timers (putting an island to sleep when it has rested
/// long enough). Each island ends with the bits it would have solved alone. The leader writes
/// each island's report to reports[0..count).
void solveIslands(const Team& team, const IslandSet& set, int first, int count,
                  IslandWorkspace& workspace, SolverStorage& storage, const StepContext& step,
                  IslandReport* reports);

/// solveIslands for one island: its report on the leader (an empty one on other members).
IslandReport solveIsland(const Team& team, const IslandSet& set, int index,
                         IslandWorkspace& workspace, SolverStorage& storage,
                         const StepContext& step);

/// For tests, process-wide: off, later substeps rebuild every joint constraint from its joint,
/// the reference that re-measuring the kept ones (kKeptAcrossSubsteps) must match bit for bit.
void setJointRemeasuring(bool enabled);

/// For tests, process-wide: off, lone bodies are solved as islands like any other (solveIsland),
/// the reference solveLoneBody must match bit for bit.
void setLoneBodyShortcut(bool enabled);
bool loneBodyShortcutOn();

/// Whether `island` is one body alone, no contact, joint or mouse joint acting on it, and is to
/// be solved by solveLoneBody.
inline bool isLoneBody(const IslandView& island) {
    return island.bodyCount == 1 && island.contactCount == 0 && island.jointCount == 0 &&
           island.mouseCount == 0 && loneBodyShortcutOn();
}

/// Advances a lone body's island (isLoneBody) by one step, to the bits solveIsland gives it,
/// without a workspace: forces, moves within the limits, write back and the sleep test. In a
/// scene of scattered debris (`smash`, `spinner`) most islands are one body, and planning and
/// sizing a workspace for each cost more than solving it.
IslandReport solveLoneBody(const IslandSet& set, int index, SlotPool<Body>& bodies,
                           const StepContext& step);

/// Plans and solves islands [first, first + count) on the calling thread.
inline void solveIslands(const IslandSet& set, int first, int count, IslandWorkspace& workspace,
                         SolverStorage& storage, const StepContext& step,
                         std::uint64_t islandRevision, IslandReport* reports) {
    planIsland(set, first, count, workspace, storage, step, 1, islandRevision);
    solveIslands(Team{}, set, first, count, workspace, storage, step, reports);
}

}  // namespace pivot
