// pivot-soak: runs testbed scenes for many steps and checks, after every step, that nothing
// went wrong that a long game session would hit:
//   - every body's pose and velocity and every joint's reaction are finite;
//   - every body stays within kPositionBound of the scene's origin;
//   - a run that blows up (scenes::isBlownUp: a runaway speed) passes only if the world
//     reported let-go joints (World::isJointLetGo, StepStats::letGoJointCount) and
//     every body stayed finite and within the bound: the engine contains a blow-up;
//   - the heap does not grow once the scene has settled: the live bytes allocated through
//     operator new (counted by heap/counting_new.h) never exceed what was live at the end of
//     the warm-up by more than the slack (kHeapSlackBytes). The warm-up is the first
//     max(2000, steps / 10) steps: every scene's scripted events are over by step 240, and the
//     chaotic ones (a whirled chain) reach their most contacts within the next thousand.
//
//   pivot-soak [--scene NAME|all] [--solver NAME|all] [--steps N] [--warmup N]
//
// Exit status 0 when every run passed, 1 otherwise, 2 on bad arguments.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "heap/counting_new.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"

namespace {

using namespace pivot;
using namespace pivot::scenes;

/// m. No body of any scene may ever be further from the scene's origin than this. The scenes are a
/// few tens of metres across; a body this far out has left through a wall or the ground, or
/// was flung by a solver.
constexpr float kPositionBound = 1.0e4f;

/// Bytes, or a fraction of what is live after the warm-up, whichever is larger: how much the
/// heap may still grow after the warm-up. A container reaching a rare new maximum (one more
/// contact than ever before, say) grows its capacity once, by a few hundred bytes; a leak of
/// even one byte per step adds 90000 bytes over the 90000 steps after a 10^5-step run's
/// warm-up.
constexpr long long kHeapSlackBytes = 4096;
constexpr long long kHeapSlackFraction = 20;  // 1/20 = 5%

struct Options {
    std::string scene = "all";
    std::string solver = "all";
    long steps = 100000;
    long warmup = -1;  // -1: max(2000, steps / 10)
};

struct RunResult {
    bool ok = true;
    std::string problem;
    long stepsTaken = 0;
    double seconds = 0.0;
    long long bytesAfterWarmup = 0;  // live when the warm-up ended
    long long peakAfterWarmup = 0;   // most live at any step after it
    long long bytesAtEnd = 0;
    long long allocationsAfterWarmup = 0;
    float farthest = 0.0f;     // m, largest |position| seen
    long lastGrowthStep = -1;  // the last step after which the heap held more than ever before
    long letGoJoints = 0;      // joints the world reported let go
    long discardedBodies = 0;  // body-steps whose non-finite solved state the world discarded
};

// What the checks look at, refreshed when the scene adds or removes bodies or joints (which
// the scenes do only during their warm-up).
struct Watched {
    std::vector<BodyId> bodies;
    std::vector<JointId> joints;
    int bodyCount = -1;
    int jointCount = -1;
    void refresh(const World& world) {
        if (world.bodyCount() == bodyCount && world.jointCount() == jointCount) return;
        bodies = world.bodyIds();
        joints = world.jointIds();
        bodyCount = world.bodyCount();
        jointCount = world.jointCount();
    }
};

std::string describe(const char* what, BodyId id, Vec2 p) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s: body %d at (%g, %g)", what, id.index,
                  static_cast<double>(p.x), static_cast<double>(p.y));
    return buffer;
}

RunResult soak(const SceneInfo& info, PositionSolver solver, long steps, long warmup) {
    RunResult result;
    SceneOptions sceneOptions;
    sceneOptions.solver = solver;
    // Soft step and XPBD are soaked with the contacts they are built to go with: soft ones
    // (velocity-level, as Box2D v3's and Avian's). NGS contacts move bodies without velocity,
    // which XPBD, deriving velocity from what moves, reads as motion (docs/position-correction.md).
    const bool fieldSolver = solver == PositionSolver::SoftStep || solver == PositionSolver::XPBD;
    sceneOptions.contactCorrection = fieldSolver ? ContactCorrection::Soft : ContactCorrection::NGS;
    Scene scene = buildScene(info, sceneOptions);
    World& world = *scene.world;
    const float dt = 1.0f / sceneOptions.hz;
    Watched watched;
    long long allocationsAtWarmup = 0;
    long long highWater = 0;

    auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, static_cast<int>(i));
        world.step(dt);
        result.stepsTaken = i + 1;

        watched.refresh(world);
        for (BodyId b : watched.bodies) {
            Vec2 p = world.bodyPosition(b);
            Vec2 v = world.bodyLinearVelocity(b);
            if (!isFinite(p) || !isFinite(v) || !std::isfinite(world.bodyAngle(b)) ||
                !std::isfinite(world.bodyAngularVelocity(b))) {
                result.problem = describe("non-finite", b, p);
                break;
            }
            float r = length(p - scene.origin);
            result.farthest = std::max(result.farthest, r);
            if (r >= kPositionBound) {
                result.problem = describe("beyond the position bound", b, p);
                break;
            }
        }
        for (JointId j : watched.joints) {
            if (!result.problem.empty()) break;
            if (!isFinite(world.jointReactionForce(j)) ||
                !std::isfinite(world.jointReactionTorque(j)) ||
                !std::isfinite(world.jointSeparation(j))) {
                result.problem = "non-finite joint " + std::to_string(j.index);
            }
        }
        const StepStats& stats = world.lastStepStats();
        result.letGoJoints += stats.letGoJointCount;
        result.discardedBodies += stats.discardedBodyCount;
        if (result.problem.empty() && isBlownUp(scene) && result.letGoJoints == 0) {
            result.problem = "the scene blew up and the world reported no let-go joint";
        }
        if (!result.problem.empty()) {
            result.ok = false;
            result.problem += " after step " + std::to_string(i);
            break;
        }

        long long live = heap::liveBytes();
        if (live > highWater) {
            highWater = live;
            result.lastGrowthStep = i;
        }
        if (i + 1 == warmup) {
            result.bytesAfterWarmup = live;
            result.peakAfterWarmup = live;
            allocationsAtWarmup = heap::allocations();
        } else if (i + 1 > warmup) {
            result.peakAfterWarmup = std::max(result.peakAfterWarmup, live);
        }
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.bytesAtEnd = heap::liveBytes();
    result.allocationsAfterWarmup = heap::allocations() - allocationsAtWarmup;
    const long long slack = std::max(kHeapSlackBytes, result.bytesAfterWarmup / kHeapSlackFraction);
    if (result.ok && steps > warmup && result.peakAfterWarmup > result.bytesAfterWarmup + slack) {
        result.ok = false;
        result.problem =
            "the heap grew after the warm-up: " + std::to_string(result.bytesAfterWarmup) +
            " bytes live at its end, " + std::to_string(result.peakAfterWarmup) + " later";
    }
    return result;
}

bool parseLong(const char* text, long& out) {
    char* end = nullptr;
    out = std::strtol(text, &end, 10);
    return end != text && *end == '\0' && out > 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: pivot-soak [--scene NAME|all] [--solver NAME|all] [--steps N] "
                 "[--warmup N]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--scene" && i + 1 < argc) {
            options.scene = argv[++i];
        } else if (arg == "--solver" && i + 1 < argc) {
            options.solver = argv[++i];
        } else if (arg == "--steps" && i + 1 < argc && parseLong(argv[i + 1], options.steps)) {
            ++i;
        } else if (arg == "--warmup" && i + 1 < argc && parseLong(argv[i + 1], options.warmup)) {
            ++i;
        } else {
            return usage();
        }
    }
    std::vector<const SceneInfo*> scenes;
    for (const SceneInfo& info : allScenes()) {
        if (options.scene == "all" || options.scene == info.name) scenes.push_back(&info);
    }
    std::vector<PositionSolver> solvers;
    for (int s = 0; s < kPositionSolverCount; ++s) {
        auto solver = static_cast<PositionSolver>(s);
        if (options.solver == "all" || options.solver == positionSolverName(solver)) {
            solvers.push_back(solver);
        }
    }
    if (scenes.empty() || solvers.empty()) {
        std::fprintf(stderr, "no such scene or solver\n");
        return usage();
    }
    const long warmup = options.warmup > 0 ? options.warmup : std::max(2000L, options.steps / 10);

    std::printf(
        "%ld steps at 60 Hz, warm-up %ld steps, position bound %g m, heap slack %lld bytes "
        "or 1/%lld\n",
        options.steps, warmup, static_cast<double>(kPositionBound), kHeapSlackBytes,
        kHeapSlackFraction);
    std::printf("%-18s %-16s %8s %8s %12s %12s %12s %10s %10s %10s %8s %9s  %s\n", "scene",
                "solver", "steps", "seconds", "heap@warmup", "heap peak", "heap@end", "allocs",
                "growth@", "farthest", "let-go", "discarded", "result");
    int failures = 0;
    for (const SceneInfo* info : scenes) {
        for (PositionSolver solver : solvers) {
            RunResult r = soak(*info, solver, options.steps, warmup);
            std::printf(
                "%-18s %-16s %8ld %8.1f %12lld %12lld %12lld %10lld %10ld %10.1f %8ld %9ld  %s\n",
                info->name, positionSolverName(solver), r.stepsTaken, r.seconds, r.bytesAfterWarmup,
                r.peakAfterWarmup, r.bytesAtEnd, r.allocationsAfterWarmup, r.lastGrowthStep,
                static_cast<double>(r.farthest), r.letGoJoints, r.discardedBodies,
                r.ok ? "ok" : r.problem.c_str());
            std::fflush(stdout);
            if (!r.ok) ++failures;
        }
    }
    if (failures > 0) {
        std::printf("%d run(s) failed\n", failures);
        return 1;
    }
    std::printf("every run passed\n");
    return 0;
}
