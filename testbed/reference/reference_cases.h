// The reference comparison: each case is one scene built in pivot2d and in Box2D 2.4.1 with
// identical parameters, and how closely the two must agree (docs/reference-agreement.md).
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "scenes/box2d/box2d_scenes.h"
#include "scenes/metrics.h"
#include "scenes/scene.h"

namespace pivot::reference {

struct ReferenceCase {
    std::string name;
    /// Chaotic motion amplifies round-off, so trajectories are compared only over the first 30
    /// steps and the rest by statistics; otherwise trajectories must agree for the whole run.
    bool chaotic = false;
    std::function<void(scenes::Scene&, const scenes::SceneOptions&)> buildPivot;
    std::function<box2d::Box2dScene(bool continuous)> buildBox2d;
    /// False where the same joint is computed with other float operations (the wheel joint's
    /// spring takes other parameters, and Box2D keeps its rows' masses from the step's start;
    /// docs/reference-agreement.md): the tolerances hold, not bit-for-bit identity.
    bool bitForBit = true;
};

const std::vector<ReferenceCase>& referenceCases();

/// How far a pivot2d run strays from Box2D's, stepping both together.
struct TrajectoryDifference {
    int steps = 0;
    double position = 0.0;   ///< m, largest centre-of-mass distance over bodies and steps
    double angle = 0.0;      ///< rad, largest angle difference
    int identicalSteps = 0;  ///< leading steps after which every pose was bit-identical
    bool bodyCountsMatch = true;
    int impacts = 0;  ///< impacts pivot2d's continuous collision solved (StepStats::impactCount)
};

/// The steps over which a case's trajectories are compared: 600, or the first 30 if chaotic.
int comparedSteps(const ReferenceCase& c);

/// Steps the case's pivot2d scene (with `options`) and Box2D scene together at 60 Hz, 8 and 3
/// iterations, for `steps` steps. Box2D's continuous collision is on where the pivot2d scene
/// has it on; `continuous`, when given, switches it in both.
TrajectoryDifference compareTrajectories(const ReferenceCase& c,
                                         const scenes::SceneOptions& options, int steps,
                                         std::optional<bool> continuous = std::nullopt);

/// For test output.
void PrintTo(const ReferenceCase& c, std::ostream* out);

/// Builds the pivot2d side of a case into a fresh world.
scenes::Scene buildPivotCase(const ReferenceCase& c, const scenes::SceneOptions& options);

/// The Box2D side's metrics, measured exactly as scenes::runScene measures pivot2d's.
scenes::RunMetrics runBox2d(box2d::Box2dScene& scene, const scenes::RunSettings& settings,
                            const std::function<void(int)>& afterStep = {});

/// Kinetic plus gravitational potential energy of the Box2D scene's bodies, as
/// scenes::mechanicalEnergy.
double box2dEnergy(const box2d::Box2dScene& scene);

}  // namespace pivot::reference
