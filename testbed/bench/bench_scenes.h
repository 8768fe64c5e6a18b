// The benchmark scenes, each built in pivot2d and in Box2D 2.4.1 with identical parameters,
// sleeping off. The first three follow Box2D v3's public benchmark suite (joint_grid,
// large_pyramid, many_pyramids), so figures can be set beside published ones.
#pragma once

#include <box2d/box2d.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::bench {

/// Takes step i (running the scene's script for it first, if it has one). Owns its world.
using Stepper = std::function<void(int)>;

/// How pivot2d steps a bench scene: its joints' solver, the world's contact correction and
/// substeps, and the iterations of each (sub)step.
struct PivotSetup {
    const char* name;  ///< as the bench prints it
    PositionSolver solver;
    ContactCorrection contacts;
    int substeps;
    int velocityIterations;
    int positionIterations;
};

/// full_ngs (the default: 8/3, NGS contacts), baumgarte (8/3, Baumgarte joints, NGS contacts)
/// and soft_step (Box2D v3's world: soft-step joints, soft contacts, 4 substeps of 1 velocity
/// and 1 relax iteration).
const std::vector<PivotSetup>& pivotSetups();

struct BenchScene {
    std::string name;
    std::string description;
    int steps = 0;  ///< steps per timed run
    /// pivot2d set up as given, with WorldDef::workerCount `workers`.
    std::function<Stepper(const PivotSetup&, int workers)> buildPivot;
    std::function<Stepper()> buildBox2d;
};

/// Continuous collision in both engines, for the scenes built from now on: on (the default, as
/// each engine's default and the testbed scenes have it) or off.
void setContinuousCollision(bool on);
bool continuousCollision();

/// The scenes of the comparison, then the scaling series (chains and pyramids of growing size).
std::vector<BenchScene> benchScenes();

}  // namespace pivot::bench
