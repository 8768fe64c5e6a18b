// The report's study of the contacts' position correction: heavy_stack (six 1 kg boxes under a
// 100 kg one), light_on_heavy (the same boxes on it) and overlap_recovery (a pyramid created a
// quarter of a box deep) with every contact correction (NGS, Baumgarte, soft) at 1, 4 and 8
// substeps of 8 velocity and 3 position iterations, and Box2D v3's soft step of 4 substeps of 1/1
// with and without its relax sweep (1/0); every configuration kTrials perturbed times. The scenes
// have no joint, so the joints' strategy plays no part.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/observations.h"
#include "report/raw_runs.h"

namespace pivot::report {

struct ContactStudy {
    std::string markdown;  ///< for docs/results.md
    int runs = 0;          ///< runs made, trials counted
    /// Solver2D's relax row on overlap_recovery, where its overshoot shows.
    std::vector<Observation> verdicts;
    RawRuns raw;  ///< every trial (docs/results/runs-contacts.csv)
};

/// Rules, written before the numbers: heavy_stack (and light_on_heavy) holds when the median run's
/// centre of mass ends less than this below where it began (a drop of a hand's breadth and the
/// settling of seven boxes, against metres when the stack collapses).
constexpr double kStackHoldsWithin = 0.5;  // m
/// overlap_recovery recovers gently when the median run's deepest overlap over its last 2 s is
/// within this, and its fastest body stayed below kGentleSpeed.
constexpr double kRecoveredOverlap = 0.015;  // m, three linear slops
constexpr double kGentleSpeed = 5.0;         // m/s

ContactStudy runContactStudy(int steps, int threads,
                             const std::function<void(const std::string&)>& progress);

}  // namespace pivot::report
