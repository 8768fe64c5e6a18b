#include "app/reference_command.h"

#include <cstdarg>
#include <cstdio>
#include <string>

#include "reference/reference_cases.h"

namespace pivot::testbed {

namespace {

void printLine(std::ostream& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void printLine(std::ostream& out, const char* format, ...) {
    char line[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    out << line;
}

void printAgreement(std::ostream& out) {
    out << "FullNGS against Box2D 2.4.1's joints: largest difference of any body's\n"
           "centre of mass and angle while stepping both (60 Hz, 8/3 iterations, continuous\n"
           "collision on in both wherever the pivot2d scene has it on: every case but chain\n"
           "and car). Required: 1e-4 over 600 steps, or over the first 30 for chaotic scenes.\n"
           "'identical' counts the steps, out of 600, before the first bit of any pose differs\n"
           "(Box2D's denormal coordinates read as 0, as pivot2d stores them). 'impacts' counts\n"
           "pivot2d's continuous-collision impacts over the 600 steps; chain+continuous is the\n"
           "chain with continuous collision switched on in both engines.\n";
    printLine(out, "%-18s %-8s %6s %13s %13s %10s %8s\n", "case", "chaotic", "steps", "max |dc| m",
              "max |da| rad", "identical", "impacts");
    scenes::SceneOptions fullNgs;
    fullNgs.solver = PositionSolver::FullNGS;
    for (const reference::ReferenceCase& c : reference::referenceCases()) {
        reference::TrajectoryDifference d =
            reference::compareTrajectories(c, fullNgs, reference::comparedSteps(c));
        reference::TrajectoryDifference whole = reference::compareTrajectories(c, fullNgs, 600);
        printLine(out, "%-18s %-8s %6d %13.3e %13.3e %10d %8d\n", c.name.c_str(),
                  c.chaotic ? "yes" : "no", d.steps, d.position, d.angle, whole.identicalSteps,
                  whole.impacts);
        if (c.name == "chain") {
            d = reference::compareTrajectories(c, fullNgs, reference::comparedSteps(c), true);
            whole = reference::compareTrajectories(c, fullNgs, 600, true);
            printLine(out, "%-18s %-8s %6d %13.3e %13.3e %10d %8d\n", "chain+continuous", "yes",
                      d.steps, d.position, d.angle, whole.identicalSteps, whole.impacts);
        }
    }
}

struct Row {
    std::string caseName;
    std::string engine;
    scenes::RunMetrics metrics;
};

void printSideBySide(std::ostream& out, const std::vector<Row>& rows) {
    out << "\nEvery position solver beside Box2D 2.4.1 over 600 steps (60 Hz, 8/3 iterations).\n"
           "'box2d' runs with continuous collision off, 'box2d+toi' with it on (Box2D's\n"
           "default). pivot2d's is on in every case but chain and car, whose testbed scenes\n"
           "measure the joints alone: 'box2d+toi' is the like-for-like row, 'box2d' for those\n"
           "two.\n";
    printLine(out, "%-16s %-22s %10s %10s %10s %12s %9s\n", "case", "engine", "max sep", "rms sep",
              "final sep", "drift J", "us/step");
    for (const Row& r : rows) {
        const scenes::RunMetrics& m = r.metrics;
        printLine(out, "%-16s %-22s %10.3e %10.3e %10.3e %12.4g %9.1f%s\n", r.caseName.c_str(),
                  r.engine.c_str(), m.maxSeparation, m.rmsSeparation, m.finalSeparation,
                  m.energyDrift(), m.microsecondsPerStep, m.blewUp ? "  blew up" : "");
    }
}

void writeCsv(std::ostream& csv, const std::vector<Row>& rows) {
    csv << "case,engine,max_sep_m,rms_sep_m,final_sep_m,energy_drift_j,us_per_step,blew_up\n";
    for (const Row& r : rows) {
        const scenes::RunMetrics& m = r.metrics;
        char line[256];
        std::snprintf(line, sizeof line, "%s,%s,%.6e,%.6e,%.6e,%.9g,%.3f,%d\n", r.caseName.c_str(),
                      r.engine.c_str(), m.maxSeparation, m.rmsSeparation, m.finalSeparation,
                      m.energyDrift(), m.microsecondsPerStep, m.blewUp ? 1 : 0);
        csv << line;
    }
}

}  // namespace

int runReferenceCommand(std::ostream& out, std::ostream* csv) {
    printAgreement(out);
    std::vector<Row> rows;
    scenes::RunSettings settings;
    for (const reference::ReferenceCase& c : reference::referenceCases()) {
        for (int s = 0; s < kPositionSolverCount; ++s) {
            scenes::SceneOptions options;
            options.solver = static_cast<PositionSolver>(s);
            scenes::Scene scene = reference::buildPivotCase(c, options);
            rows.push_back({c.name, std::string("pivot ") + positionSolverName(options.solver),
                            scenes::runScene(scene, settings)});
        }
        for (bool continuous : {false, true}) {
            box2d::Box2dScene scene = c.buildBox2d(continuous);
            rows.push_back(
                {c.name, continuous ? "box2d+toi" : "box2d", reference::runBox2d(scene, settings)});
        }
    }
    printSideBySide(out, rows);
    if (csv) writeCsv(*csv, rows);
    return 0;
}

}  // namespace pivot::testbed
