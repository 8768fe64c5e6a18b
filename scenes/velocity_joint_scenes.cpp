// Scenes of the velocity-only joints.
#include <cmath>

#include "scene.h"

namespace pivot::scenes {

// Top-down friction: gravity off, twelve boxes slide and spin across a table seen from above,
// each held back by a friction joint to the table (as much force as friction 0.5 on a floor
// would give, and a torque to match) until it stops.
void buildTopDown(Scene& scene, const SceneOptions&) {
    World& world = *scene.world;
    world.setGravity({0.0f, 0.0f});
    BodyId table = world.createBody(BodyDef{});
    for (int i = 0; i < 12; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, 2.0f * static_cast<float>(i)};
        def.linearVelocity = {2.0f + 0.5f * static_cast<float>(i), 0.3f};
        def.angularVelocity = 3.0f - 0.5f * static_cast<float>(i);
        BodyId box = world.createBody(def);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
        const float weight = world.bodyMass(box) * 10.0f;
        FrictionJointDef jd;
        jd.bodyA = table;
        jd.bodyB = box;
        jd.maxForce = 0.5f * weight;
        jd.maxTorque = 0.5f * weight * 0.5f;  // the force at half the box's width
        scene.bodies.push_back(box);
        scene.joints.push_back(world.createJoint(jd));
    }
}

// A 4 x 1 m plank driven along a figure of eight by a motor joint to the ground: each step the
// joint's target moves (linear offset (6 sin 2t, 8 + 4 sin t), angular offset t), and the
// joint pulls the plank after it within 500 N and 1,000 N m.
void buildMotorDrive(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 8.0f};
    BodyId plank = world.createBody(def);
    world.createShape(plank, ShapeDef{}, Polygon::box(2.0f, 0.5f));
    MotorJointDef jd;
    jd.bodyA = ground;
    jd.bodyB = plank;
    jd.maxForce = 500.0f;
    jd.maxTorque = 1000.0f;
    const JointId joint = world.createJoint(jd);
    scene.bodies.push_back(plank);
    scene.joints.push_back(joint);
    const float dt = 1.0f / options.hz;
    scene.beforeStep = [joint, dt](Scene& s, int step) {
        const float t = dt * static_cast<float>(step);
        s.world->setMotorJointLinearOffset(joint,
                                           {6.0f * std::sin(2.0f * t), 8.0f + 4.0f * std::sin(t)});
        s.world->setMotorJointAngularOffset(joint, t);
    };
}

}  // namespace pivot::scenes
