// The functions the page calls (web/page/app.js, through Emscripten's cwrap): a flat C
// interface over one WebSession. Every call that can meet a refusal from the engine (a
// pivot::Error, say for a bias out of range) catches it, keeps its message for pv_error, and
// returns 0: the page shows the message, and the world is as it was.
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <string>

#include "scenes/metrics.h"
#include "scenes/scene.h"
#include "web_session.h"

using namespace pivot;

namespace {

web::WebSession session;

template <typename F>
int guarded(F&& f) {
    try {
        return f() ? 1 : 0;
    } catch (const std::exception& e) {
        session.setError(e.what());
        return 0;
    }
}

bool validSolver(int solver) {
    return solver >= 0 && solver < kPositionSolverCount;
}

// Whether joint i of the scene's list is alive (scenes may destroy or let go of joints).
bool liveJoint(int i) {
    return session.loaded() && session.world().isValid(session.joint(i));
}

constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

// contacts: 0 Baumgarte, 1 NGS, 2 Soft (ContactCorrection's order); bias: a negative value for
// the solver's default. nullopt, with the error set, for an unknown solver or correction.
std::optional<web::WorldSettings> settingsOf(int solver, float bias, int contacts, int substeps,
                                             int velocityIterations, int positionIterations,
                                             int script) {
    if (!validSolver(solver) || contacts < 0 || contacts > 2) {
        session.setError("unknown solver or contact correction");
        return std::nullopt;
    }
    web::WorldSettings settings;
    settings.solver = static_cast<PositionSolver>(solver);
    if (!(bias < 0.0f)) settings.bias = bias;
    settings.contacts = static_cast<ContactCorrection>(contacts);
    settings.substeps = substeps;
    settings.velocityIterations = velocityIterations;
    settings.positionIterations = positionIterations;
    settings.script = script != 0;
    return settings;
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE int pv_scene_count() {
    return static_cast<int>(scenes::allScenes().size());
}
/// "" for a number that is no scene's.
EMSCRIPTEN_KEEPALIVE const char* pv_scene_name(int i) {
    return i >= 0 && i < pv_scene_count() ? scenes::allScenes()[static_cast<std::size_t>(i)].name
                                          : "";
}
EMSCRIPTEN_KEEPALIVE const char* pv_scene_description(int i) {
    return i >= 0 && i < pv_scene_count()
               ? scenes::allScenes()[static_cast<std::size_t>(i)].description
               : "";
}
EMSCRIPTEN_KEEPALIVE int pv_solver_count() {
    return kPositionSolverCount;
}
EMSCRIPTEN_KEEPALIVE const char* pv_solver_name(int solver) {
    return validSolver(solver) ? positionSolverName(static_cast<PositionSolver>(solver)) : "";
}

/// Builds scene `scene` with these settings (settingsOf's arguments).
EMSCRIPTEN_KEEPALIVE int pv_load(int scene, int solver, float bias, int contacts, int substeps,
                                 int velocityIterations, int positionIterations, int script) {
    return guarded([&] {
        const auto settings = settingsOf(solver, bias, contacts, substeps, velocityIterations,
                                         positionIterations, script);
        return settings && session.load(scene, *settings);
    });
}
/// The same settings for the running scene from its next step, the solver and bias aside (kept
/// for the next load).
EMSCRIPTEN_KEEPALIVE int pv_set_settings(int solver, float bias, int contacts, int substeps,
                                         int velocityIterations, int positionIterations,
                                         int script) {
    return guarded([&] {
        const auto settings = settingsOf(solver, bias, contacts, substeps, velocityIterations,
                                         positionIterations, script);
        if (!settings) return false;
        session.setSettings(*settings);
        return true;
    });
}
EMSCRIPTEN_KEEPALIVE int pv_reload() {
    return guarded([] { return session.reload(); });
}
EMSCRIPTEN_KEEPALIVE int pv_step() {
    return guarded([] {
        session.step();
        return true;
    });
}
EMSCRIPTEN_KEEPALIVE const char* pv_error() {
    return session.error().c_str();
}

/// Draws the world; returns the number of floats at pv_draw_list().
EMSCRIPTEN_KEEPALIVE int pv_draw() {
    session.draw();
    return static_cast<int>(session.drawList().size());
}
EMSCRIPTEN_KEEPALIVE const float* pv_draw_list() {
    return session.drawList().data();
}

EMSCRIPTEN_KEEPALIVE int pv_grab(float x, float y, float hertz, float forcePerKg) {
    return guarded([&] { return session.grab({x, y}, hertz, forcePerKg); });
}
EMSCRIPTEN_KEEPALIVE void pv_move_hand(float x, float y) {
    guarded([&] {
        session.moveHand({x, y});
        return true;
    });
}
EMSCRIPTEN_KEEPALIVE void pv_release() {
    guarded([] {
        session.release();
        return true;
    });
}

EMSCRIPTEN_KEEPALIVE int pv_joint_count() {
    return session.jointCount();
}
EMSCRIPTEN_KEEPALIVE int pv_joint_near(float x, float y, float radius) {
    return session.loaded() ? session.jointNear({x, y}, radius) : -1;
}
// The getters below answer NaN (or -1, "") for a joint that is not alive.
EMSCRIPTEN_KEEPALIVE int pv_joint_valid(int i) {
    return liveJoint(i) ? 1 : 0;
}
EMSCRIPTEN_KEEPALIVE const char* pv_joint_type(int i) {
    return liveJoint(i) ? jointTypeName(session.world().jointType(session.joint(i))) : "";
}
EMSCRIPTEN_KEEPALIVE float pv_joint_separation(int i) {
    return liveJoint(i) ? session.world().jointSeparation(session.joint(i)) : kNoValue;
}
/// Anchor A (which 0) or B (1), x (axis 0) or y (1).
EMSCRIPTEN_KEEPALIVE float pv_joint_anchor(int i, int which, int axis) {
    if (!liveJoint(i)) return kNoValue;
    const JointId id = session.joint(i);
    const Vec2 a = which == 0 ? session.world().jointAnchorA(id) : session.world().jointAnchorB(id);
    return axis == 0 ? a.x : a.y;
}
EMSCRIPTEN_KEEPALIVE int pv_joint_solver(int i) {
    if (!liveJoint(i)) return -1;
    return static_cast<int>(session.world().jointPositionSolver(session.joint(i)));
}
EMSCRIPTEN_KEEPALIVE int pv_set_joint_solver(int i, int solver) {
    return guarded([&] {
        if (!validSolver(solver)) {
            session.setError("unknown solver");
            return false;
        }
        session.world().setJointPositionSolver(session.joint(i),
                                               static_cast<PositionSolver>(solver));
        return true;
    });
}
EMSCRIPTEN_KEEPALIVE float pv_joint_bias(int i) {
    if (!liveJoint(i)) return kNoValue;
    return session.world().jointBiasFactor(session.joint(i));
}
/// A bias factor in [0, 1], or a negative value for the solver's default.
EMSCRIPTEN_KEEPALIVE int pv_set_joint_bias(int i, float bias) {
    return guarded([&] {
        std::optional<float> value;
        if (!(bias < 0.0f)) value = bias;
        session.world().setJointBiasFactor(session.joint(i), value);
        return true;
    });
}
EMSCRIPTEN_KEEPALIVE float pv_joint_hertz(int i) {
    if (!liveJoint(i)) return kNoValue;
    return session.world().jointSoftness(session.joint(i)).hertz;
}
EMSCRIPTEN_KEEPALIVE int pv_set_joint_hertz(int i, float hertz) {
    return guarded([&] {
        JointSoftness softness = session.world().jointSoftness(session.joint(i));
        softness.hertz = hertz;
        session.world().setJointSoftness(session.joint(i), softness);
        return true;
    });
}
/// Largest separation over the joints solved by `solver`, m; -1 when none is.
EMSCRIPTEN_KEEPALIVE float pv_largest_separation(int solver) {
    return validSolver(solver) && session.loaded()
               ? session.largestSeparation(static_cast<PositionSolver>(solver))
               : -1.0f;
}

/// The last step: 0 its cost in ms, 1 bodies simulated, 2 awake bodies' islands, 3 contacts,
/// 4 touching contacts, 5 joints solved, 6 sleeping bodies, 7 steps so far; and the world's
/// settings: 8 substeps, 9 contact correction (pv_load's numbering), 10 velocity and 11 position
/// iterations.
EMSCRIPTEN_KEEPALIVE double pv_stat(int which) {
    if (!session.loaded()) return 0.0;
    const StepStats& s = session.world().lastStepStats();
    switch (which) {
        case 0: return session.lastStepMs();
        case 1: return s.bodyCount;
        case 2: return s.islandCount;
        case 3: return s.contactCount;
        case 4: return s.touchingCount;
        case 5: return s.jointCount;
        case 6: return s.sleepingBodyCount;
        case 7: return session.stepIndex();
        case 8: return session.world().substepCount();
        case 9: return static_cast<int>(session.world().contactCorrection());
        case 10: return session.settings().velocityIterations;
        case 11: return session.settings().positionIterations;
        default: return 0.0;
    }
}

/// One run of the Pareto study's (`pivot-testbed study`, testbed/report/pareto_study.cpp), apart
/// from the page's world: scene `scene` with every joint on `solver`, perturbation `seed`, NGS
/// contacts, `substeps` x velocity/position iterations, 600 steps at 60 Hz. Returns its largest
/// joint separation (m), negated when the run tore (a joint still over 1 m apart at the end, or
/// blown up); NaN, with the error set, for a refused setting.
EMSCRIPTEN_KEEPALIVE double pv_study_run(int scene, int solver, int substeps,
                                         int velocityIterations, int positionIterations, int seed) {
    double result = kNoValue;
    guarded([&] {
        if (scene < 0 || scene >= pv_scene_count() || !validSolver(solver) || seed < 0) {
            session.setError("unknown scene or solver, or a negative seed");
            return false;
        }
        scenes::SceneOptions options;
        options.solver = static_cast<PositionSolver>(solver);
        options.substepCount = substeps;
        options.perturbation = static_cast<std::uint32_t>(seed);
        scenes::Scene run =
            scenes::buildScene(scenes::allScenes()[static_cast<std::size_t>(scene)], options);
        scenes::RunSettings settings;
        settings.steps = 600;
        settings.velocityIterations = velocityIterations;
        settings.positionIterations = positionIterations;
        const scenes::RunMetrics m = scenes::runScene(run, settings);
        // A blown-up run's separation may be NaN, which is the refusal's value: -infinity then.
        result = !m.torn()                        ? m.maxSeparation
                 : std::isfinite(m.maxSeparation) ? -m.maxSeparation
                                                  : -std::numeric_limits<double>::infinity();
        return true;
    });
    return result;
}

}  // extern "C"
