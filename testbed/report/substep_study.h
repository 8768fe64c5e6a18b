// The report's study of substeps and the solvers the field uses now: joint error against the
// substep count, error at equal cost, what relax iterations buy, and the goal for soft
// step, each on the stress scenes, with verdicts on the claims made for them (Solver2D,
// Macklin et al. 2019). Cost is counted in constraint sweeps (below) so that the verdicts do not
// depend on the machine; the measured microseconds are shown beside them.
//
// A sweep is one pass over every constraint of the island: each velocity iteration, each
// position iteration (a relax sweep, an NGS sweep or a pseudo-velocity iteration) counts one.
// A step of n substeps with v velocity and p position iterations costs n (v + p) sweeps
// (NGS may stop its sweeps early; the count is the budget, not what it used). Baumgarte has no
// position phase, so its share of a budget goes to velocity iterations: its p is always 0.
//
// Every configuration runs kTrials perturbed times (report/trials.h); figures are medians.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "report/observations.h"
#include "report/trials.h"
#include "scenes/metrics.h"

namespace pivot::report {

struct StudyRun {
    std::string scene;
    PositionSolver solver = PositionSolver::FullNGS;
    ContactCorrection contacts = ContactCorrection::NGS;
    float jointHertz = 0.0f;  ///< every joint's JointSoftness::hertz; 0: left at its default
    int substeps = 1;
    int velocityIterations = 1;
    int positionIterations = 1;
    scenes::RunMetrics metrics;              ///< each field the median over `trials`
    std::vector<scenes::RunMetrics> trials;  ///< one per perturbation seed

    int torn() const;
    int sweeps() const { return substeps * (velocityIterations + positionIterations); }
};

struct SubstepStudy {
    std::vector<StudyRun> runs;
    std::vector<Observation> verdicts;
    /// Markdown for docs/results.md (figures named by `figures`, which the caller writes).
    std::string markdown;
    std::vector<std::pair<std::string, std::string>> figures;  ///< (file name, SVG)
};

/// The scenes of the substep and equal-cost sweeps: chain, ball_chain, mass_ratio.
const std::vector<std::string>& substepStudyScenes();

/// Runs the study (`steps` steps per run at 60 Hz; each configuration's trials on `threads`
/// threads). `progress` is told what runs.
SubstepStudy runSubstepStudy(int steps, int threads,
                             const std::function<void(const std::string&)>& progress);

}  // namespace pivot::report
