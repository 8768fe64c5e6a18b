// The PositionSolver values' names and default bias factors, read from the strategies
// themselves (position_strategies.h).
#include "strategies/position_strategies.h"

namespace pivot {

const char* positionSolverName(PositionSolver solver) {
    const char* name = "invalid";
    PositionStrategies::forEach([&](auto strategy) {
        if (decltype(strategy)::kSolver == solver) name = decltype(strategy)::kName;
    });
    return name;
}

std::optional<PositionSolver> parsePositionSolver(std::string_view text) {
    std::optional<PositionSolver> solver;
    PositionStrategies::forEach([&](auto strategy) {
        if (text == decltype(strategy)::kName) solver = decltype(strategy)::kSolver;
    });
    return solver;
}

float defaultBiasFactor(PositionSolver solver) {
    float bias = kDefaultNgsBias;
    PositionStrategies::forEach([&](auto strategy) {
        if (decltype(strategy)::kSolver == solver) bias = decltype(strategy)::kDefaultBias;
    });
    return bias;
}

}  // namespace pivot
