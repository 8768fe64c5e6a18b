// For tests that step one world two ways that must agree (a fast path and its reference): the
// counts the solver reports in StepStats, compared field by field.
#pragma once

#include <gtest/gtest.h>

#include "pivot/world.h"

namespace pivot::test_support {

inline testing::AssertionResult sameSolverStats(const StepStats& a, const StepStats& b) {
    struct Field {
        const char* name;
        int StepStats::*count;
    };
    static constexpr Field kFields[] = {
        {"islands", &StepStats::islandCount},
        {"position iterations", &StepStats::positionIterations},
        {"translation clamps", &StepStats::translationClamps},
        {"rotation clamps", &StepStats::rotationClamps},
        {"let-go joints", &StepStats::letGoJointCount},
        {"bodies at the edge", &StepStats::edgeBodyCount},
        {"discarded bodies", &StepStats::discardedBodyCount},
        {"sleeping bodies", &StepStats::sleepingBodyCount},
    };
    for (const Field& field : kFields) {
        if (a.*field.count != b.*field.count) {
            return testing::AssertionFailure()
                   << field.name << ": " << a.*field.count << " against " << b.*field.count;
        }
    }
    return testing::AssertionSuccess();
}

}  // namespace pivot::test_support
