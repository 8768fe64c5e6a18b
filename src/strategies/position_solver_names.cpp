// Names and defaults of the PositionSolver values. With the switch in the solver's position
// phase, this is the only place that lists the strategies.
#include "pivot/constants.h"
#include "pivot/joint.h"

namespace pivot {

const char* positionSolverName(PositionSolver solver) {
    switch (solver) {
        case PositionSolver::Baumgarte: return "baumgarte";
        case PositionSolver::PseudoVelocity: return "pseudo_velocity";
        case PositionSolver::ModifiedNGS: return "modified_ngs";
        case PositionSolver::FullNGS: return "full_ngs";
    }
    return "invalid";
}

std::optional<PositionSolver> parsePositionSolver(std::string_view name) {
    for (int i = 0; i < kPositionSolverCount; ++i) {
        auto solver = static_cast<PositionSolver>(i);
        if (name == positionSolverName(solver)) return solver;
    }
    return std::nullopt;
}

float defaultBiasFactor(PositionSolver solver) {
    switch (solver) {
        case PositionSolver::Baumgarte: return kDefaultBaumgarteBias;
        case PositionSolver::PseudoVelocity: return kDefaultPseudoVelocityBias;
        case PositionSolver::ModifiedNGS:
        case PositionSolver::FullNGS: return kDefaultNgsBias;
    }
    return kDefaultNgsBias;
}

}  // namespace pivot
