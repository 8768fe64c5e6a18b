// The scenes of the reference comparison rebuilt in Box2D 2.4.1 with identical parameters.
// Box2D lists bodies and joints newest first and pivot2d's island builder follows the same
// order, so both engines meet the joints in the same sequence.
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

namespace pivot::reference {

struct Box2dScene {
    std::unique_ptr<b2World> world;
    std::vector<b2Body*> bodies;  // in the order of the pivot scene's Scene::bodies
    std::vector<b2Joint*> joints;
    /// As pivot::scenes::Scene::beforeStep.
    std::function<void(Box2dScene&, int)> beforeStep;
};

Box2dScene box2dPendulum(float spin, bool continuous = false);
Box2dScene box2dLimitedPendulum(bool continuous = false);
Box2dScene box2dDoublePendulum(bool continuous = false);
Box2dScene box2dMotorWheel(bool continuous = false);
Box2dScene box2dBridge(bool continuous = false);
Box2dScene box2dBridgeHeavy(bool continuous = false);
Box2dScene box2dChain(bool continuous = false);
Box2dScene box2dMassRatio(bool continuous = false);

}  // namespace pivot::reference
