// The testbed's scenes rebuilt in Box2D 2.4.1 with identical parameters, for side-by-side
// comparison. Box2D lists bodies and joints newest first and pivot2d's island builder follows
// the same order, so both engines meet the joints in the same sequence.
#pragma once

#include <box2d/box2d.h>

#include <memory>
#include <vector>

namespace pivot::reference {

struct Box2dScene {
    std::unique_ptr<b2World> world;
    std::vector<b2Body*> bodies;  // in the order of the pivot scene's Scene::bodies
    std::vector<b2Joint*> joints;
};

/// The pendulum of testbed/scenes/pendulum.cpp, spun at `spin` rad/s about the pivot.
Box2dScene box2dPendulum(float spin);
/// The chain of testbed/scenes/chain.cpp.
Box2dScene box2dChain();

}  // namespace pivot::reference
