// Stacks that stress the contacts' position correction (after Solver2D's suite). They have no
// joint: the joint strategies change nothing here, the contact correction (--contact) does.
#include "scene.h"

#include "ground.h"
#include "parts.h"

namespace pivot::scenes {

void buildHeavyStack(Scene& scene, const SceneOptions&) {
    // Six 1 m boxes of 1 kg stacked on the ground under a 1 m box of 100 kg, dropped from a
    // hand's breadth: the light boxes are squeezed between the heavy one and the ground.
    World& world = *scene.world;
    createGround(world, 0.6f);
    constexpr int kLight = 6;
    for (int i = 0; i <= kLight; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, 0.5f + kRestGap + (1.0f + kRestGap) * static_cast<float>(i) +
                                  (i == kLight ? 0.1f : 0.0f)};
        BodyId box = world.createBody(def);
        ShapeDef shape;
        shape.density = i == kLight ? 100.0f : 1.0f;
        world.createShape(box, shape, Polygon::box(0.5f, 0.5f));
        scene.bodies.push_back(box);
    }
    scene.restFromStep = 180;
}

void buildLightOnHeavy(Scene& scene, const SceneOptions&) {
    // The other half of Solver2D's mass-ratio stacks: six 1 m boxes of 1 kg stacked on a 1 m box
    // of 100 kg resting on the ground, dropped from a hand's breadth. The heavy box is the
    // floor's; nothing is squeezed, but every light box rests on a body a hundred times heavier.
    World& world = *scene.world;
    createGround(world, 0.6f);
    constexpr int kLight = 6;
    for (int i = 0; i <= kLight; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, 0.5f + kRestGap + (1.0f + kRestGap) * static_cast<float>(i) +
                                  (i == 0 ? 0.0f : 0.1f)};
        BodyId box = world.createBody(def);
        ShapeDef shape;
        shape.density = i == 0 ? 100.0f : 1.0f;
        world.createShape(box, shape, Polygon::box(0.5f, 0.5f));
        scene.bodies.push_back(box);
    }
    scene.restFromStep = 180;
}

void buildOverlapRecovery(Scene& scene, const SceneOptions&) {
    // A pyramid of four rows of 1 m boxes created a quarter of a box deep into each other and
    // into the ground: the contacts must push them apart without launching them.
    World& world = *scene.world;
    createGround(world, 0.6f);
    PyramidSpec spec;
    spec.rows = 4;
    spec.pitchX = 0.75f;
    spec.pitchY = 0.75f;
    spec.floorGap = -0.25f;
    const std::vector<BodyId> boxes = addPyramid(world, spec);
    scene.bodies.insert(scene.bodies.end(), boxes.begin(), boxes.end());
    scene.restFromStep = 240;
}

}  // namespace pivot::scenes
