// A chain holding a ball about 3,000 times heavier than a link: 20 links (boxes 1 x 0.2 m,
// density 1, 0.2 kg) with joints 1 m apart, the first pinned to a static body at (0, 25), the
// last holding a ball of radius 2 m and density 50 (628 kg) by a point on its rim, released
// horizontally. No position solver of the seed note holds such a mass ratio: the chain stretches
// tens of metres in pivot2d and in Box2D 2.4.1 alike. It is the case that showed that a joint
// must not be let go for being stretched unless the user asked for it (docs/reliability.md).
#include "scene.h"

namespace pivot::scenes {

void buildMassRatio(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    constexpr int kLinks = 20;
    const float y = 25.0f;

    BodyId previous = world.createBody(BodyDef{});
    ShapeDef link;
    link.density = 1.0f;
    const Polygon box = Polygon::box(0.5f, 0.1f);
    for (int i = 0; i <= kLinks; ++i) {
        const bool ball = i == kLinks;
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {ball ? static_cast<float>(kLinks) + 2.0f : 0.5f + static_cast<float>(i), y};
        BodyId body = world.createBody(def);
        if (ball) {
            ShapeDef heavy;
            heavy.density = 50.0f;
            world.createShape(body, heavy, Circle{{0.0f, 0.0f}, 2.0f});
        } else {
            world.createShape(body, link, box);
        }
        Vec2 anchor{static_cast<float>(i), y};
        scene.joints.push_back(world.createJoint(options.jointAt(previous, body, anchor)));
        scene.bodies.push_back(body);
        previous = body;
    }
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

}  // namespace pivot::scenes
