// The runs behind the generated report: every scene with every position solver, the bias sweep
// for the velocity-level solvers on the scenes that use it, and the position-iteration sweep behind
// the cost-against- error plots. Each configuration runs kTrials perturbed times (report/trials.h)
// and keeps every trial's metrics, their medians, and the median time series the plots need.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/svg.h"
#include "report/trials.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"

namespace pivot::report {

struct RunRecord {
    std::string scene;
    PositionSolver solver = PositionSolver::FullNGS;
    float bias = 0.0f;
    int positionIterations = kBox2D241PositionIterations;
    scenes::RunMetrics metrics;              ///< each field the median over `trials`
    std::vector<scenes::RunMetrics> trials;  ///< one per perturbation seed, trial order
    std::vector<float> maxSeparation;        ///< per step, the trials' median, m
    std::vector<float> jointMaxSeparation;   ///< per joint (scene order), the trials' median, m
    std::vector<SnapshotFrame> snapshots;    ///< only for the FullNGS main runs, first trial
    Vec2 origin;                             ///< the scene's (Scene::origin)
    int positionJoints = 0;                  ///< joints that hold a position (not friction, motor)

    int torn() const;  ///< trials that came apart (RunMetrics::torn)
};

struct RunMatrix {
    std::vector<RunRecord> runs;
    int steps = 0;
    float hz = 60.0f;

    /// The run with these settings, or nullptr. bias < 0 means the solver's default.
    const RunRecord* find(const std::string& scene, PositionSolver solver, float bias = -1.0f,
                          int positionIterations = kBox2D241PositionIterations) const;
};

/// Scenes of the position-iteration sweep (the cost-against-error plots).
const std::vector<std::string>& iterationSweepScenes();
/// Scenes of the bias sweep: those whose observations and prose use it (every other scene runs
/// each solver at its default bias).
const std::vector<std::string>& biasSweepScenes();
/// Biases of the sweep for Baumgarte and PseudoVelocity.
const std::vector<float>& sweptBiases();
/// Position iterations of the cost-against-error sweep.
const std::vector<int>& sweptIterations();

/// Runs the whole matrix (NGS contact correction, 8 velocity iterations) on `threads` threads.
/// `progress` is told each scene as its first run starts. With one thread the trials alternate
/// between the solvers (trial 1 of every configuration of a scene, then trial 2, ...), so that a
/// timing comparison between them is made from interleaved runs.
RunMatrix runMatrix(int steps, int threads,
                    const std::function<void(const std::string&)>& progress);

/// The world drawn now, for a snapshot strip.
SnapshotFrame captureFrame(const World& world, const std::string& caption);

}  // namespace pivot::report
