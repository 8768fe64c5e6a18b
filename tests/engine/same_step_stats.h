// For tests that step one world two ways that must agree (a fast path and its reference): the
// counts the solver reports in StepStats, compared field by field.
#pragma once

#include <gtest/gtest.h>

#include "pivot/world.h"

namespace pivot::test_support {

inline testing::AssertionResult sameSolverStats(const StepStats& a, const StepStats& b) {
    const auto differ = [](const char* field, int x, int y) {
        return testing::AssertionFailure() << field << ": " << x << " against " << y;
    };
    if (a.islandCount != b.islandCount) return differ("islands", a.islandCount, b.islandCount);
    if (a.positionIterations != b.positionIterations) {
        return differ("position iterations", a.positionIterations, b.positionIterations);
    }
    if (a.translationClamps != b.translationClamps) {
        return differ("translation clamps", a.translationClamps, b.translationClamps);
    }
    if (a.rotationClamps != b.rotationClamps) {
        return differ("rotation clamps", a.rotationClamps, b.rotationClamps);
    }
    if (a.letGoJointCount != b.letGoJointCount) {
        return differ("let-go joints", a.letGoJointCount, b.letGoJointCount);
    }
    if (a.edgeBodyCount != b.edgeBodyCount) {
        return differ("bodies at the edge", a.edgeBodyCount, b.edgeBodyCount);
    }
    if (a.discardedBodyCount != b.discardedBodyCount) {
        return differ("discarded bodies", a.discardedBodyCount, b.discardedBodyCount);
    }
    if (a.sleepingBodyCount != b.sleepingBodyCount) {
        return differ("sleeping bodies", a.sleepingBodyCount, b.sleepingBodyCount);
    }
    return testing::AssertionSuccess();
}

}  // namespace pivot::test_support
