// The four position-correction strategies. An island's joints are grouped by strategy into
// contiguous arrays (ConstraintGroups, indexed by PositionSolver); each stage below is a plain
// loop over a group, so no joint pays for a virtual call or a branch on its strategy inside an
// iteration loop. See docs/position-correction.md for the maths and for the order in which
// mixed strategies run inside one island.
#pragma once

#include <array>
#include <vector>

#include "joints/revolute_constraint.h"
#include "pivot/joint.h"
#include "solver/contact_solver.h"
#include "solver/solver_types.h"

namespace pivot {

using RevoluteConstraints = std::vector<RevoluteConstraint>;
using ConstraintGroups = std::array<RevoluteConstraints, kPositionSolverCount>;

/// Velocity phase set-up, after every joint is prepared: the velocity bias of the strategies
/// that have one (Baumgarte: beta / h of the pin's error and of an overshot limit, measured at
/// the start of the step).
void prepareVelocityBias(ConstraintGroups& groups, const SolverPosition* positions, float invDt);

/// One velocity iteration over every group, accumulating impulses.
void solveVelocitySweep(ConstraintGroups& groups, SolverVelocity* velocities);

struct PositionPhaseResult {
    int sweeps = 0;       ///< NGS sweeps run
    bool solved = false;  ///< every NGS joint and contact ended within tolerance
};

/// The position phase, after position integration and after the velocity phase's impulses were
/// stored (the PseudoVelocity pass reuses their fields):
///   1. PseudoVelocity: one pass of `iterations` sweeps on pseudo velocities (scratch `pseudo`,
///      one entry per island body), then positions += h * pseudo velocity;
///   2. NGS: up to `iterations` sweeps, each over the NGS contacts, then the ModifiedNGS and
///      FullNGS joints, stopping once every joint is within slop (linear and angular) and no
///      contact is deeper than ContactSolver::withinTolerance allows.
/// An island with nothing for NGS to check counts as solved.
PositionPhaseResult solvePositionPhase(ConstraintGroups& groups, const ContactSolver& contacts,
                                       SolverPosition* positions,
                                       std::vector<SolverVelocity>& pseudo, int iterations,
                                       float h);

}  // namespace pivot
