// The testbed scenes of the reference comparison rebuilt in Box2D 2.4.1 with identical
// parameters, each named as the scenes::build function it twins. Box2D lists bodies and
// joints newest first and pivot2d's island builder follows the same order, so both engines
// meet the joints in the same sequence.
//
// Continuous collision is switched off unless asked for: pivot2d has no time-of-impact solver,
// and the comparison is of the revolute joint, so both worlds run the same features. (With it
// on, Box2D rewinds a fast body that hits static ground to the moment of impact without
// solving its joints, which shows as a joint separation spike; docs/reference-agreement.md.)
#pragma once

#include <box2d/box2d.h>

#include <functional>
#include <memory>
#include <vector>

namespace pivot::box2d {

struct Box2dScene {
    std::unique_ptr<b2World> world;
    std::vector<b2Body*> bodies;  // in the order of the pivot scene's Scene::bodies
    std::vector<b2Joint*> joints;
    /// As pivot::scenes::Scene::beforeStep.
    std::function<void(Box2dScene&, int)> beforeStep;
};

Box2dScene buildSpinningPendulum(float spin, bool continuous = false);
Box2dScene buildLimitedPendulum(bool continuous = false);
Box2dScene buildDoublePendulum(bool continuous = false);
Box2dScene buildMotorWheel(bool continuous = false);
Box2dScene buildBridge(bool continuous = false);
Box2dScene buildBridgeHeavy(bool continuous = false);
Box2dScene buildChain(bool continuous = false);
Box2dScene buildMassRatio(bool continuous = false);
/// The pendulum of buildSpinningPendulum(100) with a distance joint (a rod, min = max = 5 m).
Box2dScene buildDistancePendulum(bool continuous = false);
Box2dScene buildPulley(bool continuous = false);
Box2dScene buildTopDown(bool continuous = false);
Box2dScene buildMotorDrive(bool continuous = false);
Box2dScene buildElevator(bool continuous = false);
Box2dScene buildWeldBeam(bool continuous = false);
Box2dScene buildGearTrain(bool continuous = false);
/// Box2D 2.4.1's wheel spring takes a stiffness and damping (N/m, N s/m): the twin computes
/// them from pivot2d's 4 Hz and 0.7 on the effective mass of the suspension row at the start,
/// the same spring while the chassis is level.
Box2dScene buildCar(bool continuous = false);
/// The `bullets` scene: scenes::Volley's pyramid, range and shots, flagged as bullets.
Box2dScene buildBullets(bool continuous = true);

}  // namespace pivot::box2d
