// The browser testbed's simulation side: one testbed scene (scenes, the very code the
// headless testbed and the report run), stepped one 1/60 s step per call, with the page's hand
// (a mouse joint), its chosen settings, per-joint solver changes, and the world drawn into a
// flat list of numbers the page paints (web/page/app.js reads it: see DrawList).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/scene.h"

namespace pivot::web {

/// What the page sets for the whole world: all applied when a scene is (re)loaded; all but the
/// solver and bias also at once (setSettings).
struct WorldSettings {
    PositionSolver solver = PositionSolver::FullNGS;  ///< every joint's, at load: then per joint
    std::optional<float> bias;  ///< every joint's bias factor, at load; unset: the solver's default
    ContactCorrection contacts = ContactCorrection::NGS;
    int substeps = 1;
    int velocityIterations = kBox2D241VelocityIterations;
    int positionIterations = kBox2D241PositionIterations;
    bool script = true;  ///< run the scene's own script (its scripted drags, drops and motors)
};

/// The page's drawing commands, each a code and its numbers (colour channels in [0, 1], world
/// coordinates in metres):
///   kPolygon r g b radius n x1 y1 ... xn yn    kCircle r g b x y radius axisX axisY
///   kCapsule r g b x1 y1 x2 y2 radius           kSegment r g b x1 y1 x2 y2
///   kPoint r g b x y size                       kJoint r g b ax ay bx by separation
enum DrawCode : int { kPolygon = 1, kCircle, kCapsule, kSegment, kPoint, kJoint };

class WebSession {
public:
    /// Builds scene `index` of scenes::allScenes() with `settings`; false (and error()) if the
    /// index is out of range.
    bool load(int index, const WorldSettings& settings);
    /// Rebuilds the current scene with the current settings (the page's reset).
    bool reload() { return load(sceneIndex_, settings_); }
    /// Applies contact correction, substeps, iterations and script from the next step, and
    /// keeps the solver and bias for the next load (the scene's joints have theirs). Throws
    /// pivot::Error, changing nothing, if the world refuses a value.
    void setSettings(const WorldSettings& settings);
    /// One step of 1/60 s: the scene's script (if on), then World::step. Times the step.
    void step();

    /// Draws the world into the list drawList() returns (see DrawCode).
    void draw();
    const std::vector<float>& drawList() const { return drawList_; }

    /// Takes hold of the dynamic body under `point` with a hand of `hertz` whose force is capped
    /// at `forcePerKg` times the body's mass (the testbed's drag scenes use 30 Hz and 50,000);
    /// false if no dynamic body is there. Replaces a hand already held.
    bool grab(Vec2 point, float hertz, float forcePerKg);
    void moveHand(Vec2 target);
    void release();
    bool holding() const { return hand_.has_value(); }

    int jointCount() const { return static_cast<int>(scene_.joints.size()); }
    /// Joint i of the scene's list (scenes add joints as they go), or an invalid id.
    JointId joint(int i) const;
    /// The scene joint with an anchor nearest `point` within `radius` m; -1 if none.
    int jointNear(Vec2 point, float radius) const;
    /// Largest separation over the scene's joints solved by `solver`, m; -1 if it has none.
    float largestSeparation(PositionSolver solver) const;

    /// Whether a scene is loaded; the calls below that reach the world need one.
    bool loaded() const { return scene_.world != nullptr; }
    World& world() { return *scene_.world; }
    const World& world() const { return *scene_.world; }
    const WorldSettings& settings() const { return settings_; }
    int sceneIndex() const { return sceneIndex_; }
    int stepIndex() const { return stepIndex_; }
    double lastStepMs() const { return lastStepMs_; }
    const std::string& error() const { return error_; }
    void setError(std::string message) { error_ = std::move(message); }

private:
    scenes::Scene scene_;
    WorldSettings settings_;
    int sceneIndex_ = -1;
    int stepIndex_ = 0;
    double lastStepMs_ = 0.0;
    std::optional<MouseJointId> hand_;
    std::vector<float> drawList_;
    std::string error_;
};

}  // namespace pivot::web
