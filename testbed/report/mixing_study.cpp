#include "report/mixing_study.h"

#include <algorithm>
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

// A scene of the study and the strategy its joints that matter less would take in a game.
struct MixingScene {
    const char* name;
    PositionSolver cheap;
    const char* cheapName;
};

const MixingScene kScenes[] = {
    {"ragdoll_pile", PositionSolver::Baumgarte, "Baumgarte"},
    {"bridge_chains", PositionSolver::Baumgarte, "Baumgarte"},
    {"rope_load", PositionSolver::Baumgarte, "Baumgarte"},
    {"vehicle", PositionSolver::SoftStep, "SoftStep"},  // a soft suspension
};

enum class Kind {
    FullNGS,  ///< every joint FullNGS
    Cheap,    ///< every joint the scene's cheap strategy
    Mixed,    ///< FullNGS key joints, the cheap strategy elsewhere
};

struct Setup {
    Kind kind;
    int velocity;
    int position = 3;
    int keyExtra = 0;  // the key joints' extraPositionIterations (the second knob)

    bool mixed() const { return kind == Kind::Mixed; }
    bool knob() const { return keyExtra > 0; }

    std::string name(const MixingScene& scene) const {
        const std::string split = std::to_string(velocity) + "/" + std::to_string(position);
        switch (kind) {
            case Kind::FullNGS:
                return "FullNGS " + split +
                       (knob() ? ", key +" + std::to_string(keyExtra) : std::string());
            case Kind::Cheap:
                // Baumgarte has no position phase: only its velocity iterations tell set-ups apart.
                return std::string(scene.cheapName) + " " +
                       (scene.cheap == PositionSolver::Baumgarte ? std::to_string(velocity)
                                                                 : split);
            case Kind::Mixed: return "mixed " + split;
        }
        return {};
    }

    scenes::SceneOptions options(const MixingScene& scene) const {
        scenes::SceneOptions options;
        options.solver = kind == Kind::Cheap ? scene.cheap : PositionSolver::FullNGS;
        if (mixed()) options.secondarySolver = scene.cheap;
        options.keyExtraIterations = keyExtra;
        return options;
    }
};

const Setup kSetups[] = {
    {Kind::FullNGS, 2, 1},    {Kind::FullNGS, 2},       {Kind::FullNGS, 4},
    {Kind::FullNGS, 8},       {Kind::Cheap, 8},         {Kind::Cheap, 12},
    {Kind::Cheap, 16},        {Kind::Cheap, 24},        {Kind::Mixed, 4},
    {Kind::Mixed, 8},         {Kind::FullNGS, 2, 1, 2}, {Kind::FullNGS, 2, 1, 5},
    {Kind::FullNGS, 4, 1, 2},
};

struct Result {
    const Setup* setup;
    std::string name;
    int sideJoints = 0;  // joints that are not key
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
          "and joints that matter less, a mixed island (FullNGS on the key joints, a cheap "
          "strategy on the rest: Baumgarte, or SoftStep for the vehicle's suspension) against "
          "uniform ones of either at several budgets, each the median over "
       << kTrials
       << " perturbed runs [with their range]. The error is the largest separation of the key "
          "joints; the other joints' is shown beside it, to see what they pay. Cost is *joint "
          "solves* per step: each joint once per velocity iteration, an NGS joint once more per "
          "position sweep the step ran and once per extra sweep it asked for and ran, a SoftStep "
          "joint once more per relax sweep; *us/step* is measured (contacts included). "
          "Iterations are velocity/position, one substep; *key +n*: the key joints ask for n NGS "
          "sweeps more "
          "than the world's (extraPositionIterations), the second per-joint knob. Rule, set "
          "before the runs: mixing (or the knob) pays on a scene when each mixed island's (each "
          "knob island's) median error is smaller than every plain uniform island's that costs "
          "at most "
       << num("%g", kEqualCostSlack) << " times its joint solves.\n\n";
    for (const MixingScene& scene : kScenes) {
        const char* name = scene.name;
        if (progress) progress(std::string("mixing: ") + name);
        const scenes::SceneInfo* info = scenes::findScene(name);
        if (!info) throw std::logic_error(std::string("report: no scene ") + name);
        std::vector<Result> results;
        for (const Setup& s : kSetups) {
            const scenes::SceneOptions options = s.options(scene);
            // How many joints run NGS sweeps, how many run every position iteration (relax,
            // pseudo-velocity or XPBD sweeps), and how many there are: the same in every trial.
            scenes::Scene probe = scenes::buildScene(*info, options);
            int ngs = 0;
            int everySweep = 0;
            const int joints = static_cast<int>(probe.joints.size());
            for (JointId j : probe.joints) {
                const PositionSolver solver = probe.world->jointPositionSolver(j);
                const bool isNgs =
                    solver == PositionSolver::FullNGS || solver == PositionSolver::ModifiedNGS;
                ngs += isNgs ? 1 : 0;
                everySweep += !isNgs && solver != PositionSolver::Baumgarte ? 1 : 0;
            }
            scenes::RunSettings settings;
            settings.steps = steps;
            settings.velocityIterations = s.velocity;
            settings.positionIterations = s.position;
            Result r;
            r.setup = &s;
            r.name = s.name(scene);
            r.sideJoints = joints - static_cast<int>(probe.keyJoints.size());
            r.trials = runTrials(*info, options, settings, threads, [](scenes::Scene& scene) {
                for (JointId j : scene.joints) {
                    if (std::find(scene.keyJoints.begin(), scene.keyJoints.end(), j) ==
                        scene.keyJoints.end()) {
                        scene.sideJoints.push_back(j);
                    }
                }
                scene.joints = scene.keyJoints;
            });
            out.runs += static_cast<int>(r.trials.size());
            out.raw.add(
                {name, r.name,
                 s.kind == Kind::Mixed ? std::string("mixed") : positionSolverName(options.solver),
                 options.contactCorrection, -1.0f, 1, s.velocity, s.position},
                r.trials);
            r.median = medianMetrics(r.trials);
            r.jointSolves = double(s.velocity) * joints +
                            double(ngs) * r.median.meanPositionIterations +
                            double(everySweep) * s.position + r.median.meanExtraPositionSolves;
            results.push_back(std::move(r));
        }
        md << "### " << name << "\n\n"
           << info->description << ".\n\n"
           << "| set-up | joint solves | us/step | key max sep (m) | others' max sep (m) | torn "
              "|\n"
           << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
        for (const Result& r : results) {
            md << "| " << r.name << " | " << num("%.0f", r.jointSolves) << " | "
               << num("%.1f", r.median.microsecondsPerStep) << " | "
               << spreadOf(r.trials, [](const scenes::RunMetrics& t) { return t.maxSeparation; })
                      .text()
               << " | "
               << (r.sideJoints == 0
                       ? std::string("-")
                       : spreadOf(r.trials,
                                  [](const scenes::RunMetrics& t) { return t.maxSideSeparation; })
                             .text())
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
                        rivals += std::string(rivals.empty() ? "" : ", ") + uniform.name + " (" +
                                  num("%.3g", uniform.median.maxSeparation) + " m at " +
                                  num("%.0f", uniform.jointSolves) + ")";
                    }
                }
                pays = pays && rivals.empty();
                result += std::string(result.empty() ? "" : "; ") + candidate.name + ": " +
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
                           : "mixed island (FullNGS key joints, " + std::string(scene.cheapName) +
                                 " elsewhere)") +
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
