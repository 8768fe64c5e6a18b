// The seed note's multi-link chain, laid out as in Box2D's testbed chain (scenes::layChain;
// neighbouring links overlap and, being jointed, do not collide), the first link pinned to the
// ground at (0, 25), the chain released horizontally.
#include "scene.h"

#include "ground.h"
#include "parts.h"

namespace pivot::scenes {

void buildChain(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyId ground = createGround(world);
    Chain chain = addChain(world, ground, 0.0f, 25.0f, [&](BodyId a, BodyId b, Vec2 anchor) {
        return options.jointAt(a, b, anchor);
    });
    scene.bodies.insert(scene.bodies.end(), chain.links.begin(), chain.links.end());
    scene.joints.insert(scene.joints.end(), chain.joints.begin(), chain.joints.end());
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

}  // namespace pivot::scenes
