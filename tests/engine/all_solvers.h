// Every position solver, for the tests that run a case with each (a new strategy joins them
// all here, and the static_assert says when this list falls behind).
#pragma once

#include <iterator>

#include "pivot/solvers.h"

namespace pivot::test_support {

inline constexpr PositionSolver kAllSolvers[] = {
    PositionSolver::Baumgarte, PositionSolver::PseudoVelocity, PositionSolver::ModifiedNGS,
    PositionSolver::FullNGS,   PositionSolver::SoftStep,       PositionSolver::XPBD};

static_assert(std::size(kAllSolvers) == kPositionSolverCount, "a position solver is missing");

}  // namespace pivot::test_support
