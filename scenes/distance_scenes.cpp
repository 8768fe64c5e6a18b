// A rope of distance joints. (The seed note's pendulum on a rod is in pendulum.cpp.)
#include "scene.h"

namespace pivot::scenes {

// A rope of 30 beads (balls of 0.15 m radius, 1 m apart), each tied to the next by a rope of
// 0.5 to 1 m (a distance joint whose limit is its only constraint), the first tied to a static
// point; released level with every rope taut. Tied at their centres, the beads are the point
// masses of a game's rope, and each rope's effective mass is the same in every pose. (Tied at
// the ends of planks instead, the ropes' lever arms let pseudo velocities stretch the rope
// without end: see docs/position-correction.md.)
void buildRope(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 start{0.0f, 20.0f};
    BodyId previous = world.createBody(BodyDef{});
    Vec2 previousAnchor = start;  // in the previous body's frame
    for (int i = 1; i <= 30; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = start + Vec2{static_cast<float>(i), 0.0f};
        BodyId bead = world.createBody(def);
        world.createShape(bead, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.15f});
        DistanceJointDef jd = options.distanceJoint(previous, bead);
        jd.localAnchorA = previousAnchor;
        jd.limit = {true, 0.5f, 1.0f};
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(bead);
        previous = bead;
        previousAnchor = Vec2{};
    }
}

// The bead rope's planks: 30 planks of 0.4 x 0.1 m, each tied by its ends to the next by a rope
// of 0.3 to 0.6 m (a distance joint's limits), the first to a static point; released level with
// every rope taut. Each rope's lever arms on its planks (rA x u, rB x u) change as the planks
// swing and spin, so its scalar effective mass changes with the pose: the case the bead rope,
// tied at the centres, cannot show.
void buildPlankRope(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    constexpr float kHalfPlank = 0.2f;
    constexpr float kRope = 0.6f;
    const Vec2 start{0.0f, 20.0f};
    BodyId previous = world.createBody(BodyDef{});
    Vec2 previousAnchor = start;  // in the previous body's frame
    float x = start.x;
    for (int i = 0; i < 30; ++i) {
        x += kRope + kHalfPlank;
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {x, start.y};
        BodyId plank = world.createBody(def);
        world.createShape(plank, ShapeDef{}, Polygon::box(kHalfPlank, 0.05f));
        DistanceJointDef jd = options.distanceJoint(previous, plank);
        jd.localAnchorA = previousAnchor;
        jd.localAnchorB = {-kHalfPlank, 0.0f};
        jd.limit = {true, 0.3f, kRope};
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(plank);
        previous = plank;
        previousAnchor = {kHalfPlank, 0.0f};
        x += kHalfPlank;
    }
}

}  // namespace pivot::scenes
