// The position phase, after position integration, for every strategy and joint type:
//   1. the relax sweeps of the strategies that relax (SoftStep) and of soft contacts:
//      `iterations` velocity sweeps of their rows, rigid and without bias (joints, then
//      contacts, as in the velocity iterations);
//   2. the strategies with a pseudo-velocity pass (PseudoVelocity): `iterations` sweeps on
//      pseudo velocities that start at zero, then poses += h * pseudo velocity;
//   3. the XPBD sweeps (XPBD): `iterations` sweeps of XPBD solves on the poses, then each
//      body's velocity += its move over them / h;
//   4. the NGS sweeps: up to `iterations`, each over the NGS contacts, then the joints of the
//      strategies that take part (ModifiedNGS, then FullNGS), stopping once every joint is
//      within slop (linear and angular) and no contact is deeper than
//      ContactSolver::withinTolerance allows;
//   5. if they stopped with something out of tolerance, the extra sweeps: over only the NGS
//      joints that ask for more (Joint::extraPositionIterations), each in as many as it asks,
//      until those are within slop. On one thread, in solving order, and for each island of a
//      bundle apart, so the bits are the same on any worker count and in any bundle.
// Contacts come first in a sweep, so a joint has the last word on a body both move, and a
// joint's error is the one users look at (as in Box2D 2.4.1's position loop).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "constraints/contact_solver.h"
#include "constraints/solver_body.h"
#include "islands/island_schedule.h"
#include "islands/team.h"
#include "strategies/joint_groups.h"

namespace pivot {

struct PositionPhaseResult {
    int sweeps = 0;       ///< NGS sweeps run
    bool solved = false;  ///< every NGS joint and contact ended within tolerance
    int extraSolves = 0;  ///< joint solves of the extra sweeps (step 5)
};

/// The position phase's scratch.
struct PositionPhaseScratch {
    std::vector<SolverVelocity> pseudo;  // one per solver slot
    std::vector<SolverPose> xpbdStart;   // one per solver slot
    // One flag per NGS sweep of the island's step (substeps x iterations), set by any block of
    // the sweep that found something out of tolerance. Each is written in one sweep only and
    // read after it by every member, however late: flags are never reused within a step.
    std::unique_ptr<std::atomic<std::uint8_t>[]> sweepFailed;
    std::size_t sweepFlags = 0;  // allocated
    /// Each island's own result, for a bundle of islands (IslandSchedule::memberCount; one
    /// entry for one island), sized by the caller; written by the team's leader only.
    std::vector<PositionPhaseResult> memberResults;
    /// Room for `count` flags, all clear. On one thread, before the island is solved.
    void clearSweepFlags(std::size_t count) {
        if (count > sweepFlags) {
            sweepFailed.reset(new std::atomic<std::uint8_t>[count]);
            sweepFlags = count;
        }
        for (std::size_t i = 0; i < count; ++i) sweepFailed[i].store(0, std::memory_order_relaxed);
    }
};

/// Runs the phase of substep `substep`. An island with nothing for NGS to check counts as
/// solved. In a bundle (one thread) each island stops its NGS sweeps when it is solved, as it
/// would alone; the result is then the longest island's and whether all were solved, and
/// scratch.memberResults has each island's. `scratch` is sized by the caller (pseudo and xpbdStart:
/// the island's solver slots; sweep flags: substeps x iterations, clear).
PositionPhaseResult solvePositionPhase(const Team& team, JointGroups& groups,
                                       const IslandSchedule& schedule, ContactSolver& contacts,
                                       SolverPose* poses, SolverVelocity* velocities,
                                       PositionPhaseScratch& scratch, int iterations, float h,
                                       int substep);

}  // namespace pivot
