// The seed note's suspension bridge, laid out as in Box2D's testbed bridge: 30 planks of
// 1.0 x 0.25 m (density 20, friction 0.2) side by side at y = 5, each pinned to the next at
// their shared end, the first and last pinned to the ground.
#include "scene.h"

#include "ground.h"

namespace pivot::scenes {

void buildBridge(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    constexpr int kPlanks = 30;
    const float y = 5.0f;

    BodyId ground = createGround(world);

    ShapeDef plank;
    plank.density = 20.0f;
    plank.friction = 0.2f;
    const Polygon box = Polygon::box(0.5f, 0.125f);

    BodyId previous = ground;
    for (int i = 0; i < kPlanks; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-14.5f + 1.0f * static_cast<float>(i), y};
        BodyId body = world.createBody(def);
        world.createShape(body, plank, box);
        Vec2 anchor{-15.0f + 1.0f * static_cast<float>(i), y};
        scene.joints.push_back(world.createJoint(options.jointAt(previous, body, anchor)));
        scene.bodies.push_back(body);
        previous = body;
    }
    Vec2 anchor{-15.0f + 1.0f * static_cast<float>(kPlanks), y};
    scene.joints.push_back(world.createJoint(options.jointAt(previous, ground, anchor)));
}

}  // namespace pivot::scenes
