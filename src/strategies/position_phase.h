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
//      ContactSolver::withinTolerance allows.
// Contacts come first in a sweep, so a joint has the last word on a body both move, and a
// joint's error is the one users look at (as in Box2D 2.4.1's position loop).
#pragma once

#include <array>
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
    std::vector<SolverPose> xpbdStart;               // one per solver slot
    std::array<std::vector<SweepTally>, 2> tallies;  // one per member
};

/// Runs the phase. An island with nothing for NGS to check counts as solved. `scratch` is
/// sized by the caller (pseudo: the island's solver slots; tallies: the team's members).
PositionPhaseResult solvePositionPhase(const Team& team, JointGroups& groups,
                                       const IslandSchedule& schedule, ContactSolver& contacts,
                                       SolverPose* poses, SolverVelocity* velocities,
                                       PositionPhaseScratch& scratch, int iterations, float h);

}  // namespace pivot
