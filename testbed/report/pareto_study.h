// `pivot-testbed study`: the Pareto fronts of joint error against cost on the stress scenes
// (chain, ball_chain, mass_ratio). Every strategy runs at every split of substeps {1, 2, 4, 8, 16}
// x velocity iterations {1, 2, 4, 8} x position iterations {0, 1, 3} (Baumgarte, which has no
// position phase, at 0 only: its other rows would repeat those runs), each kTrials perturbed
// times. Cost is counted two ways: sweeps (one pass over every constraint; a step of n substeps
// of v velocity and p position iterations costs n (v + p)) and measured microseconds per step.
// A configuration is on its strategy's front when no cheaper configuration of that strategy has
// a smaller median largest separation.
//
// Every raw run goes to docs/results/pareto-<scene>.csv (one row per trial), so anyone can
// re-plot; the fronts to docs/results/pareto-<scene>.svg (sweeps) and pareto-time-<scene>.svg
// (microseconds), and the tables to docs/pareto.md, which names the commit it was made at: the
// whole study (about 10^4 runs) is too slow for CI, which checks one strategy of one scene
// (`pivot-testbed study --check`).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scenes/metrics.h"

namespace pivot::report {

struct ParetoSettings {
    std::string docsDir = "docs";
    int steps = 600;
    int threads = 1;  ///< timings are quoted from one-thread studies
    /// Only these scenes and strategies (all when empty): what `--check` regenerates.
    std::vector<std::string> scenes;
    std::vector<PositionSolver> solvers;
};

struct ParetoRun {
    std::string scene;
    PositionSolver solver = PositionSolver::FullNGS;
    int substeps = 1;
    int velocityIterations = 1;
    int positionIterations = 0;
    std::vector<scenes::RunMetrics> trials;
    scenes::RunMetrics median;

    int sweeps() const { return substeps * (velocityIterations + positionIterations); }
    std::string split() const;  ///< "n x v/p"
};

/// The scenes of the study.
const std::vector<std::string>& paretoScenes();

/// Runs the configurations `settings` selects.
std::vector<ParetoRun> runParetoStudy(const ParetoSettings& settings, std::ostream& log);

/// The runs of one scene as CSV, one row per trial (timings in the last column).
std::string paretoCsv(const std::vector<ParetoRun>& runs, const std::string& scene);

/// The front of `runs` (one strategy's, or all) by `cost`: cheapest first.
std::vector<const ParetoRun*> paretoFront(const std::vector<const ParetoRun*>& runs,
                                          double (*cost)(const ParetoRun&));

/// Writes docs/pareto.md, the CSVs and the figures. Returns an empty string or the problem.
std::string generateParetoStudy(const ParetoSettings& settings, std::ostream& log);

/// Regenerates the CSV rows of `settings`' scenes and strategies and compares them, timings
/// aside, with the committed CSVs. Returns an empty string when they agree.
std::string checkParetoStudy(const ParetoSettings& settings, std::ostream& log);

}  // namespace pivot::report
