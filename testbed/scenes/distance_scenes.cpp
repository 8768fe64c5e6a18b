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

}  // namespace pivot::scenes
