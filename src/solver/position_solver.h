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
#include "solver/solver_types.h"

namespace pivot {

using PointConstraints = std::vector<PointConstraint>;
using ConstraintGroups = std::array<PointConstraints, kPositionSolverCount>;

/// Velocity phase set-up: the velocity bias of the strategies that have one (Baumgarte:
/// biasFactor / h * C with C measured at the start of the step). Call after preparePoint.
void prepareVelocityBias(ConstraintGroups& groups, const SolverPosition* positions, float invDt);

/// One velocity iteration over every group, accumulating impulses.
void solveVelocitySweep(ConstraintGroups& groups, SolverVelocity* velocities);

/// The position phase, after position integration:
///   1. PseudoVelocity: one pass of `iterations` sweeps on pseudo velocities (scratch `pseudo`,
///      one entry per island body), then positions += h * pseudo velocity;
///   2. NGS: up to `iterations` sweeps over ModifiedNGS then FullNGS joints, stopping once every
///      error is within kLinearSlop.
/// Returns the number of NGS sweeps run.
int solvePositionPhase(ConstraintGroups& groups, SolverPosition* positions,
                       std::vector<SolverVelocity>& pseudo, int iterations, float h);

}  // namespace pivot
