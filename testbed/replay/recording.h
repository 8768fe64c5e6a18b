// Recording scene runs for the browser replay: every body's pose and every joint's anchors,
// frame by frame, one run per position solver. Uses only pivot2d's public API.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/scene.h"

namespace pivot::replay {

/// A shape's outline in its body's frame.
struct Outline {
    ShapeType type = ShapeType::Circle;
    Vec2 center;                 ///< circle
    float radius = 0;            ///< circle
    std::vector<Vec2> vertices;  ///< polygon, counter-clockwise
};

/// One body through a run.
struct Track {
    std::vector<Outline> outlines;
    bool isStatic = false;
    int firstFrame = 0;        ///< the frame at which the body appears (scenes may add bodies)
    std::vector<float> poses;  ///< x, y, angle of the body origin for each frame from firstFrame
};

struct Run {
    std::string label;  ///< the position solver's name
    std::vector<Track> tracks;
    /// Per frame: for each joint, anchor A then anchor B (x, y, x, y), in world coordinates.
    std::vector<std::vector<float>> jointAnchors;
    std::vector<float> maxSeparation;  ///< per frame, largest joint separation, m
    /// Per frame, each joint's separation, m.
    std::vector<std::vector<float>> jointSeparations;
    /// Whether some joint's anchors are meant to be apart (a distance joint), so that its
    /// separation is not the gap between them.
    bool hasLinks = false;
};

struct Recording {
    std::string scene;
    std::string description;
    float frameInterval = 0.0f;  ///< s between frames
    int frameCount = 0;
    std::vector<Run> runs;  ///< one per position solver, in enum order
};

/// Runs the scene once per position solver (60 Hz, 8/3 iterations, NGS contacts) for `steps`
/// steps, recording the state before the first step and after every `stepsPerFrame`-th step.
Recording recordScene(const scenes::SceneInfo& scene, int steps, int stepsPerFrame);

}  // namespace pivot::replay
