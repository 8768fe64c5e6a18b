#include "report/pareto_study.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "report/page_text.h"
#include "report/svg.h"
#include "report/trials.h"
#include "scenes/scene.h"

namespace pivot::report {

namespace {

namespace fs = std::filesystem;

const std::vector<int> kSubsteps{1, 2, 4, 8, 16};
const std::vector<int> kVelocity{1, 2, 4, 8};
const std::vector<int> kPosition{0, 1, 3};
// Error targets of the "cheapest to hold" table, m.
const std::vector<double> kTargets{0.1, 0.05, 0.02};

double sweepCost(const ParetoRun& r) {
    return r.sweeps();
}

double timeCost(const ParetoRun& r) {
    return r.median.microsecondsPerStep;
}

// The command's output (trimmed), or "" when it fails.
std::string shell(const std::string& command) {
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
        if (::pclose(pipe) != 0) return "";
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

// The commit the study measures, and whether the code differs from it.
std::string commitMeasured(const std::string& docsDir) {
    const std::string git = "git -C '" + docsDir + "' ";
    const std::string head = shell(git + "rev-parse --short HEAD 2>/dev/null");
    if (head.empty()) return "an unknown commit (no git checkout)";
    const std::string changed =
        shell(git + "status --porcelain -- ../src ../include ../testbed 2>/dev/null");
    return "`" + head + "`" + (changed.empty() ? "" : " with uncommitted changes to the code");
}

bool selected(const std::vector<std::string>& only, const std::string& name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
}

bool selected(const std::vector<PositionSolver>& only, PositionSolver solver) {
    return only.empty() || std::find(only.begin(), only.end(), solver) != only.end();
}

std::string frontFigure(const std::vector<ParetoRun>& runs, const std::string& scene,
                        double (*cost)(const ParetoRun&), const std::string& xLabel) {
    ScatterPlot plot;
    plot.title = scene + ": each strategy's front, median largest separation against cost";
    plot.xLabel = xLabel;
    plot.yLabel = "max separation (m)";
    plot.logX = true;
    plot.logY = true;
    for (int s = 0; s < kPositionSolverCount; ++s) {
        std::vector<const ParetoRun*> mine;
        for (const ParetoRun& r : runs) {
            if (r.scene == scene && r.solver == PositionSolver(s)) mine.push_back(&r);
        }
        for (const ParetoRun* r : paretoFront(mine, cost)) {
            plot.points.push_back(
                {cost(*r), r->median.maxSeparation, positionSolverName(r->solver), r->split()});
        }
    }
    return renderScatterPlot(plot);
}

}  // namespace

std::string ParetoRun::split() const {
    return std::to_string(substeps) + " x " + std::to_string(velocityIterations) + "/" +
           std::to_string(positionIterations);
}

const std::vector<std::string>& paretoScenes() {
    static const std::vector<std::string> scenes{"chain", "ball_chain", "mass_ratio"};
    return scenes;
}

std::vector<ParetoRun> runParetoStudy(const ParetoSettings& settings, std::ostream& log) {
    std::vector<ParetoRun> runs;
    for (const std::string& scene : paretoScenes()) {
        if (!selected(settings.scenes, scene)) continue;
        if (!scenes::findScene(scene)) throw std::logic_error("report: no scene " + scene);
        for (int s = 0; s < kPositionSolverCount; ++s) {
            const auto solver = PositionSolver(s);
            if (!selected(settings.solvers, solver)) continue;
            for (int n : kSubsteps) {
                for (int v : kVelocity) {
                    for (int p : kPosition) {
                        if (solver == PositionSolver::Baumgarte && p > 0) continue;
                        ParetoRun r;
                        r.scene = scene;
                        r.solver = solver;
                        r.substeps = n;
                        r.velocityIterations = v;
                        r.positionIterations = p;
                        r.trials.resize(kTrials);
                        runs.push_back(std::move(r));
                    }
                }
            }
        }
    }
    // Trial-major: with one thread every configuration's timings interleave with the others'.
    std::mutex logMutex;
    std::size_t done = 0;
    runJobs(runs.size() * kTrials, settings.threads, [&](std::size_t job) {
        const std::size_t trial = job / runs.size();
        ParetoRun& r = runs[job % runs.size()];
        scenes::SceneOptions options;
        options.solver = r.solver;
        options.substepCount = r.substeps;
        options.perturbation = trialSeed(static_cast<int>(trial));
        scenes::Scene scene = scenes::buildScene(*scenes::findScene(r.scene), options);
        scenes::RunSettings run;
        run.steps = settings.steps;
        run.velocityIterations = r.velocityIterations;
        run.positionIterations = r.positionIterations;
        r.trials[trial] = scenes::runScene(scene, run);
        std::lock_guard<std::mutex> lock(logMutex);
        if (++done % runs.size() == 0) {
            log << "trial " << done / runs.size() << " of " << kTrials << " done\n";
        }
    });
    for (ParetoRun& r : runs) r.median = medianMetrics(r.trials);
    return runs;
}

std::string paretoCsv(const std::vector<ParetoRun>& runs, const std::string& scene) {
    std::ostringstream csv;
    csv << "scene,solver,substeps,velocity_iterations,position_iterations,sweeps,seed,"
           "max_separation_m,settled_separation_m,torn,blew_up,energy_drift_j,"
           "clamped_body_steps,ngs_iterations_per_step,us_per_step\n";
    for (const ParetoRun& r : runs) {
        if (r.scene != scene) continue;
        for (std::size_t t = 0; t < r.trials.size(); ++t) {
            const scenes::RunMetrics& m = r.trials[t];
            csv << r.scene << ',' << positionSolverName(r.solver) << ',' << r.substeps << ','
                << r.velocityIterations << ',' << r.positionIterations << ',' << r.sweeps() << ','
                << trialSeed(static_cast<int>(t)) << ',' << num("%.6g", m.maxSeparation) << ','
                << num("%.6g", m.settledSeparation) << ',' << (m.torn() ? 1 : 0) << ','
                << (m.blewUp ? 1 : 0) << ',' << num("%.6g", m.energyDrift()) << ','
                << m.clampedBodySteps() << ',' << num("%.4g", m.meanPositionIterations) << ','
                << num("%.2f", m.microsecondsPerStep) << '\n';
        }
    }
    return csv.str();
}

std::vector<const ParetoRun*> paretoFront(const std::vector<const ParetoRun*>& runs,
                                          double (*cost)(const ParetoRun&)) {
    std::vector<const ParetoRun*> sorted = runs;
    std::stable_sort(sorted.begin(), sorted.end(), [&](const ParetoRun* a, const ParetoRun* b) {
        if (cost(*a) != cost(*b)) return cost(*a) < cost(*b);
        return a->median.maxSeparation < b->median.maxSeparation;
    });
    std::vector<const ParetoRun*> front;
    for (const ParetoRun* r : sorted) {
        // NaN never enters the front; a tie in error goes to the cheaper.
        if (!(r->median.maxSeparation <
              (front.empty() ? HUGE_VAL : front.back()->median.maxSeparation))) {
            continue;
        }
        front.push_back(r);
    }
    return front;
}

std::string generateParetoStudy(const ParetoSettings& settings, std::ostream& log) {
    const fs::path docs(settings.docsDir);
    std::error_code ec;
    fs::create_directories(docs / "results", ec);
    if (ec) return "cannot create " + (docs / "results").string() + ": " + ec.message();
    const std::string commit = commitMeasured(settings.docsDir);
    const std::vector<ParetoRun> runs = runParetoStudy(settings, log);

    std::string problem;
    std::ostringstream md;
    md << "# Pareto fronts: joint error against cost\n\n"
       << "Generated by `pivot-testbed study` (run it from the repository root; about three "
          "minutes on one thread) at commit "
       << commit << ", " << todayUtc() << ", " << machineName()
       << ", one thread: " << runs.size() * kTrials << " runs of " << settings.steps
       << " steps at 60 Hz. CI regenerates FullNGS on mass_ratio and checks it against "
          "`results/pareto-mass_ratio.csv` (`pivot-testbed study --check`); the rest is as "
          "that commit made it.\n\n"
       << "Every strategy runs on the stress scenes at every split of substeps {1, 2, 4, 8, 16} "
          "x velocity iterations {1, 2, 4, 8} x position iterations {0, 1, 3} (Baumgarte, "
          "which has no position phase, at 0 only), NGS contacts, each configuration "
       << kTrials
       << " times with its own perturbation (`scenes/perturbation.h`). The error is "
          "the median over those runs of the largest joint separation over the run; a run is "
          "*torn* when a joint is still over "
       << num("%g", scenes::kTornSeparation) << " m apart in its last "
       << num("%g", scenes::kSettleSeconds)
       << " s. Cost is counted in sweeps (one pass over every constraint: a step of n substeps "
          "of v velocity and p position iterations costs n (v + p)) and in measured "
          "microseconds per step (the median of the runs, interleaved with every other "
          "configuration's). A configuration is on its strategy's front when no cheaper one "
          "of that strategy has a smaller median error. Every run is in "
          "`results/pareto-<scene>.csv`.\n\n";
    for (const std::string& scene : paretoScenes()) {
        if (!selected(settings.scenes, scene)) continue;
        const std::string csvFile = "pareto-" + scene + ".csv";
        const std::string sweepFile = "pareto-" + scene + ".svg";
        const std::string timeFile = "pareto-time-" + scene + ".svg";
        if (!writeFile(docs / "results" / csvFile, paretoCsv(runs, scene), problem) ||
            !writeFile(docs / "results" / sweepFile,
                       frontFigure(runs, scene, sweepCost, "sweeps per step"), problem) ||
            !writeFile(docs / "results" / timeFile,
                       frontFigure(runs, scene, timeCost, "microseconds per step"), problem)) {
            return problem;
        }
        md << "## " << scene << "\n\n"
           << "![" << scene << ": fronts by sweeps](results/" << sweepFile << ")\n\n"
           << "![" << scene << ": fronts by time](results/" << timeFile << ")\n\n"
           << "The cheapest configuration of each strategy whose median largest separation is "
              "within each target, by sweeps (the median decides; the front below gives how "
              "many runs tore):\n\n| strategy |";
        for (double t : kTargets) md << " within " << num("%g", t) << " m |";
        md << "\n| --- |";
        for (std::size_t i = 0; i < kTargets.size(); ++i) md << " --- |";
        md << "\n";
        for (int s = 0; s < kPositionSolverCount; ++s) {
            if (!selected(settings.solvers, PositionSolver(s))) continue;
            std::vector<const ParetoRun*> mine;
            for (const ParetoRun& r : runs) {
                if (r.scene == scene && r.solver == PositionSolver(s)) mine.push_back(&r);
            }
            const std::vector<const ParetoRun*> front = paretoFront(mine, sweepCost);
            md << "| " << positionSolverName(PositionSolver(s)) << " |";
            for (double target : kTargets) {
                const ParetoRun* cheapest = nullptr;
                for (const ParetoRun* r : front) {
                    if (r->median.maxSeparation <= target) {
                        cheapest = r;
                        break;
                    }
                }
                md << " "
                   << (cheapest ? cheapest->split() + " (" + std::to_string(cheapest->sweeps()) +
                                      " sweeps, " +
                                      num("%.3g", cheapest->median.microsecondsPerStep) + " us)"
                                : std::string("none"))
                   << " |";
            }
            md << "\n";
        }
        md << "\nEach strategy's front by sweeps:\n\n| strategy | split | sweeps | us/step | max "
              "sep (m) | torn |\n| --- | --- | ---: | ---: | ---: | ---: |\n";
        for (int s = 0; s < kPositionSolverCount; ++s) {
            std::vector<const ParetoRun*> mine;
            for (const ParetoRun& r : runs) {
                if (r.scene == scene && r.solver == PositionSolver(s)) mine.push_back(&r);
            }
            for (const ParetoRun* r : paretoFront(mine, sweepCost)) {
                md << "| " << positionSolverName(r->solver) << " | " << r->split() << " | "
                   << r->sweeps() << " | " << num("%.1f", r->median.microsecondsPerStep) << " | "
                   << spreadOf(r->trials,
                               [](const scenes::RunMetrics& t) { return t.maxSeparation; })
                          .text()
                   << " | " << tornCount(r->trials) << "/" << kTrials << " |\n";
            }
        }
        md << "\n";
    }
    if (!writeFile(docs / "pareto.md", md.str(), problem)) return problem;
    log << "wrote " << (docs / "pareto.md").string() << " and its figures and CSVs\n";
    return {};
}

std::string checkParetoStudy(const ParetoSettings& settings, std::ostream& log) {
    const std::vector<ParetoRun> runs = runParetoStudy(settings, log);
    // Every column but the last (microseconds) of each regenerated row must be a committed row.
    auto withoutTiming = [](const std::string& row) { return row.substr(0, row.rfind(',')); };
    std::string differences;
    for (const std::string& scene : paretoScenes()) {
        if (!selected(settings.scenes, scene)) continue;
        const fs::path committedPath =
            fs::path(settings.docsDir) / "results" / ("pareto-" + scene + ".csv");
        std::map<std::string, int> committed;
        std::istringstream in(readFile(committedPath));
        for (std::string line; std::getline(in, line);) ++committed[withoutTiming(line)];
        std::istringstream fresh(paretoCsv(runs, scene));
        for (std::string line; std::getline(fresh, line);) {
            auto it = committed.find(withoutTiming(line));
            if (it == committed.end() || it->second == 0) {
                differences += committedPath.string() + " lacks: " + withoutTiming(line) + "\n";
            } else {
                --it->second;
            }
        }
    }
    return differences;
}

}  // namespace pivot::report
