#include "report/report.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/contact_study.h"
#include "report/exact_baseline.h"
#include "report/mixing_study.h"
#include "report/observations.h"
#include "report/page_text.h"
#include "report/raw_runs.h"
#include "report/run_matrix.h"
#include "report/substep_study.h"
#include "report/svg.h"
#include "report/trials.h"
#include "scenes/perturbation.h"

namespace pivot::report {

namespace {

namespace fs = std::filesystem;

std::string optional(const char* spec, double v) {
    if (v == scenes::RunMetrics::kNotApplicable) return "-";
    if (v == scenes::RunMetrics::kNever) return "never";
    return num(spec, v);
}

// "k/n" trials, bold when any.
std::string countOf(int count) {
    const std::string text = std::to_string(count) + "/" + std::to_string(kTrials);
    return count > 0 ? "**" + text + "**" : text;
}

std::string runRow(const RunRecord& r, double hz) {
    const scenes::RunMetrics& m = r.metrics;
    int blewUp = 0;
    for (const scenes::RunMetrics& t : r.trials) blewUp += t.blewUp ? 1 : 0;
    const Spread maxSeparation =
        spreadOf(r.trials, [](const scenes::RunMetrics& t) { return t.maxSeparation; });
    std::ostringstream row;
    row << "| " << positionSolverName(r.solver) << " | " << num("%.2f", r.bias) << " | "
        << maxSeparation.text() << " | " << num("%.2e", m.settledSeparation) << " | "
        << countOf(r.torn()) << " | " << num("%.2e", m.rmsSeparation) << " | "
        << optional("%.2f s", m.recoverySeconds) << " | " << optional("%.2e", m.jitter) << " | "
        << num("%.3f", m.maxLimitViolation) << " | "
        << num("%.4g", m.energyDrift() * hz / std::max(1, m.steps)) << " | " << countOf(blewUp)
        << " | " << m.clampedBodySteps() << " | " << num("%.2f", m.meanPositionIterations) << " | "
        << num("%.1f", m.microsecondsPerStep) << " |\n";
    return row.str();
}

std::string separationPlot(const RunMatrix& matrix, const std::string& scene) {
    LinePlot plot;
    plot.title = scene + ": largest joint separation";
    plot.xLabel = "time (s)";
    plot.yLabel = "separation (m)";
    plot.logY = true;
    for (int s = 0; s < kPositionSolverCount; ++s) {
        const RunRecord* r = matrix.find(scene, static_cast<PositionSolver>(s));
        if (!r) continue;
        Series series;
        series.name = positionSolverName(r->solver);
        for (std::size_t i = 0; i < r->maxSeparation.size(); ++i) {
            series.points.push_back({double(i + 1) / matrix.hz, r->maxSeparation[i]});
        }
        plot.series.push_back(series);
    }
    return renderLinePlot(plot);
}

// A view of the moving parts: the static ground is 80 m wide and would shrink everything.
std::pair<Vec2, Vec2> dynamicView(const std::vector<SnapshotFrame>& frames, Vec2 origin) {
    Vec2 lower{1e9f, 1e9f}, upper{-1e9f, -1e9f};
    auto grow = [&](Vec2 p, float r) {
        lower = {std::min(lower.x, p.x - r), std::min(lower.y, p.y - r)};
        upper = {std::max(upper.x, p.x + r), std::max(upper.y, p.y + r)};
    };
    for (const SnapshotFrame& f : frames) {
        for (const auto& c : f.circles) {
            if (!c.isStatic) grow(c.center, c.radius);
        }
        for (const auto& p : f.polygons) {
            if (p.isStatic) continue;
            for (Vec2 v : p.vertices) grow(v, 0.0f);
        }
        for (const auto& j : f.joints) grow(j.first, 0.0f);
    }
    if (lower.x > upper.x) return {};
    // Keep the scene's origin, on its ground line, in view.
    lower = {std::min(lower.x, origin.x - 1.0f), std::min(lower.y, origin.y - 1.0f)};
    return {lower - Vec2{1.0f, 1.0f}, upper + Vec2{1.0f, 1.0f}};
}

std::string costPlot(const RunMatrix& matrix, const std::string& scene) {
    ScatterPlot plot;
    plot.title = scene + ": cost against error (one point per solver and position iterations)";
    plot.xLabel = "microseconds per step";
    plot.yLabel = "RMS joint separation (m)";
    plot.logY = true;
    for (int s = 0; s < kPositionSolverCount; ++s) {
        auto solver = static_cast<PositionSolver>(s);
        for (int iterations : sweptIterations()) {
            const RunRecord* r = matrix.find(scene, solver, -1.0f, iterations);
            if (!r) continue;
            plot.points.push_back({r->metrics.microsecondsPerStep, r->metrics.rmsSeparation,
                                   positionSolverName(solver), std::to_string(iterations)});
        }
    }
    return renderScatterPlot(plot);
}

// The scene tables' runs, the bias sweep's and the position-iteration sweep's, trial by trial.
RawRuns matrixRuns(const RunMatrix& matrix) {
    RawRuns raw;
    for (const RunRecord& r : matrix.runs) {
        raw.add(
            {r.scene, positionSolverName(r.solver), positionSolverName(r.solver),
             ContactCorrection::NGS, r.bias, 1, kBox2D241VelocityIterations, r.positionIterations},
            r.trials);
    }
    return raw;
}

// The substep study's runs (the error-against-substeps, equal-cost and relax sweeps).
RawRuns substepRuns(const SubstepStudy& study) {
    RawRuns raw;
    for (const StudyRun& r : study.runs) {
        std::string setup = positionSolverName(r.solver);
        if (r.jointHertz > 0.0f) setup += " at " + num("%g", r.jointHertz) + " Hz";
        raw.add({r.scene, setup, positionSolverName(r.solver), r.contacts, -1.0f, r.substeps,
                 r.velocityIterations, r.positionIterations},
                r.trials);
    }
    return raw;
}

std::string observationsMarkdown(const std::vector<Observation>& observations) {
    std::ostringstream md;
    for (const Observation& o : observations) {
        md << "### " << o.algorithm << ": \"" << o.claim << "\"\n\n"
           << "- Measured: " << o.test << ".\n"
           << "- Result: " << o.result << ".\n"
           << "- Verdict: **" << o.verdict << "**.\n\n";
    }
    return md.str();
}

std::string replaceBlock(const std::string& text, const std::string& block, bool& found) {
    std::size_t begin = text.find(kObservationsBegin);
    std::size_t end = text.find(kObservationsEnd);
    found = begin != std::string::npos && end != std::string::npos && begin < end;
    if (!found) return text;
    begin += std::string(kObservationsBegin).size();
    return text.substr(0, begin) + "\n\n" + block + text.substr(end);
}

}  // namespace

std::string generateReport(const ReportSettings& settings, std::ostream& log) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const fs::path docs(settings.docsDir);
    const fs::path figures = docs / "results";
    const fs::path pc = docs / "position-correction.md";
    std::string pcText;
    if (settings.updatePositionCorrection) {
        // Checked before the runs, so a wrong directory fails at once and writes nothing.
        std::ifstream in(pc, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        pcText = text.str();
        bool found = false;
        replaceBlock(pcText, "", found);
        if (!found) {
            return pc.string() + " has no observations block (" + kObservationsBegin + " ... " +
                   kObservationsEnd + ")";
        }
    }
    std::error_code ec;
    fs::create_directories(figures, ec);
    if (ec) return "cannot create " + figures.string() + ": " + ec.message();

    RunMatrix matrix = runMatrix(settings.steps, settings.threads, [&](const std::string& scene) {
        log << "running " << scene << "\n";
    });
    std::vector<Observation> observations = evaluateObservations(matrix);
    // The note's recommendation itself, measured on mixed islands: its verdicts join the rest.
    const MixingStudy mixing =
        runMixingStudy(settings.steps, settings.threads,
                       [&](const std::string& what) { log << "running " << what << "\n"; });
    observations.insert(observations.end(), mixing.verdicts.begin(), mixing.verdicts.end());

    std::string problem;
    std::ostringstream md;
    md << "# Results\n\n"
       << "Generated by `pivot-testbed report` (run it from the repository root to regenerate "
          "this page, its figures in `docs/results/` and the observations in "
          "`docs/position-correction.md`). Every scene runs "
       << settings.steps << " steps at 60 Hz with 8 velocity and 3 position iterations and "
       << "the NGS contact correction. Every configuration runs " << kTrials
       << " times, each with its own perturbation (seeds 1 to " << kTrials
       << ": gravity tilted and scaled, and every body's initial velocity scaled, each by up "
          "to "
       << num("%g", scenes::kPerturbation)
       << " relative; `scenes/perturbation.h`), and every figure is the median over "
          "those runs; *max sep* also gives their range. Microseconds per step depend on the "
          "machine: this run: "
       << machineName() << ", " << todayUtc()
       << ", the runs of a scene interleaved on one thread.\n\n"
       << "Columns: *max*, *RMS* and *final sep* are the joint separation |anchorB - anchorA| "
          "(largest over joints; max and RMS over the run, *settled* over its last "
       << num("%g", scenes::kSettleSeconds) << " s); *torn* counts the runs still further than "
       << num("%g", scenes::kTornSeparation)
       << " m apart then, or blown up; "
          "*recovery* is the time from the end of the scene's disturbance until every joint is "
          "back within the linear slop (5 mm) for good (`never` when it is not back by the "
          "end, `-` when the scene has no disturbance); *jitter* is the RMS speed of the "
          "bodies once the scene should be at rest (`-` when it never should be); *limit* is "
          "the furthest a limited joint went past its limit (rad); *drift* is the rate at which "
          "kinetic plus potential energy changed over the run (W: the change over the run's "
          "duration; bodies a scene adds count from the moment they appear; the tumbler is "
          "driven); *blew up* is a non-finite state or a body faster "
          "than 1e4 m/s (runs of n); *clamps* the body-steps cut short by the translation or "
          "rotation clamp (where they are many, the clamps shape the run more than the "
          "solver); *NGS its* the position iterations actually run per step.\n\n";

    md << "## The seed note's observations\n\n"
       << "Each observation of `shared/seed/position-correction.txt`, the measurement that "
          "tests it and the verdict (the rules are in `docs/position-correction.md`).\n\n"
       << "| algorithm | the note says | measured | verdict |\n| --- | --- | --- | --- |\n";
    for (const Observation& o : observations) {
        md << "| " << o.algorithm << " | \"" << o.claim << "\" | " << o.result << " | " << o.verdict
           << " |\n";
    }
    md << "\n## Scenes\n\n";

    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        const std::string name = info.name;
        md << "### " << name << "\n\n"
           << info.description << ".\n\n"
           << "| solver | bias | max sep (m) | settled (m) | torn | RMS sep (m) | recovery | "
              "jitter (m/s) | limit (rad) | drift (W) | blew up | clamps | NGS its | us/step |\n"
           << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
              "| ---: | ---: |\n";
        for (const RunRecord& r : matrix.runs) {
            if (r.scene == name && r.positionIterations == kBox2D241PositionIterations) {
                md << runRow(r, matrix.hz);
            }
        }
        const std::string plotFile = name + "-separation.svg";
        const std::string stripFile = name + "-snapshots.svg";
        if (!writeFile(figures / plotFile, separationPlot(matrix, name), problem)) return problem;
        const RunRecord* full = matrix.find(name, PositionSolver::FullNGS);
        if (full && !full->snapshots.empty()) {
            std::string strip = renderSnapshotStrip(name + " with FullNGS", full->snapshots,
                                                    dynamicView(full->snapshots, full->origin));
            if (!writeFile(figures / stripFile, strip, problem)) return problem;
        }
        md << "\n![" << name << ": separation against time](results/" << plotFile << ")\n\n"
           << "![" << name << ": snapshots with FullNGS](results/" << stripFile << ")\n\n";
    }

    md << "## Cost against error\n\n"
       << "Each point is one configuration: a position solver at 1, 2, 3, 5 or 10 position "
          "iterations (the label), its median cost in microseconds per step against its median "
          "RMS joint separation.\n\n";
    for (const std::string& scene : iterationSweepScenes()) {
        const std::string file = "cost-" + scene + ".svg";
        if (!writeFile(figures / file, costPlot(matrix, scene), problem)) return problem;
        md << "![" << scene << ": cost against error](results/" << file << ")\n\n";
        md << "| solver | iterations | RMS sep (m) | max sep (m) | us/step |\n"
           << "| --- | ---: | ---: | ---: | ---: |\n";
        for (int s = 0; s < kPositionSolverCount; ++s) {
            for (int iterations : sweptIterations()) {
                const RunRecord* r =
                    matrix.find(scene, static_cast<PositionSolver>(s), -1.0f, iterations);
                if (!r) continue;
                md << "| " << positionSolverName(r->solver) << " | " << iterations << " | "
                   << num("%.2e", r->metrics.rmsSeparation) << " | "
                   << num("%.2e", r->metrics.maxSeparation) << " | "
                   << num("%.1f", r->metrics.microsecondsPerStep) << " |\n";
            }
        }
        md << "\n";
    }

    const SubstepStudy study =
        runSubstepStudy(settings.steps, settings.threads,
                        [&](const std::string& what) { log << "running " << what << "\n"; });
    md << study.markdown;
    for (const auto& [file, svg] : study.figures) {
        if (!writeFile(figures / file, svg, problem)) return problem;
    }
    const ContactStudy contacts =
        runContactStudy(settings.steps, settings.threads,
                        [&](const std::string& what) { log << "running " << what << "\n"; });
    observations.insert(observations.end(), contacts.verdicts.begin(), contacts.verdicts.end());
    const ExactBaseline exact =
        runExactBaseline(settings.steps, settings.threads,
                         [&](const std::string& what) { log << "running " << what << "\n"; });
    md << contacts.markdown << mixing.markdown << exact.markdown;
    const std::pair<const char*, std::string> rawRuns[] = {
        {"runs-scenes.csv", matrixRuns(matrix).csv()},
        {"runs-substeps.csv", substepRuns(study).csv()},
        {"runs-contacts.csv", contacts.raw.csv()},
        {"runs-mixing.csv", mixing.raw.csv()},
        {"runs-exact.csv", exact.csv},
    };
    md << "## Every run\n\n"
       << "Every run behind the tables above, one row per perturbed trial with its seed and "
          "every metric the tables take medians of, so that anyone can re-plot or re-judge "
          "them: ";
    for (const auto& [file, csv] : rawRuns) {
        if (!writeFile(figures / file, csv, problem)) return problem;
        md << "[`results/" << file << "`](results/" << file << ")"
           << (file == rawRuns[std::size(rawRuns) - 1].first ? ".\n\n" : ", ");
    }

    double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    md << "This page took " << num("%.0f", seconds) << " s to generate ("
       << (matrix.runs.size() + study.runs.size()) * kTrials + contacts.runs + mixing.runs +
              exact.runs
       << " runs).\n";
    if (!writeFile(docs / "results.md", md.str(), problem)) return problem;

    if (settings.updatePositionCorrection) {
        bool found = false;
        std::string updated = replaceBlock(pcText, observationsMarkdown(observations), found);
        if (!writeFile(pc, updated, problem)) return problem;
    }
    log << "wrote " << (docs / "results.md").string() << " and " << figures.string() << "/ in "
        << num("%.0f", seconds) << " s\n";
    return {};
}

}  // namespace pivot::report
