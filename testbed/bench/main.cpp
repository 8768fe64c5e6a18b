// pivot-bench: the same scenes in pivot2d and in Box2D 2.4.1, in one process, on one machine, in
// one run. For each scene it times whole runs (a warm-up run, then repeats, alternating the
// engines so drift affects both alike), takes the median milliseconds per step of each engine
// and prints the ratio box2d / pivot ("speedup"). Then it reports heap bytes per body, joint and
// contact, counted by a replaced global operator new.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "bench/bench_scenes.h"
#include "heap/counting_new.h"

namespace {

using namespace pivot;
using Clock = std::chrono::steady_clock;

struct Options {
    bool quick = false;
    bool csv = false;
    int repeats = 3;
    int workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    bool workersGiven = false;  // --workers on the command line (--profile then uses it)
    std::string only;
    std::string profileEngine;  // --profile: step one engine, untimed, for a profiler
    int profileSteps = 0;
};

// --profile ENGINE STEPS: build the --scene in one engine and step it STEPS times on one thread
// (or --workers threads, if given), nothing else, so that a profiler (perf, callgrind) sees only
// the engine. Instructions per step are the difference of two such runs over their difference in
// steps.
int profileRun(const Options& options) {
    const int workers = options.workersGiven ? options.workers : 1;
    for (const bench::BenchScene& scene : bench::benchScenes()) {
        if (scene.name != options.only) continue;
        bench::Stepper step;
        if (options.profileEngine == "box2d") {
            step = scene.buildBox2d();
        } else if (options.profileEngine == "full_ngs") {
            step = scene.buildPivot(PositionSolver::FullNGS, workers);
        } else if (options.profileEngine == "baumgarte") {
            step = scene.buildPivot(PositionSolver::Baumgarte, workers);
        } else {
            std::cerr << "pivot-bench: --profile takes full_ngs, baumgarte or box2d (got '"
                      << options.profileEngine << "')\n";
            return 2;
        }
        for (int i = 0; i < options.profileSteps; ++i) step(i);
        return 0;
    }
    std::cerr << "pivot-bench: --profile needs --scene NAME (see --list)\n";
    return 2;
}

double millisecondsPerStep(const bench::Stepper& step, int steps) {
    Clock::time_point start = Clock::now();
    for (int i = 0; i < steps; ++i) step(i);
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count() / steps;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Result {
    std::string scene;
    double fullNgs = 0.0, baumgarte = 0.0;        // with Options::workers
    double fullNgsOne = 0.0, baumgarteOne = 0.0;  // on one thread
    double box2d = 0.0;
};

Result runScene(const bench::BenchScene& scene, const Options& options) {
    const int steps = options.quick ? std::max(10, scene.steps / 20) : scene.steps;
    auto timeIt = [&](auto build) {
        auto stepper = build();  // built outside the timed region
        return millisecondsPerStep(stepper, steps);
    };
    auto pivot = [&](PositionSolver solver, int workers) {
        return [&scene, solver, workers] { return scene.buildPivot(solver, workers); };
    };
    auto box2d = [&] { return scene.buildBox2d(); };
    if (!options.quick) {  // warm-up: caches, page faults, frequency scaling
        timeIt(pivot(PositionSolver::FullNGS, options.workers));
        timeIt(box2d);
    }
    const bool alsoOne = options.workers > 1;
    std::vector<double> full, baum, fullOne, baumOne, box;
    for (int r = 0; r < options.repeats; ++r) {
        full.push_back(timeIt(pivot(PositionSolver::FullNGS, options.workers)));
        baum.push_back(timeIt(pivot(PositionSolver::Baumgarte, options.workers)));
        if (alsoOne) {
            fullOne.push_back(timeIt(pivot(PositionSolver::FullNGS, 1)));
            baumOne.push_back(timeIt(pivot(PositionSolver::Baumgarte, 1)));
        }
        box.push_back(timeIt(box2d));
    }
    Result result{scene.name, median(full), median(baum), 0.0, 0.0, median(box)};
    result.fullNgsOne = alsoOne ? median(fullOne) : result.fullNgs;
    result.baumgarteOne = alsoOne ? median(baumOne) : result.baumgarte;
    return result;
}

// Heap bytes per body (with one circle), per joint and per contact, from worlds built to size.
void reportMemory(std::ostream& out) {
    const int n = 10000;
    long long before = heap::liveBytes();
    auto world = std::make_unique<World>();
    std::vector<BodyId> bodies;
    for (int i = 0; i < n; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {float(i % 100), float(i / 100)};
        bodies.push_back(world->createBody(def));
        world->createShape(bodies.back(), ShapeDef{}, Circle{{0, 0}, 0.25f});
    }
    long long withBodies = heap::liveBytes();
    for (int i = 1; i < n; ++i) {
        world->createJoint(RevoluteJointDef::atWorldAnchor(bodies[i - 1], bodies[i], {0, 0}));
    }
    long long withJoints = heap::liveBytes();
    world.reset();
    (void)before;

    // Contacts: a settled pyramid, measured across its first step (the step also sizes the
    // solver's reusable buffers, which are counted here too).
    auto world2 = std::make_unique<World>();
    {
        ShapeDef def;
        def.friction = 0.6f;
        BodyId ground = world2->createBody(BodyDef{});
        ShapeDef g;
        g.density = 0.0f;
        world2->createShape(ground, g, Polygon::box(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
        const float gap = 2.0f * kPolygonRadius - kLinearSlop;
        for (int row = 0; row < 40; ++row) {
            for (int i = 0; i < 40 - row; ++i) {
                BodyDef bd;
                bd.type = BodyType::Dynamic;
                bd.position = {-20.0f + (0.5f * row + i) * (1.0f + gap),
                               0.5f + gap + row * (1.0f + gap)};
                world2->createShape(world2->createBody(bd), def, Polygon::box(0.5f, 0.5f));
            }
        }
    }
    long long beforeStep = heap::liveBytes();
    world2->step(1.0f / 60.0f);
    world2->step(1.0f / 60.0f);
    long long afterStep = heap::liveBytes();
    int contacts = world2->lastStepStats().contactCount;
    char line[256];
    std::snprintf(line, sizeof line,
                  "\nheap bytes (counted through operator new):\n"
                  "  per body with one circle shape: %.0f\n"
                  "  per revolute joint:             %.0f\n"
                  "  per contact (pyramid of 40 rows, %d contacts, including the solver's "
                  "reusable buffers): %.0f\n",
                  double(withBodies - before) / n, double(withJoints - withBodies) / (n - 1),
                  contacts, contacts > 0 ? double(afterStep - beforeStep) / contacts : 0.0);
    out << line;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--quick") {
            options.quick = true;
            options.repeats = 1;
        } else if (arg == "--csv") {
            options.csv = true;
        } else if (arg == "--repeats" && i + 1 < argc) {
            options.repeats = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--workers" && i + 1 < argc) {
            options.workers = std::max(1, std::min(64, std::atoi(argv[++i])));
            options.workersGiven = true;
        } else if (arg == "--scene" && i + 1 < argc) {
            options.only = argv[++i];
        } else if (arg == "--profile" && i + 2 < argc) {
            options.profileEngine = argv[++i];
            options.profileSteps = std::max(0, std::atoi(argv[++i]));
        } else if (arg == "--list") {
            for (const bench::BenchScene& scene : bench::benchScenes()) {
                std::printf("%-15s %s\n", scene.name.c_str(), scene.description.c_str());
            }
            return 0;
        } else {
            std::cerr << "usage: pivot-bench [--quick] [--csv] [--repeats N] [--workers N] "
                         "[--scene NAME] [--list] [--profile ENGINE STEPS]\n"
                         "  Times each scene in pivot2d (FullNGS and Baumgarte joints) and in\n"
                         "  Box2D 2.4.1, sleeping and continuous collision off, 1/60 s steps\n"
                         "  with 8 velocity and 3 position iterations, and prints the median\n"
                         "  milliseconds per step and the ratio box2d / pivot. pivot2d runs with\n"
                         "  --workers threads (default: the machine's hardware threads) and, for\n"
                         "  comparison, on one thread; Box2D 2.4.1 is single-threaded.\n"
                         "  --quick    a smoke run: a twentieth of the steps, one repeat\n"
                         "  --csv      print scene,solver,pivot_ms,box2d_ms,speedup lines only\n"
                         "  --list     name and describe the scenes\n"
                         "  --profile ENGINE STEPS  step --scene STEPS times in one engine\n"
                         "             (full_ngs, baumgarte or box2d) on one thread (pivot2d:\n"
                         "             --workers threads if given), untimed, for perf or\n"
                         "             callgrind\n";
            return arg == "--help" ? 0 : 2;
        }
    }

    if (!options.only.empty()) {
        bool known = false;
        for (const bench::BenchScene& scene : bench::benchScenes())
            known |= scene.name == options.only;
        if (!known) {
            std::cerr << "pivot-bench: no scene named '" << options.only << "' (see --list)\n";
            return 2;
        }
    }

    if (!options.profileEngine.empty()) return profileRun(options);

    std::vector<Result> results;
    for (const bench::BenchScene& scene : bench::benchScenes()) {
        if (!options.only.empty() && scene.name != options.only) continue;
        if (!options.csv) std::cerr << "timing " << scene.name << "...\n";
        results.push_back(runScene(scene, options));
    }

    if (options.csv) {
        // pivot_ms is with --workers threads; see the table for one thread.
        std::cout << "scene,solver,pivot_ms,box2d_ms,speedup\n";
        for (const Result& r : results) {
            std::printf("%s,full_ngs,%.4f,%.4f,%.3f\n", r.scene.c_str(), r.fullNgs, r.box2d,
                        r.box2d / r.fullNgs);
            std::printf("%s,baumgarte,%.4f,%.4f,%.3f\n", r.scene.c_str(), r.baumgarte, r.box2d,
                        r.box2d / r.baumgarte);
        }
        return 0;
    }
    std::printf(
        "%s: median ms per step over %d run%s; sleeping and continuous collision off;\n"
        "pivot2d with %d worker thread%s (and on 1 thread); Box2D 2.4.1 single-threaded\n",
        options.quick ? "quick smoke run" : "pivot-bench", options.repeats,
        options.repeats == 1 ? "" : "s", options.workers, options.workers == 1 ? "" : "s");
    std::printf("%-15s %9s %9s %9s %9s %9s | %8s %8s %8s %8s\n", "scene", "full", "baumg.",
                "full 1t", "baumg.1t", "box2d", "x full", "x baumg.", "x full1t", "x baum1t");
    for (const Result& r : results) {
        std::printf("%-15s %9.3f %9.3f %9.3f %9.3f %9.3f | %7.2fx %7.2fx %7.2fx %7.2fx\n",
                    r.scene.c_str(), r.fullNgs, r.baumgarte, r.fullNgsOne, r.baumgarteOne, r.box2d,
                    r.box2d / r.fullNgs, r.box2d / r.baumgarte, r.box2d / r.fullNgsOne,
                    r.box2d / r.baumgarteOne);
    }
    if (options.only.empty()) reportMemory(std::cout);
    return 0;
}
