// The seed note's suspension bridge, laid out as in Box2D's testbed bridge: 30 planks of
// 1.0 x 0.25 m (density 20, friction 0.2) side by side at y = 5, each pinned to the next at
// their shared end, the first and last pinned to the ground.
#include "scene.h"

#include "ground.h"

namespace pivot::scenes {

namespace {
constexpr int kPlanks = 30;
constexpr float kDeckHeight = 5.0f;

void buildBridgeOf(Scene& scene, const SceneOptions& options, int planks, float y,
                   float density = 20.0f) {
    World& world = *scene.world;
    const float left = -0.5f * static_cast<float>(planks);

    BodyId ground = createGround(world);

    ShapeDef plank;
    plank.density = density;
    plank.friction = 0.2f;
    const Polygon box = Polygon::box(0.5f, 0.125f);

    BodyId previous = ground;
    for (int i = 0; i < planks; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {left + 0.5f + 1.0f * static_cast<float>(i), y};
        BodyId body = world.createBody(def);
        world.createShape(body, plank, box);
        Vec2 anchor{left + 1.0f * static_cast<float>(i), y};
        scene.joints.push_back(world.createJoint(options.jointAt(previous, body, anchor)));
        scene.bodies.push_back(body);
        previous = body;
    }
    Vec2 anchor{left + 1.0f * static_cast<float>(planks), y};
    scene.joints.push_back(world.createJoint(options.jointAt(previous, ground, anchor)));
    scene.restFromStep = stepAt(options, 5.0f);  // sagged and settled by then
}

}  // namespace

void buildBridge(Scene& scene, const SceneOptions& options) {
    buildBridgeOf(scene, options, kPlanks, kDeckHeight);
}

// Solver2D's long bridge: 160 planks, its deck at 40 m so that its sag stays off the ground. With
// Gauss-Seidel each iteration passes a correction one plank along, so the sag a long deck must
// hold takes far more iterations to settle than the 30 planks' does.
void buildLongBridge(Scene& scene, const SceneOptions& options) {
    buildBridgeOf(scene, options, 160, 40.0f);
}

// The seed note's "heavy cube dropped on the bridge": after 2 s a 1 m box of four times the
// bridge's mass (4 x 30 planks x 5 kg = 600 kg) is released 5 m above the deck's middle.
void buildBridgeHeavy(Scene& scene, const SceneOptions& options) {
    buildBridge(scene, options);
    const int dropStep = stepAt(options, 2.0f);
    scene.disturbanceEndStep = stepAt(options, 3.0f);  // the box has landed (it falls 5 m)
    scene.restFromStep = stepAt(options, 8.0f);
    scene.beforeStep = [dropStep](Scene& s, int step) {
        if (step != dropStep) return;
        float bridgeMass = 0.0f;
        for (BodyId plank : s.bodies) bridgeMass += s.world->bodyMass(plank);
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, kDeckHeight + 5.0f};
        BodyId box = s.world->createBody(def);
        ShapeDef shape;
        shape.density = 4.0f * bridgeMass;  // a 1 m x 1 m box: density equals mass
        shape.friction = 0.6f;
        s.world->createShape(box, shape, Polygon::box(0.5f, 0.5f));
        s.bodies.push_back(box);
    };
}

}  // namespace pivot::scenes

namespace pivot::scenes {

// One of the scenes WorldDef's defaults are chosen for (docs/position-correction.md,
// "Defaults"): a bridge of 20 planks of 0.4 kg (density 1.6) on pins that never break, and a 1 m
// crate of 36 kg, 90 times a plank, released at the start with its centre 2 m above the deck's
// middle. The crate is the scene's last body.
void buildBridgeCrate(Scene& scene, const SceneOptions& options) {
    buildBridgeOf(scene, options, 20, kDeckHeight, 1.6f);
    World& world = *scene.world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, kDeckHeight + 2.0f};
    const BodyId crate = world.createBody(def);
    ShapeDef shape;
    shape.density = 36.0f;
    shape.friction = 0.6f;
    world.createShape(crate, shape, Polygon::box(0.5f, 0.5f));
    scene.bodies.push_back(crate);
    scene.disturbanceEndStep = stepAt(options, 1.0f);  // landed
}

}  // namespace pivot::scenes
