// The four position-correction strategies. An island's joints are grouped by strategy into
// contiguous arrays (ConstraintGroups, indexed by PositionSolver); each stage below is a plain
// loop over a group, so no joint pays for a virtual call or a branch on its strategy inside an
// iteration loop. See docs/position-correction.md for the maths and for the order in which
// mixed strategies run inside one island.
//
// Every stage takes the Team solving the island and the island's schedule: a member solves its
// share of each batch and the team syncs after each batch (a team of one just runs the loops).
#pragma once

#include <array>
#include <vector>

#include "constraints/contact_solver.h"
#include "constraints/solver_body.h"
#include "islands/island_schedule.h"
#include "islands/team.h"
#include "joints/revolute_constraint.h"
#include "pivot/joint.h"

namespace pivot {

using RevoluteConstraints = std::vector<RevoluteConstraint>;
using ConstraintGroups = std::array<RevoluteConstraints, kPositionSolverCount>;

/// Runs f(range) on this member's share of each batch in turn, syncing after each.
template <typename F>
void forEachBatch(const Team& team, const std::vector<Batch>& batches, F&& f) {
    for (const Batch& batch : batches) {
        f(team.share(batch));
        team.sync();
    }
}

/// Velocity phase set-up, after every joint is prepared: the velocity bias of the strategies
/// that have one (Baumgarte: beta / h of the pin's error and of an overshot limit, measured at
/// the start of the step). Independent per joint: each member does its share, no sync.
void prepareVelocityBias(const Team& team, ConstraintGroups& groups, const SolverPose* positions,
                         float invDt);

/// Applies every joint's warm-start impulse, group by group.
void warmStartJoints(const Team& team, const ConstraintGroups& groups,
                     const IslandSchedule& schedule, SolverVelocity* velocities);

/// One velocity iteration over every group, accumulating impulses.
void solveVelocitySweep(const Team& team, ConstraintGroups& groups, const IslandSchedule& schedule,
                        SolverVelocity* velocities);

struct PositionPhaseResult {
    int sweeps = 0;       ///< NGS sweeps run
    bool solved = false;  ///< every NGS joint and contact ended within tolerance
};

/// One member's tally of an NGS sweep.
struct SweepTally {
    float minSeparation = 0.0f;
    bool jointsWithinSlop = true;
};

/// The position phase's scratch. Tallies alternate between two rounds, so that a member can
/// publish one sweep's tally while another still reads the previous sweep's.
struct PositionPhaseScratch {
    std::vector<SolverVelocity> pseudo;              // one per solver slot
    std::array<std::vector<SweepTally>, 2> tallies;  // one per member
};

/// The position phase, after position integration and after the velocity phase's impulses were
/// stored (the PseudoVelocity pass reuses their fields):
///   1. PseudoVelocity: one pass of `iterations` sweeps on pseudo velocities, then
///      positions += h * pseudo velocity;
///   2. NGS: up to `iterations` sweeps, each over the NGS contacts, then the ModifiedNGS and
///      FullNGS joints, stopping once every joint is within slop (linear and angular) and no
///      contact is deeper than ContactSolver::withinTolerance allows.
/// An island with nothing for NGS to check counts as solved. `scratch` is sized by the caller
/// (pseudo: the island's solver slots; tallies: the team's members).
PositionPhaseResult solvePositionPhase(const Team& team, ConstraintGroups& groups,
                                       const IslandSchedule& schedule,
                                       const ContactSolver& contacts, SolverPose* positions,
                                       PositionPhaseScratch& scratch, int iterations, float h);

}  // namespace pivot
