// The report's test of the seed note's recommendation itself: choose the position solver per
// joint. On scenes with joints that matter and joints that matter less (ragdoll_pile,
// bridge_chains, rope_load, vehicle: scenes/mixing_scenes.cpp), a mixed island (FullNGS on the
// key joints, a cheap strategy on the rest: Baumgarte, or SoftStep on the vehicle's suspension)
// against uniform islands of either at several budgets, each
// kTrials perturbed times: the key joints' error against the cost. And the second per-joint
// knob the same way: a FullNGS island whose key joints ask for extra NGS sweeps
// (extraPositionIterations) against the plain uniform islands.
//
// Cost is counted in joint solves per step, what each strategy actually does: every joint solves
// once per velocity iteration, and an NGS joint once more per position sweep the step ran (its
// early exit counted) and once per extra sweep it ran (StepStats::extraPositionSolves); a
// SoftStep joint once more per relax sweep; Baumgarte joints have no position phase. Measured
// microseconds are shown beside it (they include the contacts, which every set-up shares).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/observations.h"
#include "report/raw_runs.h"

namespace pivot::report {

struct MixingStudy {
    std::string markdown;
    std::vector<Observation> verdicts;  ///< two per scene: mixing, then extra iterations
    int runs = 0;
    RawRuns raw;  ///< every trial (docs/results/runs-mixing.csv)
};

/// Rule, written before the numbers: mixing pays on a scene when each mixed island's median
/// largest key-joint separation is smaller than that of every plain uniform island costing at
/// most this factor times the mixed one's joint solves; the extra iterations likewise.
constexpr double kEqualCostSlack = 1.1;

MixingStudy runMixingStudy(int steps, int threads,
                           const std::function<void(const std::string&)>& progress);

}  // namespace pivot::report
