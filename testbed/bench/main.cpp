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
#include "bench/query_bench.h"
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

std::string setupNames() {
    std::string names;
    for (const bench::PivotSetup& setup : bench::pivotSetups()) {
        names += (names.empty() ? "" : ", ") + std::string(setup.name);
    }
    return names;
}

// --profile ENGINE STEPS: build the --scene in one engine and step it STEPS times on one thread
// (or --workers threads, if given), nothing else, so that a profiler (perf, callgrind) sees only
// the engine. Instructions per step are the difference of two such runs over their difference in
// steps.
int profileRun(const Options& options) {
    const int workers = options.workersGiven ? options.workers : 1;
    for (const bench::BenchScene& scene : bench::benchScenes()) {
        if (scene.name != options.only) continue;
        bench::Stepper step;
        if (options.profileEngine == "box2d") step = scene.buildBox2d();
        for (const bench::PivotSetup& setup : bench::pivotSetups()) {
            if (options.profileEngine == setup.name) step = scene.buildPivot(setup, workers);
        }
        if (!step) {
            std::cerr << "pivot-bench: --profile takes " << setupNames() << " or box2d (got '"
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

// One timed configuration of a scene: pivot2d set up one way on `threads` threads.
struct Row {
    std::string scene;
    std::string engine;
    int threads = 1;
    double pivot = 0.0;  // median ms per step
    double box2d = 0.0;  // Box2D 2.4.1's, single-threaded, timed in the same rounds
};

// Every setup on one thread and, when --workers is above one, on that many; each round times
// every configuration once and Box2D once, so drift touches all alike.
std::vector<Row> runScene(const bench::BenchScene& scene, const Options& options) {
    const int steps = options.quick ? std::max(10, scene.steps / 20) : scene.steps;
    auto timeIt = [&](auto build) {
        auto stepper = build();  // built outside the timed region
        return millisecondsPerStep(stepper, steps);
    };
    std::vector<int> threads{1};
    if (options.workers > 1) threads.push_back(options.workers);
    const std::vector<bench::PivotSetup>& setups = bench::pivotSetups();
    auto box2d = [&] { return scene.buildBox2d(); };
    if (!options.quick) {  // warm-up: caches, page faults, frequency scaling
        timeIt([&] { return scene.buildPivot(setups.front(), threads.back()); });
        timeIt(box2d);
    }
    std::vector<std::vector<double>> times(threads.size() * setups.size());
    std::vector<double> box;
    for (int r = 0; r < options.repeats; ++r) {
        for (std::size_t t = 0; t < threads.size(); ++t) {
            for (std::size_t s = 0; s < setups.size(); ++s) {
                times[t * setups.size() + s].push_back(
                    timeIt([&] { return scene.buildPivot(setups[s], threads[t]); }));
            }
        }
        box.push_back(timeIt(box2d));
    }
    std::vector<Row> rows;
    for (std::size_t t = 0; t < threads.size(); ++t) {
        for (std::size_t s = 0; s < setups.size(); ++s) {
            rows.push_back({scene.name, setups[s].name, threads[t],
                            median(times[t * setups.size() + s]), median(box)});
        }
    }
    return rows;
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
        } else if (arg == "--continuous" && i + 1 < argc &&
                   (std::string(argv[i + 1]) == "on" || std::string(argv[i + 1]) == "off")) {
            bench::setContinuousCollision(std::string(argv[++i]) == "on");
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
                         "[--scene NAME] [--continuous on|off] [--list] [--profile ENGINE "
                         "STEPS]\n"
                         "  Times each scene in pivot2d and in Box2D 2.4.1, sleeping off,\n"
                         "  continuous collision on in both, 1/60 s steps, and prints the median\n"
                         "  milliseconds per step and the ratio box2d / pivot. pivot2d runs as\n"
                         "  full_ngs (8/3), baumgarte (8/3) and soft_step (4 substeps of 1/1,\n"
                         "  soft contacts), on one thread and on --workers threads (default: the\n"
                         "  machine's hardware threads); Box2D 2.4.1 is single-threaded, 8/3.\n"
                         "  --quick    a smoke run: a twentieth of the steps, one repeat\n"
                         "  --csv      print scene,engine,threads,pivot_ms,box2d_ms,speedup lines\n"
                         "  --continuous off  continuous collision off in both engines (on by\n"
                         "             default, as in both engines and in the testbed scenes)\n"
                         "  --list     name and describe the scenes\n"
                         "  --scene queries  only the query rows (ray casts and box queries in\n"
                         "             10^4 shapes), which a full run prints after the scenes\n"
                         "  --profile ENGINE STEPS  step --scene STEPS times in one engine\n"
                         "             (full_ngs, baumgarte, soft_step or box2d) on one thread\n"
                         "             (pivot2d: --workers threads if given), untimed, for perf\n"
                         "             or callgrind\n";
            return arg == "--help" ? 0 : 2;
        }
    }

    const bool queriesOnly = options.only == "queries";
    if (!options.only.empty() && !queriesOnly) {
        bool known = false;
        for (const bench::BenchScene& scene : bench::benchScenes())
            known |= scene.name == options.only;
        if (!known) {
            std::cerr << "pivot-bench: no scene named '" << options.only << "' (see --list)\n";
            return 2;
        }
    }

    if (!options.profileEngine.empty()) return profileRun(options);

    std::vector<Row> rows;
    for (const bench::BenchScene& scene : bench::benchScenes()) {
        if (!options.only.empty() && scene.name != options.only) continue;
        if (!options.csv) std::cerr << "timing " << scene.name << "...\n";
        for (Row& row : runScene(scene, options)) rows.push_back(row);
    }
    // One-thread rows first: like against like (Box2D 2.4.1 has one thread).
    std::stable_sort(rows.begin(), rows.end(),
                     [](const Row& a, const Row& b) { return a.threads < b.threads; });
    std::vector<bench::QueryRow> queries;
    if (options.only.empty() || queriesOnly) {
        if (!options.csv) std::cerr << "timing queries...\n";
        queries = bench::runQueryBench(options.quick, options.repeats);
    }

    if (options.csv) {
        std::cout << "scene,engine,threads,pivot_ms,box2d_ms,speedup\n";
        for (const Row& r : rows) {
            std::printf("%s,%s,%d,%.4f,%.4f,%.3f\n", r.scene.c_str(), r.engine.c_str(), r.threads,
                        r.pivot, r.box2d, r.box2d / r.pivot);
        }
        for (const bench::QueryRow& q : queries) {
            std::printf("%s,queries,1,%.4f,%.4f,%.3f\n", q.name.c_str(), q.pivotMs, q.box2dMs,
                        q.box2dMs / q.pivotMs);
        }
        return 0;
    }
    std::printf(
        "%s: median ms per step over %d run%s; sleeping off, continuous collision %s.\n"
        "Engines: full_ngs and baumgarte (8 velocity / 3 position iterations, NGS contacts),\n"
        "soft_step (soft-step joints and contacts, 4 substeps of 1 velocity / 1 relax\n"
        "iteration); Box2D 2.4.1 at 8/3, single-threaded, beside each. x box2d = box2d / pivot.\n",
        options.quick ? "quick smoke run" : "pivot-bench", options.repeats,
        options.repeats == 1 ? "" : "s", bench::continuousCollision() ? "on" : "off");
    std::printf("%-15s %-10s %7s %9s %9s %8s\n", "scene", "engine", "threads", "pivot", "box2d",
                "x box2d");
    for (const Row& r : rows) {
        std::printf("%-15s %-10s %7d %9.3f %9.3f %7.2fx\n", r.scene.c_str(), r.engine.c_str(),
                    r.threads, r.pivot, r.box2d, r.box2d / r.pivot);
    }
    if (!queries.empty()) {
        std::printf(
            "\nqueries: ms per batch of %d (median), the same world of 10^4 static shapes "
            "(circles,\n"
            "boxes, pentagons) in both engines; Box2D 2.4.1's b2World::RayCast (closest hit) and\n"
            "QueryAABB (which reports fat boxes; pivot2d also tests each shape's own box).\n",
            options.quick ? 1000 : 10000);
        std::printf("%-15s %9s %9s %8s %12s %12s %12s\n", "query", "pivot", "box2d", "x box2d",
                    "pivot found", "box2d found", "allocations");
        for (const bench::QueryRow& q : queries) {
            std::printf("%-15s %9.3f %9.3f %7.2fx %12lld %12lld %12lld\n", q.name.c_str(),
                        q.pivotMs, q.box2dMs, q.box2dMs / q.pivotMs, q.pivotFound, q.box2dFound,
                        q.pivotAllocations);
        }
    }
    if (options.only.empty()) reportMemory(std::cout);
    return 0;
}
