// The seed note's multi-link chain, laid out as in Box2D's testbed chain: 30 links, boxes of
// 1.2 x 0.25 m (density 20, friction 0.2) with joints 1 m apart (neighbours overlap by 0.2 m
// and, being jointed, do not collide), the first link pinned to the ground at (0, 25), the
// chain released horizontally.
#include "scene.h"

#include "ground.h"

namespace pivot::scenes {

void buildChain(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    constexpr int kLinks = 30;
    const float y = 25.0f;

    BodyId ground = createGround(world);

    ShapeDef link;
    link.density = 20.0f;
    link.friction = 0.2f;
    const Polygon box = Polygon::box(0.6f, 0.125f);

    BodyId previous = ground;
    for (int i = 0; i < kLinks; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.5f + static_cast<float>(i), y};
        BodyId body = world.createBody(def);
        world.createShape(body, link, box);
        Vec2 anchor{static_cast<float>(i), y};
        scene.joints.push_back(world.createJoint(options.jointAt(previous, body, anchor)));
        scene.bodies.push_back(body);
        previous = body;
    }
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

}  // namespace pivot::scenes
