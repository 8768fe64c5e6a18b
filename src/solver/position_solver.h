// The four position-correction strategies. An island's joints are grouped by strategy into
// contiguous arrays (ConstraintGroups, indexed by PositionSolver); each stage below is a plain
// loop over a group, so no joint pays for a virtual call or a branch on its strategy inside an
// iteration loop. See docs/position-correction.md for the maths and for the order in which
// mixed strategies run inside one island.
#pragma once

#include <array>
#include <vector>

#include "joints/point_constraint.h"
#include "pivot/joint.h"
#include "solver/contact_solver.h"
#include "solver/solver_types.h"

namespace pivot {

using PointConstraints = std::vector<PointConstraint>;
using ConstraintGroups = std::array<PointConstraints, kPositionSolverCount>;

/// Velocity phase set-up: the velocity bias of the strategies that have one (Baumgarte:
/// biasFactor / h * C with C measured at the start of the step). Call after preparePoint.
void prepareVelocityBias(ConstraintGroups& groups, const SolverPosition* positions, float invDt);

/// One velocity iteration over every group, accumulating impulses.
void solveVelocitySweep(ConstraintGroups& groups, SolverVelocity* velocities);

struct PositionPhaseResult {
    int sweeps = 0;       ///< NGS sweeps run
    bool solved = false;  ///< every NGS joint and contact ended within tolerance
};

/// The position phase, after position integration:
///   1. PseudoVelocity: one pass of `iterations` sweeps on pseudo velocities (scratch `pseudo`,
///      one entry per island body), then positions += h * pseudo velocity;
///   2. NGS: up to `iterations` sweeps, each over the NGS contacts, then the ModifiedNGS and
///      FullNGS joints, stopping once every joint error is within kLinearSlop and no contact
///      is deeper than ContactSolver::withinTolerance allows.
/// An island with nothing for NGS to check counts as solved.
PositionPhaseResult solvePositionPhase(ConstraintGroups& groups, const ContactSolver& contacts,
                                       SolverPosition* positions,
                                       std::vector<SolverVelocity>& pseudo, int iterations,
                                       float h);

}  // namespace pivot
