// Every raw run behind the report's tables, as CSV files under docs/results/ (runs-<study>.csv),
// so that anyone can re-plot or re-judge them: one row per trial, with its configuration and its
// perturbation seed, and every metric the tables take medians of (RunMetrics: recovery_s is -1
// for never and -2, like jitter_m_s, where the scene has no such phase). The last column,
// us_per_step, is a timing, which the report's check leaves out of its comparison.
#pragma once

#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/metrics.h"

namespace pivot::report {

/// How one configuration of a study was run, as its CSV rows name it.
struct RunConfig {
    std::string scene;
    std::string setup;  ///< the configuration's name in the study's table
    /// The joints' strategy (positionSolverName), or "mixed" when the joints differ.
    std::string solver;
    ContactCorrection contacts = ContactCorrection::NGS;
    float bias = -1.0f;  ///< < 0: the strategy's default
    int substeps = 1;
    int velocityIterations = kBox2D241VelocityIterations;
    int positionIterations = kBox2D241PositionIterations;
};

/// The lower-case name the CSVs give a contact correction: ngs, baumgarte, soft.
const char* contactCorrectionName(ContactCorrection contacts);

class RawRuns {
public:
    /// One row per trial, trial t with seed trialSeed(t).
    void add(const RunConfig& config, const std::vector<scenes::RunMetrics>& trials);
    /// The header and every row added, in the order added.
    std::string csv() const;

    /// The column whose values are timings (masked by the report's check).
    static constexpr const char* kTimingColumn = "us_per_step";

private:
    std::string rows_;
};

}  // namespace pivot::report
