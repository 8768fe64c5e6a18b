// The seed note's multi-link chain, laid out as in Box2D's testbed chain (scenes::layChain;
// neighbouring links overlap and, being jointed, do not collide), the first link pinned to the
// ground at (0, 25), the chain released horizontally; and the same chain 30 km from the origin.
#include "scene.h"

#include "ground.h"
#include "parts.h"

namespace pivot::scenes {

void buildChain(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    BodyId ground = createGround(world);
    Chain chain = addChain(world, ground, 0.0f, 25.0f, [&](BodyId a, BodyId b, Vec2 anchor) {
        return options.jointAt(a, b, anchor);
    });
    scene.bodies.insert(scene.bodies.end(), chain.links.begin(), chain.links.end());
    scene.joints.insert(scene.joints.end(), chain.joints.begin(), chain.joints.end());
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

void buildFarChain(Scene& scene, const SceneOptions& options) {
    // 30 km out, neighbouring floats are 2 mm apart (4 mm beyond 32 km): the same chain with
    // its poses rounded 250 times coarser than at the origin, still finer than the 5 mm slop.
    constexpr float kFar = 30000.0f;
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    BodyDef groundDef;
    groundDef.position = {kFar, 0.0f};
    BodyId ground = world.createBody(groundDef);
    ShapeDef slab;
    slab.density = 0.0f;
    world.createShape(ground, slab, Polygon::box(40.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    Chain chain = addChain(world, ground, kFar, 25.0f, [&](BodyId a, BodyId b, Vec2 anchor) {
        return options.jointAt(a, b, anchor);
    });
    scene.bodies.insert(scene.bodies.end(), chain.links.begin(), chain.links.end());
    scene.joints.insert(scene.joints.end(), chain.joints.begin(), chain.joints.end());
    scene.origin = {kFar, 0.0f};
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

}  // namespace pivot::scenes
