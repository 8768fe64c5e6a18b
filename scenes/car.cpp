// A car: a 2.5 x 0.5 m chassis on two wheels of 0.4 m radius, each on a wheel joint with a
// vertical suspension (4 Hz, damping ratio 0.7, travel limited to +-0.25 m), the rear wheel
// driven by a motor (10 rad/s, at most 20 N m) that reverses when the chassis passes 12 m either
// side of the start, over ground with a 0.15 m bump every 3 m from -15 to 15 m. The suspension rows
// take the bumps; the line rows hold the wheels under the chassis as it pitches.
#include "ground.h"
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

void buildCar(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    const BodyId ground = createGround(world);
    ShapeDef bump;
    bump.density = 0.0f;
    bump.friction = 0.6f;
    for (int i = -5; i <= 5; ++i) {
        world.createShape(ground, bump,
                          Polygon::box(0.5f, 0.15f, {3.0f * static_cast<float>(i), 0.0f}, 0.0f));
    }
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 1.3f};
    const BodyId chassis = world.createBody(def);
    world.createShape(chassis, ShapeDef{}, Polygon::box(1.25f, 0.25f));
    scene.bodies.push_back(chassis);
    ShapeDef tyre;
    tyre.friction = 0.9f;
    for (float x : {-0.9f, 0.9f}) {
        def.position = {x, 0.55f};
        const BodyId wheel = world.createBody(def);
        world.createShape(wheel, tyre, Circle{{0.0f, 0.0f}, 0.4f});
        WheelJointDef jd = WheelJointDef::atWorldAnchor(chassis, wheel, {x, 0.55f}, {0.0f, 1.0f});
        jd.spring = {true, 4.0f, 0.7f};
        jd.limit = {true, -0.25f, 0.25f};
        jd.motor = {x < 0.0f, -10.0f, 20.0f};
        jd.positionSolver = options.solver;
        jd.biasFactor = options.biasFactor;
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(wheel);
    }
    const JointId drive = scene.joints.front();
    scene.beforeStep = [drive, chassis](Scene& s, int) {
        JointMotor motor = s.world->jointMotor(drive);
        const float x = s.world->bodyPosition(chassis).x;
        // A negative wheel speed (clockwise) drives the car to the right.
        if ((x > 12.0f && motor.speed < 0.0f) || (x < -12.0f && motor.speed > 0.0f)) {
            motor.speed = -motor.speed;
            s.world->setJointMotor(drive, motor);
        }
    };
}

}  // namespace pivot::scenes
