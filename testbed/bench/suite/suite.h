// The benchmark scenes, each written once against bench::Builder and so built alike in every
// engine. The first seven are Box2D v3's benchmark suite (its benchmark app, v3.1): the same
// bodies, shapes, joints, creation order and step counts; then many_chains and the scaling
// series (chains and pyramids of growing size). Where a scene departs from v3's, its
// description and docs/performance.md say how.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bench/suite/builder.h"

namespace pivot::bench {

/// Runs before step `step` (0, 1, ...): a scene's script (rain's ragdolls, for one).
using Script = std::function<void(Builder&, int step)>;

struct SuiteScene {
    std::string name;
    std::string description;
    int steps = 0;       ///< per run, as v3's benchmark app takes them
    bool sleep = false;  ///< whether bodies may sleep (v3's app: on, but for the first three)
    /// Builds the scene into an empty world (gravity -10 m/s^2 unless it says otherwise) and
    /// returns its script, or an empty function.
    std::function<Script(Builder&)> build;
};

/// Every scene, in the order the bench runs them.
std::vector<SuiteScene> suiteScenes();

// The two halves of the list (box2d_v3_suite.cpp, scaling_scenes.cpp).
void addBox2dV3Suite(std::vector<SuiteScene>& scenes);
void addScalingScenes(std::vector<SuiteScene>& scenes);

}  // namespace pivot::bench
