// A cantilever: ten 1 x 0.25 m boxes welded end to end out of a wall at y = 5, and a 1 m box of
// twenty times a segment's mass welded to the tip. The welds hold the beam straight against the
// load's torque, which grows towards the wall: each weld's 3x3 block (point and angle) carries
// it. Released at rest, the beam sags until the joints' errors balance the load, and bounces.
// The beam is one object: its parts never collide with each other (a shared negative collision
// group), so a strategy that lets it fold (Baumgarte whips it) folds it through itself.
#include "scene.h"

namespace pivot::scenes {

void buildWeldBeam(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyId previous = world.createBody(BodyDef{});  // the wall
    constexpr int kSegments = 10;
    BodyDef def;
    def.type = BodyType::Dynamic;
    for (int i = 0; i <= kSegments; ++i) {
        const bool load = i == kSegments;
        def.position = {0.5f + static_cast<float>(i), 5.0f};
        BodyId body = world.createBody(def);
        ShapeDef shape;
        shape.density = load ? 5.0f : 1.0f;
        shape.filter.groupIndex = -1;
        world.createShape(body, shape,
                          load ? Polygon::box(0.5f, 0.5f) : Polygon::box(0.5f, 0.125f));
        WeldJointDef jd =
            WeldJointDef::atWorldAnchor(previous, body, {static_cast<float>(i), 5.0f});
        jd.positionSolver = options.solver;
        jd.biasFactor = options.biasFactor;
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(body);
        previous = body;
    }
}

}  // namespace pivot::scenes
