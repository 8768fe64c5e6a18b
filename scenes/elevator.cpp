// An elevator: a 3 x 0.2 m platform on a vertical prismatic joint to the ground, its travel
// limited to [0, 4] m, carries a 1 m box of five times its density resting 1 m off its centre.
// The motor (at most 500 N) drives it up at 1 m/s for 5 s, so that it rides the last second
// against the upper limit, then down for 5 s to the lower one, and so on: the load twists the
// slide (the block's angle row), and the motor presses the platform into each limit (the block
// with the limit's row).
#include "scene.h"

namespace pivot::scenes {

namespace {
constexpr int kStepsPerTrip = 300;
}

void buildElevator(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    BodyId ground = world.createBody(BodyDef{});
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 1.0f};
    BodyId platform = world.createBody(def);
    world.createShape(platform, ShapeDef{}, Polygon::box(1.5f, 0.1f));
    def.position = {1.0f, 1.6f};
    BodyId load = world.createBody(def);
    ShapeDef heavy;
    heavy.density = 5.0f;
    world.createShape(load, heavy, Polygon::box(0.5f, 0.5f));

    PrismaticJointDef jd =
        PrismaticJointDef::atWorldAnchor(ground, platform, {0.0f, 1.0f}, {0.0f, 1.0f});
    jd.limit = {true, 0.0f, 4.0f};
    jd.motor = {true, 1.0f, 500.0f};
    jd.positionSolver = options.solver;
    jd.biasFactor = options.biasFactor;
    const JointId shaft = world.createJoint(jd);
    scene.bodies.push_back(platform);
    scene.bodies.push_back(load);
    scene.joints.push_back(shaft);
    scene.beforeStep = [shaft](Scene& s, int step) {
        if (step == 0 || step % kStepsPerTrip != 0) return;
        LinearMotor motor = s.world->prismaticJointMotor(shaft);
        motor.speed = -motor.speed;
        s.world->setPrismaticJointMotor(shaft, motor);
    };
}

}  // namespace pivot::scenes
