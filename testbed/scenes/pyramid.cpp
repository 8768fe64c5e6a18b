// A pyramid of 1 m boxes (density 1, friction 0.6), 20 rows high, on the ground: 210 boxes
// that must stand still. The boxes start at their resting spacing: polygons collide with a
// kPolygonRadius skin and contacts settle about kLinearSlop deep into it, so two boxes rest
// with their cores 2 * kPolygonRadius - kLinearSlop apart. Neighbours in a row start 5 cm apart.
#include "ground.h"
#include "scene.h"

namespace pivot::scenes {

void buildPyramid(Scene& scene, const SceneOptions& options) {
    scene.restFromStep = stepAt(options, 1.0f);
    World& world = *scene.world;
    constexpr int kRows = 20;
    const float restGap = 2.0f * kPolygonRadius - kLinearSlop;
    const float pitchY = 1.0f + restGap;
    const float pitchX = 1.05f;

    createGround(world);
    ShapeDef shape;
    shape.density = 1.0f;
    shape.friction = 0.6f;
    const Polygon box = Polygon::box(0.5f, 0.5f);
    for (int row = 0; row < kRows; ++row) {
        int count = kRows - row;
        float left = -0.5f * pitchX * static_cast<float>(count - 1);
        for (int i = 0; i < count; ++i) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {left + pitchX * static_cast<float>(i),
                            0.5f + restGap + pitchY * static_cast<float>(row)};
            BodyId body = world.createBody(def);
            world.createShape(body, shape, box);
            scene.bodies.push_back(body);
        }
    }
}

}  // namespace pivot::scenes
