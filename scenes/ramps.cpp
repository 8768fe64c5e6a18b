// Segments as level geometry: a ramp, a floor with a bump on it (one chain shape, one-sided,
// solid from above) and a wall (a two-sided segment), on one static body. Balls, boxes (one
// rounded) and a capsule slide and roll down the ramp, over the joins and the bump and into a
// chain of five links hanging from a pin above the floor, which they push aside; the chain's
// joints take the knocks.
#include "scene.h"

namespace pivot::scenes {

void buildRamps(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef level;
    level.density = 0.0f;
    level.friction = 0.1f;
    // Right to left, so that each segment's solid side (its right) faces up; the first and last
    // points are ghosts: the floor runs on into the wall, the ramp on upwards.
    world.createChain(ground, level,
                      Chain{{{16.0f, 0.0f},
                             {15.0f, 0.0f},
                             {4.0f, 0.0f},
                             {3.0f, 0.3f},
                             {1.0f, 0.0f},
                             {-3.0f, 0.0f},
                             {-14.0f, 12.0f},
                             {-15.0f, 13.1f}},
                            false});
    world.createShape(ground, level, Segment{{15.0f, 0.0f}, {15.0f, 8.0f}});

    // Three balls and three other bodies on the ramp, 1.5 m apart, alternating, a box first
    // (lowest), then a box with rounded corners, then a capsule.
    for (int i = 0; i < 6; ++i) {
        const float x = -5.0f - 1.5f * static_cast<float>(i);
        const float rampY = 12.0f * (x + 3.0f) / -11.0f;
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {x, rampY + 0.8f};
        const BodyId body = world.createBody(def);
        ShapeDef shape;
        shape.friction = 0.1f;
        if (i % 2 == 1) {
            world.createShape(body, shape, Circle{{0.0f, 0.0f}, 0.4f});
        } else if (i == 2) {
            world.createShape(body, shape, Polygon::roundedBox(0.4f, 0.4f, 0.15f));
        } else if (i == 4) {
            world.createShape(body, shape, Capsule{{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.3f});
        } else {
            world.createShape(body, shape, Polygon::box(0.4f, 0.4f));
        }
        scene.bodies.push_back(body);
    }

    // Five links of 0.8 m hanging from a pin at (9, 4.3), their last one 0.3 m above the floor.
    BodyId previous = ground;
    for (int i = 0; i < 5; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {9.0f, 3.9f - 0.8f * static_cast<float>(i)};
        const BodyId link = world.createBody(def);
        ShapeDef shape;
        shape.density = 2.0f;
        world.createShape(link, shape, Polygon::box(0.1f, 0.4f));
        scene.bodies.push_back(link);
        scene.joints.push_back(world.createJoint(
            options.jointAt(previous, link, {9.0f, 4.3f - 0.8f * static_cast<float>(i)})));
        previous = link;
    }
}

}  // namespace pivot::scenes
