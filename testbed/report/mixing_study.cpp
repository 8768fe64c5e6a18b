#include "report/mixing_study.h"

#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "report/page_text.h"
#include "report/trials.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"

namespace pivot::report {

namespace {

struct Setup {
    const char* name;
    PositionSolver key;
    std::optional<PositionSolver> secondary;  // unset: uniform
    int velocity;
    int position = 3;
    int keyExtra = 0;  // the key joints' extraPositionIterations (the second knob)

    bool mixed() const { return secondary.has_value(); }
    bool knob() const { return keyExtra > 0; }
};

const Setup kSetups[] = {
    {"FullNGS 2/1", PositionSolver::FullNGS, std::nullopt, 2, 1},
    {"FullNGS 2/3", PositionSolver::FullNGS, std::nullopt, 2},
    {"FullNGS 4/3", PositionSolver::FullNGS, std::nullopt, 4},
    {"FullNGS 8/3", PositionSolver::FullNGS, std::nullopt, 8},
    {"Baumgarte 8", PositionSolver::Baumgarte, std::nullopt, 8},
    {"Baumgarte 12", PositionSolver::Baumgarte, std::nullopt, 12},
    {"Baumgarte 16", PositionSolver::Baumgarte, std::nullopt, 16},
    {"Baumgarte 24", PositionSolver::Baumgarte, std::nullopt, 24},
    {"mixed 4/3", PositionSolver::FullNGS, PositionSolver::Baumgarte, 4},
    {"mixed 8/3", PositionSolver::FullNGS, PositionSolver::Baumgarte, 8},
    {"FullNGS 2/1, key +2", PositionSolver::FullNGS, std::nullopt, 2, 1, 2},
    {"FullNGS 2/1, key +5", PositionSolver::FullNGS, std::nullopt, 2, 1, 5},
    {"FullNGS 4/1, key +2", PositionSolver::FullNGS, std::nullopt, 4, 1, 2},
};

scenes::SceneOptions optionsOf(const Setup& s) {
    scenes::SceneOptions options;
    options.solver = s.key;
    options.secondarySolver = s.secondary;
    options.keyExtraIterations = s.keyExtra;
    return options;
}

struct Result {
    const Setup* setup;
    std::vector<scenes::RunMetrics> trials;
    scenes::RunMetrics median;
    double jointSolves = 0.0;  // per step, the median run's
};

}  // namespace

MixingStudy runMixingStudy(int steps, int threads,
                           const std::function<void(const std::string&)>& progress) {
    MixingStudy out;
    std::ostringstream md;
    md << "## Mixing strategies in one island\n\n"
       << "The seed note's recommendation, measured: scenes with joints that matter (*key*) "
          "and joints that matter less, a mixed island (FullNGS on the key joints, Baumgarte on "
          "the rest) against uniform ones of either at several budgets, each the median over "
       << kTrials
       << " perturbed runs [with their range]. The error is the largest separation of the key "
          "joints. Cost is *joint solves* per step: each joint once per velocity iteration, an "
          "NGS joint once more per position sweep the step ran, and once per extra sweep it "
          "asked for and ran; *us/step* is measured (contacts included). Iterations are "
          "velocity/position, one substep; *key +n*: the key joints ask for n NGS sweeps more "
          "than the world's (extraPositionIterations), the second per-joint knob. Rule, set "
          "before the runs: mixing (or the knob) pays on a scene when each mixed island's (each "
          "knob island's) median error is smaller than every plain uniform island's that costs "
          "at most "
       << num("%g", kEqualCostSlack) << " times its joint solves.\n\n";
    for (const char* name : {"ragdoll_pile", "bridge_chains", "rope_load"}) {
        if (progress) progress(std::string("mixing: ") + name);
        const scenes::SceneInfo* info = scenes::findScene(name);
        if (!info) throw std::logic_error(std::string("report: no scene ") + name);
        std::vector<Result> results;
        for (const Setup& s : kSetups) {
            const scenes::SceneOptions options = optionsOf(s);
            // How many joints run NGS sweeps, and how many there are: the same in every trial.
            scenes::Scene probe = scenes::buildScene(*info, options);
            int ngs = 0;
            const int joints = static_cast<int>(probe.joints.size());
            for (JointId j : probe.joints) {
                ngs += probe.world->jointPositionSolver(j) == PositionSolver::FullNGS ? 1 : 0;
            }
            scenes::RunSettings settings;
            settings.steps = steps;
            settings.velocityIterations = s.velocity;
            settings.positionIterations = s.position;
            Result r;
            r.setup = &s;
            r.trials = runTrials(*info, options, settings, threads,
                                 [](scenes::Scene& scene) { scene.joints = scene.keyJoints; });
            out.runs += static_cast<int>(r.trials.size());
            r.median = medianMetrics(r.trials);
            r.jointSolves = double(s.velocity) * joints +
                            double(ngs) * r.median.meanPositionIterations +
                            r.median.meanExtraPositionSolves;
            results.push_back(std::move(r));
        }
        md << "### " << name << "\n\n"
           << info->description << ".\n\n"
           << "| set-up | joint solves | us/step | key max sep (m) | torn |\n"
           << "| --- | ---: | ---: | ---: | ---: |\n";
        for (const Result& r : results) {
            md << "| " << r.setup->name << " | " << num("%.0f", r.jointSolves) << " | "
               << num("%.1f", r.median.microsecondsPerStep) << " | "
               << spreadOf(r.trials, [](const scenes::RunMetrics& t) { return t.maxSeparation; })
                      .text()
               << " | " << tornCount(r.trials) << "/" << kTrials << " |\n";
        }
        // The verdicts: each mixed island, then each island whose key joints ask for extra
        // sweeps, against the plain uniform islands as cheap.
        for (const bool knob : {false, true}) {
            std::string result;
            bool pays = true;
            for (const Result& candidate : results) {
                if (knob ? !candidate.setup->knob() : !candidate.setup->mixed()) continue;
                std::string rivals;
                for (const Result& uniform : results) {
                    if (uniform.setup->mixed() || uniform.setup->knob()) continue;
                    if (uniform.jointSolves > kEqualCostSlack * candidate.jointSolves) continue;
                    if (!(candidate.median.maxSeparation < uniform.median.maxSeparation)) {
                        rivals += std::string(rivals.empty() ? "" : ", ") +
                                  uniform.setup->name + " (" +
                                  num("%.3g", uniform.median.maxSeparation) + " m at " +
                                  num("%.0f", uniform.jointSolves) + ")";
                    }
                }
                pays = pays && rivals.empty();
                result += std::string(result.empty() ? "" : "; ") + candidate.setup->name + ": " +
                          num("%.3g", candidate.median.maxSeparation) + " m at " +
                          num("%.0f", candidate.jointSolves) + " joint solves" +
                          (rivals.empty() ? ", no uniform island as cheap does as well"
                                          : ", matched or beaten by " + rivals);
            }
            Observation o;
            o.algorithm = std::string(knob ? "Extra iterations (" : "Mixing (") + name + ")";
            o.claim = knob ? "let the joints that matter ask for more position iterations"
                           : "choose the position-correction algorithm per joint";
            o.test = std::string(name) + ": the key joints' median largest separation of each " +
                     (knob ? "island whose key joints ask for extra NGS sweeps (FullNGS "
                             "throughout)"
                           : "mixed island (FullNGS key joints, Baumgarte elsewhere)") +
                     " against the plain uniform islands costing at most " +
                     num("%g", kEqualCostSlack) +
                     " times its joint solves; confirmed if every one is ahead of all of them";
            o.result = result;
            o.verdict = pays ? "confirmed" : "not confirmed";
            const char* says = knob ? (pays ? "Extra iterations on the key joints **pay**"
                                            : "Extra iterations on the key joints **do not pay**")
                                    : (pays ? "Mixing **pays**" : "Mixing **does not pay**");
            md << "\n" << says << " here: " << result << ".\n";
            out.verdicts.push_back(o);
        }
        md << "\n";
    }
    out.markdown = md.str();
    return out;
}

}  // namespace pivot::report
