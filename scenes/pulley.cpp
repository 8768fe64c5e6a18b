// A pulley: two boxes hung by their tops from wheels 4 m apart, the rope over them geared 1.5 to
// 1 (a block and tackle). The heavier box (2x the density) starts level with the lighter, which
// hangs half a metre to the side of its wheel so that it swings as it rises: the rope's
// effective mass then changes with the pose, through the lever arm of the box's top.
#include "scene.h"

namespace pivot::scenes {

void buildPulley(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    const Vec2 wheelA{-2.0f, 10.0f};
    const Vec2 wheelB{2.0f, 10.0f};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {-2.0f, 5.0f};
    BodyId heavy = world.createBody(def);
    ShapeDef shape;
    shape.density = 2.0f;
    world.createShape(heavy, shape, Polygon::box(0.5f, 0.5f));
    def.position = {2.5f, 5.0f};
    BodyId light = world.createBody(def);
    shape.density = 1.0f;
    world.createShape(light, shape, Polygon::box(0.5f, 0.5f));

    PulleyJointDef jd;
    jd.bodyA = heavy;
    jd.bodyB = light;
    jd.groundAnchorA = wheelA;
    jd.groundAnchorB = wheelB;
    jd.localAnchorA = {0.0f, 0.5f};
    jd.localAnchorB = {0.0f, 0.5f};
    jd.ratio = 1.5f;
    jd.positionSolver = options.solver;
    jd.biasFactor = options.biasFactor;
    scene.bodies.push_back(heavy);
    scene.bodies.push_back(light);
    scene.joints.push_back(world.createJoint(jd));
}

}  // namespace pivot::scenes
