// The report's method for chaotic systems: every configuration runs kTrials times, each with its
// own seeded perturbation (scenes/perturbation.h, seeds 1 to kTrials), and every figure the
// report quotes is a median over those runs with its range. kTrials is odd, so a median is a
// value one of the runs produced (a two-state scene, torn in some runs and held in others, has
// no meaningful mean of its middle two).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenes/metrics.h"

namespace pivot::report {

constexpr int kTrials = 9;

/// The perturbation seed of trial `trial` (0-based): 1 to kTrials.
inline std::uint32_t trialSeed(int trial) {
    return static_cast<std::uint32_t>(trial + 1);
}

/// A median with the smallest and largest value it was taken over.
struct Spread {
    double median = 0.0;
    double low = 0.0;
    double high = 0.0;

    /// "m [low-high]" in %.3g, or just "m" when the range prints as a single value.
    std::string text(const char* unit = "") const;
};

/// The median and range of `values` (NaN sorts last; empty gives zeros).
Spread spreadOf(std::vector<double> values);

/// The spread of one metric over the trials.
Spread spreadOf(const std::vector<scenes::RunMetrics>& trials,
                double (*metric)(const scenes::RunMetrics&));

/// Every field of RunMetrics, each the median over the trials (a recovery that never came counts
/// as the longest; blewUp is the majority's). Not one run's metrics: the fields may come from
/// different runs.
scenes::RunMetrics medianMetrics(const std::vector<scenes::RunMetrics>& trials);

/// How many of the trials came apart (RunMetrics::torn).
int tornCount(const std::vector<scenes::RunMetrics>& trials);

/// Runs `info` kTrials times, trial t built with `options` and perturbation trialSeed(t), then
/// given to `adjust` (when set) before it runs with `settings`; the trials on `threads` threads.
std::vector<scenes::RunMetrics> runTrials(const scenes::SceneInfo& info,
                                          const scenes::SceneOptions& options,
                                          const scenes::RunSettings& settings, int threads,
                                          const std::function<void(scenes::Scene&)>& adjust = {});

/// Runs job(0) ... job(count - 1) on `threads` threads (1: in order on this one). Jobs must touch
/// only their own results. Timings taken in parallel runs share the machine: the report measures
/// its timings with one thread.
void runJobs(std::size_t count, int threads, const std::function<void(std::size_t)>& job);

}  // namespace pivot::report
