// pivot-bench: the same scenes in pivot2d, Box2D 2.4.1 and (when CMake was given its source)
// Box2D v3, in one process, on one machine, in one run. Each scene is written once
// (suite/suite.h) and built through each engine's Builder. For each scene it times whole runs as
// Box2D v3's benchmark app does (the scene's first step, which may pay for a first pair search,
// is left out), on one thread and on --workers threads, every configuration once per round so
// that drift touches all alike, and prints the median milliseconds per step with ratios against
// Box2D 2.4.1 and Box2D v3. Then the ray cast and box query rows, and heap bytes per body,
// shape, joint and contact in each engine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench/engines/engine.h"
#include "bench/memory.h"
#include "bench/query_bench.h"
#include "bench/suite/suite.h"

namespace {

using namespace pivot;
using namespace pivot::bench;
using Clock = std::chrono::steady_clock;

struct Options {
    bool quick = false;
    bool csv = false;
    int repeats = 3;
    int workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    bool workersGiven = false;  // --workers on the command line (--profile then uses it)
    bool continuous = true;
    // --continuous substeps|fast: every pivot2d set-up's policy (unset: each its own).
    std::optional<ContinuousCollision> continuousCollision;
    bool predictiveBoxes = false;  // --boxes predictive: pivot2d's worlds use Box2D 2.4.1's
    bool sharedTasks = false;      // --pivot-workers tasks: pivot2d's on the bench's pool
    bool adaptWorkers = true;      // --adapt off: pivot2d's worlds on all workers every step
    std::optional<int> positionIterations;  // --position-iterations N
    std::string only;                       // --scene
    std::vector<std::string> engines;       // --engines; empty: all
    std::string profileEngine;              // --profile: step one engine, untimed, for a profiler
    int profileSteps = 0;
};

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, ',');) {
        if (!part.empty()) parts.push_back(part);
    }
    return parts;
}

std::string engineNames(const std::vector<EngineKind>& kinds) {
    std::string names;
    for (const EngineKind& kind : kinds) names += (names.empty() ? "" : ", ") + kind.name;
    return names;
}

// A run of a scene in one engine: built, then stepped; the script runs before each step.
class Run {
public:
    Run(const SuiteScene& scene, const EngineKind& kind, int threads, const Options& options) {
        WorldSettings settings;
        settings.threads = threads;
        settings.sleep = scene.sleep;
        settings.continuous = options.continuous;
        settings.continuousCollision = options.continuousCollision;
        settings.predictiveBoxes = options.predictiveBoxes;
        settings.sharedTasks = options.sharedTasks;
        settings.adaptWorkers = options.adaptWorkers;
        settings.positionIterations = options.positionIterations;
        engine_ = kind.make(settings);
        script_ = scene.build(*engine_);
    }

    void step(int i) {
        if (script_) script_(*engine_, i);
        engine_->step();
    }

    int contactCount() const { return engine_->contactCount(); }

private:
    std::unique_ptr<Engine> engine_;
    Script script_;
};

// ms per step over steps 1 .. steps - 1, as Box2D v3's app times them: the world is built and
// its first step taken outside the timed region.
double timeRun(const SuiteScene& scene, const EngineKind& kind, int threads, int steps,
               const Options& options) {
    Run run(scene, kind, threads, options);
    run.step(0);
    const Clock::time_point start = Clock::now();
    for (int i = 1; i < steps; ++i) run.step(i);
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count() /
           std::max(1, steps - 1);
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Row {
    std::string scene;
    std::string engine;
    int threads = 1;
    double ms = 0.0;                  // median ms per step
    std::optional<double> vsBox2d;    // Box2D 2.4.1's ms (one thread) / ms
    std::optional<double> vsBox2dV3;  // Box2D v3's ms on as many threads / ms
};

struct Configuration {
    const EngineKind* kind;
    int threads;
    std::vector<double> times;
};

std::vector<Row> runScene(const SuiteScene& scene, const std::vector<EngineKind>& kinds,
                          const Options& options) {
    const int steps = options.quick ? std::max(10, scene.steps / 20) : scene.steps;
    std::vector<int> threadCounts{1};
    if (options.workers > 1) threadCounts.push_back(options.workers);
    std::vector<Configuration> configurations;
    for (int threads : threadCounts) {
        for (const EngineKind& kind : kinds) {
            if (threads <= kind.maxThreads) configurations.push_back({&kind, threads, {}});
        }
    }
    if (!options.quick && !kinds.empty()) {  // warm-up: caches, page faults, clock speed
        timeRun(scene, kinds.front(), threadCounts.back(), steps, options);
    }
    for (int r = 0; r < options.repeats; ++r) {
        for (Configuration& c : configurations) {
            c.times.push_back(timeRun(scene, *c.kind, c.threads, steps, options));
        }
    }
    std::vector<Row> rows;
    for (const Configuration& c : configurations) {
        rows.push_back({scene.name, c.kind->name, c.threads, median(c.times), {}, {}});
    }
    auto find = [&](const std::string& engine, int threads) -> std::optional<double> {
        for (const Row& row : rows) {
            if (row.engine == engine && row.threads == threads) return row.ms;
        }
        return std::nullopt;
    };
    for (Row& row : rows) {
        if (auto box2d = find("box2d_2.4.1", 1)) row.vsBox2d = *box2d / row.ms;
        if (auto v3 = find("box2d_v3", row.threads)) row.vsBox2dV3 = *v3 / row.ms;
    }
    return rows;
}

std::string ratio(const std::optional<double>& value, const char* format) {
    if (!value) return "";
    char text[32];
    std::snprintf(text, sizeof text, format, *value);
    return text;
}

// --profile ENGINE STEPS: build the --scene in one engine and step it STEPS times on one thread
// (or --workers threads, if given), nothing else, so that a profiler (perf, callgrind) sees only
// the engine.
int profileRun(const Options& options, const std::vector<EngineKind>& kinds) {
    const int threads = options.workersGiven ? options.workers : 1;
    for (const SuiteScene& scene : suiteScenes()) {
        if (scene.name != options.only) continue;
        for (const EngineKind& kind : kinds) {
            if (kind.name != options.profileEngine) continue;
            Run run(scene, kind, std::min(threads, kind.maxThreads), options);
            double contacts = 0.0;
            for (int i = 0; i < options.profileSteps; ++i) {
                run.step(i);
                contacts += run.contactCount();
            }
            // The broad phase's contacts per step, to compare engines' pair finding.
            std::cerr << "pivot-bench: " << options.profileSteps << " steps, "
                      << contacts / std::max(1, options.profileSteps)
                      << " contacts per step on average\n";
            return 0;
        }
        std::cerr << "pivot-bench: --profile takes " << engineNames(kinds) << " (got '"
                  << options.profileEngine << "')\n";
        return 2;
    }
    std::cerr << "pivot-bench: --profile needs --scene NAME (see --list)\n";
    return 2;
}

void usage(const std::vector<EngineKind>& kinds) {
    std::cerr
        << "usage: pivot-bench [--quick] [--csv] [--repeats N] [--workers N] [--scene NAME]\n"
           "                   [--engines A,B,...] [--continuous on|off|substeps|fast]\n"
           "                   [--boxes compact|predictive] [--pivot-workers own|tasks]\n"
           "                   [--adapt on|off] [--position-iterations N] [--list]\n"
           "                   [--profile ENGINE STEPS]\n"
           "  Times each scene in every engine, 1/60 s steps, continuous collision on, sleeping\n"
           "  as the scene says, and prints the median milliseconds per step (the first step\n"
           "  left out, as Box2D v3's benchmark app does) with ratios: x 2.4.1 = Box2D 2.4.1's\n"
           "  ms / this row's, x v3 = Box2D v3's ms on as many threads / this row's (above 1:\n"
           "  this row is faster). Each engine runs on one thread and, where it can, on\n"
           "  --workers threads (default: the machine's hardware threads). Box2D 2.4.1 takes\n"
           "  minutes a run on spinner (its continuous collision); --engines leaves it out.\n"
           "  Engines here: "
        << engineNames(kinds)
        << "\n"
           "  --quick    a smoke run: a twentieth of the steps, one repeat\n"
           "  --csv      print scene,engine,threads,ms,vs_box2d_2.4.1,vs_box2d_v3 lines (a\n"
           "             ratio is empty when its engine did not run), then the memory table\n"
           "  --engines  only these engines (the ratios need their engine in the run)\n"
           "  --continuous off  continuous collision off in every engine; on (the default):\n"
           "             each engine's own, and each pivot2d set-up that of the engine it is\n"
           "             like for like with (full_ngs and baumgarte Box2D 2.4.1's, soft_step\n"
           "             Box2D v3's: WorldDef::continuousCollision); substeps or fast: every\n"
           "             pivot2d set-up Box2D 2.4.1's (Substeps) or Box2D v3's (FastBodies)\n"
           "  --boxes predictive  pivot2d's worlds use BroadPhaseBoxes::Predictive (Box2D\n"
           "             2.4.1's boxes) instead of the default, Compact (Box2D v3's)\n"
           "  --pivot-workers tasks  pivot2d's helpers run as tasks on the bench's pool of\n"
           "             threads, the one Box2D v3 is given (WorldDef::enqueueTask), instead of\n"
           "             on threads of the world's own (the default, --pivot-workers own)\n"
           "  --adapt off  pivot2d's worlds step on all their workers at every step\n"
           "             (WorldDef::adaptWorkerCount = false) instead of timing whether the\n"
           "             caller alone is faster (the default, --adapt on)\n"
           "  --position-iterations N  full_ngs and baumgarte take N position iterations a\n"
           "             step instead of 3 (0..100; 0: no NGS position sweeps, to see what\n"
           "             they cost)\n"
           "  --list     name and describe the scenes\n"
           "  --scene queries  only the query rows (ray casts and box queries in 10^4\n"
           "             shapes); --scene memory  only the memory rows\n"
           "  --profile ENGINE STEPS  step --scene STEPS times in one engine on one thread\n"
           "             (--workers threads if given), untimed, for perf or callgrind\n";
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<EngineKind> everyEngine = allEngines();
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
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
        } else if (arg == "--engines" && i + 1 < argc) {
            options.engines = splitCommas(argv[++i]);
        } else if (arg == "--continuous" && i + 1 < argc &&
                   (std::string(argv[i + 1]) == "on" || std::string(argv[i + 1]) == "off" ||
                    std::string(argv[i + 1]) == "substeps" || std::string(argv[i + 1]) == "fast")) {
            const std::string value = argv[++i];
            options.continuous = value != "off";
            if (value == "substeps") options.continuousCollision = ContinuousCollision::Substeps;
            if (value == "fast") options.continuousCollision = ContinuousCollision::FastBodies;
        } else if (arg == "--boxes" && i + 1 < argc &&
                   (std::string(argv[i + 1]) == "predictive" ||
                    std::string(argv[i + 1]) == "compact")) {
            options.predictiveBoxes = std::string(argv[++i]) == "predictive";
        } else if (arg == "--pivot-workers" && i + 1 < argc &&
                   (std::string(argv[i + 1]) == "tasks" || std::string(argv[i + 1]) == "own")) {
            options.sharedTasks = std::string(argv[++i]) == "tasks";
        } else if (arg == "--adapt" && i + 1 < argc &&
                   (std::string(argv[i + 1]) == "on" || std::string(argv[i + 1]) == "off")) {
            options.adaptWorkers = std::string(argv[++i]) == "on";
        } else if (arg == "--position-iterations" && i + 1 < argc) {
            char* end = nullptr;
            const long n = std::strtol(argv[i + 1], &end, 10);
            if (end == argv[i + 1] || *end != '\0' || n < 0 || n > 100) {
                std::cerr << "pivot-bench: --position-iterations takes a whole number from 0 "
                             "to 100, not '"
                          << argv[i + 1] << "'\n";
                return 2;
            }
            options.positionIterations = static_cast<int>(n);
            ++i;
        } else if (arg == "--profile" && i + 2 < argc) {
            options.profileEngine = argv[++i];
            options.profileSteps = std::max(0, std::atoi(argv[++i]));
        } else if (arg == "--list") {
            for (const SuiteScene& scene : suiteScenes()) {
                std::printf("%-15s %s\n", scene.name.c_str(), scene.description.c_str());
            }
            return 0;
        } else {
            usage(everyEngine);
            return arg == "--help" ? 0 : 2;
        }
    }

    std::vector<EngineKind> kinds;
    for (const EngineKind& kind : everyEngine) {
        if (options.engines.empty() || std::find(options.engines.begin(), options.engines.end(),
                                                 kind.name) != options.engines.end()) {
            kinds.push_back(kind);
        }
    }
    for (const std::string& name : options.engines) {
        bool known = false;
        for (const EngineKind& kind : everyEngine) known |= kind.name == name;
        if (!known) {
            std::cerr << "pivot-bench: no engine named '" << name
                      << "' (here: " << engineNames(everyEngine) << ")\n";
            return 2;
        }
    }

    const bool queriesOnly = options.only == "queries";
    const bool memoryOnly = options.only == "memory";
    if (!options.only.empty() && !queriesOnly && !memoryOnly) {
        bool known = false;
        for (const SuiteScene& scene : suiteScenes()) known |= scene.name == options.only;
        if (!known) {
            std::cerr << "pivot-bench: no scene named '" << options.only << "' (see --list)\n";
            return 2;
        }
    }
    if (!options.profileEngine.empty()) return profileRun(options, everyEngine);

    std::vector<Row> rows;
    if (!queriesOnly && !memoryOnly) {
        for (const SuiteScene& scene : suiteScenes()) {
            if (!options.only.empty() && scene.name != options.only) continue;
            if (!options.csv) std::cerr << "timing " << scene.name << "...\n";
            for (Row& row : runScene(scene, kinds, options)) {
                // As each scene is done, so that a stopped run keeps what it measured (the
                // table at the end has them all, one-thread rows first).
                if (!options.csv) {
                    std::fprintf(stderr, "  %-12s %d thread%s %9.3f ms\n", row.engine.c_str(),
                                 row.threads, row.threads == 1 ? " " : "s", row.ms);
                }
                rows.push_back(row);
            }
        }
    }
    // One-thread rows first: like against like (Box2D 2.4.1 has one thread).
    std::stable_sort(rows.begin(), rows.end(),
                     [](const Row& a, const Row& b) { return a.threads < b.threads; });
    std::vector<QueryRow> queries;
    if (options.only.empty() || queriesOnly) {
        if (!options.csv) std::cerr << "timing queries...\n";
        queries = runQueryBench(options.quick, options.repeats);
    }
    std::vector<MemoryRow> memory;
    if (options.only.empty() || memoryOnly) memory = measureMemory(kinds);

    if (options.csv) {
        std::cout << "scene,engine,threads,ms,vs_box2d_2.4.1,vs_box2d_v3\n";
        for (const Row& r : rows) {
            std::printf("%s,%s,%d,%.4f,%s,%s\n", r.scene.c_str(), r.engine.c_str(), r.threads, r.ms,
                        ratio(r.vsBox2d, "%.3f").c_str(), ratio(r.vsBox2dV3, "%.3f").c_str());
        }
        for (const QueryRow& q : queries) {
            std::printf("%s,queries,1,%.4f,%.3f,\n", q.name.c_str(), q.pivotMs,
                        q.box2dMs / q.pivotMs);
        }
        if (!memory.empty()) {  // a second table: bytes, not times
            std::cout << "\nmemory,engine,bytes_per_body,bytes_per_shape,bytes_per_joint,"
                         "bytes_per_contact\n";
            for (const MemoryRow& m : memory) {
                std::printf("memory,%s,%.0f,%.0f,%.0f,%.0f\n", m.engine.c_str(), m.perBody,
                            m.perShape, m.perJoint, m.perContact);
            }
        }
        return 0;
    }
    std::printf(
        "%s: median ms per step over %d run%s (first step left out); continuous collision "
        "%s; pivot2d's broad-phase boxes %s; pivot2d's helpers on %s%s.\n",
        options.quick ? "quick smoke run" : "pivot-bench", options.repeats,
        options.repeats == 1 ? "" : "s",
        !options.continuous            ? "off"
        : !options.continuousCollision ? "on (pivot2d: each set-up's own)"
        : *options.continuousCollision == ContinuousCollision::Substeps
            ? "on (pivot2d: Box2D 2.4.1's in every set-up)"
            : "on (pivot2d: Box2D v3's in every set-up)",
        options.predictiveBoxes ? "predictive" : "compact",
        options.sharedTasks ? "the bench's pool of threads (tasks)" : "threads of their own",
        options.adaptWorkers ? "" : ", all of them at every step");
    if (options.positionIterations) {
        std::printf("full_ngs and baumgarte: %d position iteration%s a step (not 3).\n",
                    *options.positionIterations, *options.positionIterations == 1 ? "" : "s");
    }
    for (const EngineKind& kind : kinds) {
        std::printf("  %-12s %s\n", kind.name.c_str(), kind.about.c_str());
    }
    std::printf("%-15s %-12s %7s %9s %8s %8s\n", "scene", "engine", "threads", "ms", "x 2.4.1",
                "x v3");
    for (const Row& r : rows) {
        std::printf("%-15s %-12s %7d %9.3f %8s %8s\n", r.scene.c_str(), r.engine.c_str(), r.threads,
                    r.ms, ratio(r.vsBox2d, "%.2fx").c_str(), ratio(r.vsBox2dV3, "%.2fx").c_str());
    }
    if (!queries.empty()) {
        std::printf(
            "\nqueries: ms per batch of %d (median), the same world of 10^4 static shapes "
            "(circles,\n"
            "boxes, pentagons) in pivot2d and Box2D 2.4.1; Box2D 2.4.1's b2World::RayCast "
            "(closest\n"
            "hit) and QueryAABB (which reports fat boxes; pivot2d also tests each shape's own "
            "box).\n",
            options.quick ? 1000 : 10000);
        std::printf("%-15s %9s %9s %8s %12s %12s %12s\n", "query", "pivot", "box2d", "x box2d",
                    "pivot found", "box2d found", "allocations");
        for (const QueryRow& q : queries) {
            std::printf("%-15s %9.3f %9.3f %7.2fx %12lld %12lld %12lld\n", q.name.c_str(),
                        q.pivotMs, q.box2dMs, q.box2dMs / q.pivotMs, q.pivotFound, q.box2dFound,
                        q.pivotAllocations);
        }
    }
    if (!memory.empty()) printMemory(memory);
    return 0;
}
