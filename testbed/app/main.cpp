// pivot-testbed: runs the scenes headless and prints what each position solver does.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <thread>

#include "app/cli.h"
#include "app/table.h"
#include "replay/html_replay.h"
#include "report/defaults_study.h"
#include "report/pareto_study.h"
#include "report/report.h"
#include "report/report_check.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"
#if PIVOT_TESTBED_HAS_BOX2D
#include "app/reference_command.h"
#endif

using namespace pivot;

namespace {

std::vector<testbed::TableRow> runAll(const testbed::CliOptions& options) {
    std::vector<testbed::TableRow> rows;
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        if (options.scene && *options.scene != info.name) continue;
        for (int s = 0; s < kPositionSolverCount; ++s) {
            for (ContactCorrection contact :
                 {ContactCorrection::NGS, ContactCorrection::Baumgarte, ContactCorrection::Soft}) {
                auto solver = static_cast<PositionSolver>(s);
                if (options.solver && *options.solver != solver) continue;
                if (options.contact && *options.contact != contact) continue;
                // Soft contacts go with soft-step and XPBD joints (Box2D v3's world, Avian's
                // pairing) unless asked for.
                if (!options.contact && contact == ContactCorrection::Soft &&
                    solver != PositionSolver::SoftStep && solver != PositionSolver::XPBD) {
                    continue;
                }
                scenes::SceneOptions sceneOptions;
                sceneOptions.solver = solver;
                sceneOptions.contactCorrection = contact;
                sceneOptions.biasFactor = options.bias;
                sceneOptions.hz = options.hz;
                sceneOptions.substepCount = options.substeps;
                sceneOptions.continuous = options.continuous;
                sceneOptions.continuousCollision = options.continuousCollision;
                scenes::Scene scene = scenes::buildScene(info, sceneOptions);

                scenes::RunSettings settings;
                settings.steps = options.steps;
                settings.hz = options.hz;
                settings.velocityIterations = options.velocityIterations;
                settings.positionIterations = options.positionIterations;

                testbed::TableRow row;
                row.scene = info.name;
                row.solver = positionSolverName(solver);
                row.contact = testbed::contactCorrectionName(contact);
                row.bias = options.bias.value_or(defaultBiasFactor(solver));
                row.metrics = scenes::runScene(scene, settings);
                rows.push_back(row);
            }
        }
    }
    return rows;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        testbed::CliOptions options = testbed::parseCli({argv + 1, argv + argc});
        if (options.help) {
            std::cout << testbed::usage();
            return 0;
        }
        if (options.command == testbed::Command::Defaults) {
            report::runDefaultsStudy(std::cout);
            return 0;
        }
        if (options.command == testbed::Command::Study) {
            report::ParetoSettings settings;
            settings.docsDir = options.docsDir;
            settings.threads = std::max(1, options.jobs);
            if (options.check) {
                // A documented subset: one strategy of one scene, every split.
                settings.scenes = {"mass_ratio"};
                settings.solvers = {PositionSolver::FullNGS};
                if (options.jobs == 0) {
                    settings.threads =
                        std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
                }
                const std::string differences = report::checkParetoStudy(settings, std::cout);
                if (!differences.empty()) {
                    std::cerr << "pivot-testbed: the committed study no longer says what the "
                                 "code does; regenerate it with `pivot-testbed study`:\n"
                              << differences.substr(0, 2000);
                    return 1;
                }
                std::cout << "the committed study's FullNGS runs on mass_ratio match the code\n";
                return 0;
            }
            const std::string problem = report::generateParetoStudy(settings, std::cout);
            if (!problem.empty()) {
                std::cerr << "pivot-testbed: " << problem << "\n";
                return 1;
            }
            return 0;
        }
        if (options.command == testbed::Command::Report) {
            if (options.check) {
                const std::string differences =
                    report::checkReport(options.docsDir, options.steps, options.jobs, std::cout);
                if (!differences.empty()) {
                    std::cerr << "pivot-testbed: the committed report no longer says what the code "
                                 "does; regenerate it with `pivot-testbed report`:\n"
                              << differences;
                    return 1;
                }
                std::cout << "the committed report matches the code (timings aside)\n";
                return 0;
            }
            report::ReportSettings settings;
            settings.docsDir = options.docsDir;
            settings.steps = options.steps;
            settings.threads = std::max(1, options.jobs);
            std::string problem = report::generateReport(settings, std::cout);
            if (!problem.empty()) {
                std::cerr << "pivot-testbed: " << problem << "\n";
                return 1;
            }
            return 0;
        }
        if (options.command == testbed::Command::Reference) {
#if PIVOT_TESTBED_HAS_BOX2D
            std::ofstream csv;
            if (options.csvPath) {
                csv.open(*options.csvPath);
                if (!csv) {
                    std::cerr << "pivot-testbed: cannot write " << *options.csvPath << "\n";
                    return 1;
                }
            }
            return testbed::runReferenceCommand(std::cout, options.csvPath ? &csv : nullptr);
#else
            std::cerr << "pivot-testbed: this build has no Box2D 2.4.1; install Debian's "
                         "libbox2d-dev and build again to use 'reference'\n";
            return 1;
#endif
        }
        if (options.htmlPath) {
            std::vector<std::string> names;
            if (options.scene) {
                names.push_back(*options.scene);
            } else {
                for (const char* n : {"pendulum_drag", "chain_drag", "bridge_heavy", "ragdoll"}) {
                    if (scenes::findScene(n)) names.push_back(n);
                }
            }
            std::string problem = replay::writeReplayFile(*options.htmlPath, names);
            if (!problem.empty()) {
                std::cerr << "pivot-testbed: " << problem << "\n";
                return 1;
            }
            std::cout << "wrote " << *options.htmlPath << "\n";
            return 0;
        }
        if (options.list) {
            for (const scenes::SceneInfo& info : scenes::allScenes()) {
                std::cout << info.name << "  " << info.description << "\n";
            }
            return 0;
        }
        std::vector<testbed::TableRow> rows = runAll(options);
        std::cout << options.steps << " steps at " << options.hz << " Hz, "
                  << options.velocityIterations << " velocity / " << options.positionIterations
                  << " position iterations";
        if (options.substeps > 1) std::cout << " in each of " << options.substeps << " substeps";
        std::cout << "\n";
        testbed::printTable(std::cout, rows);
        if (options.csvPath) {
            std::ofstream csv(*options.csvPath);
            if (!csv) {
                std::cerr << "pivot-testbed: cannot write " << *options.csvPath << "\n";
                return 1;
            }
            testbed::writeCsv(csv, rows);
        }
        return 0;
    } catch (const testbed::CliError& e) {
        std::cerr << "pivot-testbed: " << e.what() << "\n";
        return 2;
    } catch (const Error& e) {
        std::cerr << "pivot-testbed: " << e.what() << "\n";
        return 1;
    }
}
