// Scenes of distance joints: the seed note's pendulum on a rod instead of a pin, and a rope.
#include "scene.h"

namespace pivot::scenes {

// The seed note's pendulum (pendulum.cpp) with the stick made a distance joint: a 1 m ball whose
// centre is held 5 m from the pivot, spun at 100 rad/s. Where the revolute joint's pin is a 2x2
// block, the rod is one scalar row along the stick, the shape of constraint for which the note
// wonders whether Modified NGS is viable.
void buildDistancePendulum(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 pivot{0.0f, 10.0f};
    const float stickLength = 5.0f;
    const float spin = 100.0f;

    BodyId ground = world.createBody(BodyDef{});
    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = pivot + Vec2{0.0f, -stickLength};
    ballDef.angularVelocity = spin;
    ballDef.linearVelocity = cross(spin, ballDef.position - pivot);
    BodyId ball = world.createBody(ballDef);
    ShapeDef shape;
    shape.density = 1.0f;
    world.createShape(ball, shape, Circle{{0.0f, 0.0f}, 0.5f});

    DistanceJointDef jd = options.distanceJoint(ground, ball);
    jd.localAnchorA = pivot;
    scene.bodies.push_back(ball);
    scene.joints.push_back(world.createJoint(jd));
}

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
