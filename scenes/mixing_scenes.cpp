// Scenes for the mixing study (the seed note's recommendation to choose the position solver per
// joint): each has joints that matter, its keyJoints, and joints that matter less, which take
// SceneOptions::secondarySolver when it is set. Without it every joint has the scene's solver, and
// they are ordinary testbed scenes.
#include "ground.h"
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

// Six ragdolls dropped one above the other into a 5 m pit, tumbling: the pile of Solver2D's
// suite. Key: necks, shoulders and hips; secondary: elbows and knees.
void buildRagdollPile(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    const BodyId ground = createGround(world, 0.6f);
    ShapeDef wall;
    wall.density = 0.0f;
    wall.friction = 0.6f;
    world.createShape(ground, wall, Polygon::box(0.25f, 4.0f, {-2.75f, 4.0f}, 0.0f));
    world.createShape(ground, wall, Polygon::box(0.25f, 4.0f, {2.75f, 4.0f}, 0.0f));
    for (int i = 0; i < 6; ++i) {
        const float side = i % 2 == 0 ? -1.0f : 1.0f;
        addRagdoll(scene, options, {0.6f * side, 0.5f + 2.2f * static_cast<float>(i)},
                   {-1.0f * side, 0.0f}, 1.5f * side, false, -1 - i);
    }
    scene.disturbanceEndStep = stepAt(options, 3.0f);  // the pile has landed
    scene.restFromStep = stepAt(options, 7.0f);
}

// The bridge (bridge.cpp's 30 planks at 5 m) with a decorative chain of six 0.6 m links hanging
// from every fifth plank, set swinging. Key: the deck's joints; secondary: the chains'.
void buildBridgeChains(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    const BodyId ground = createGround(world);
    constexpr float kDeck = 5.0f;
    ShapeDef plankShape;
    plankShape.density = 20.0f;
    plankShape.friction = 0.2f;
    std::vector<BodyId> planks;
    BodyId previous = ground;
    for (int i = 0; i < 30; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-14.5f + static_cast<float>(i), kDeck};
        const BodyId plank = world.createBody(def);
        world.createShape(plank, plankShape, Polygon::box(0.5f, 0.125f));
        const JointId joint = world.createJoint(
            options.jointAt(previous, plank, {-15.0f + static_cast<float>(i), kDeck}));
        scene.joints.push_back(joint);
        scene.keyJoints.push_back(joint);
        scene.bodies.push_back(plank);
        planks.push_back(plank);
        previous = plank;
    }
    const JointId last = world.createJoint(options.jointAt(previous, ground, {15.0f, kDeck}));
    scene.joints.push_back(last);
    scene.keyJoints.push_back(last);

    ShapeDef linkShape;
    linkShape.density = 20.0f;
    for (std::size_t p = 4; p < planks.size(); p += 5) {
        const float x = world.bodyPosition(planks[p]).x;
        BodyId above = planks[p];
        for (int k = 0; k < 6; ++k) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {x, kDeck - 0.3f - 0.6f * static_cast<float>(k)};
            def.linearVelocity = {2.0f, 0.0f};  // swinging
            const BodyId link = world.createBody(def);
            world.createShape(link, linkShape, Polygon::box(0.1f, 0.3f));
            scene.joints.push_back(world.createJoint(
                options.secondaryJointAt(above, link, {x, kDeck - 0.6f * static_cast<float>(k)})));
            scene.bodies.push_back(link);
            above = link;
        }
    }
    scene.restFromStep = stepAt(options, 5.0f);
}

// A rope of 30 planks (1 m x 0.25 m, 5 kg) pinned end to end from a pivot at 35 m, a 120 kg ball
// (24 times a link) pinned to its end, released level: a game's rope with a heavy load. Key: every
// joint (the rope must hold); secondary: the 22 nearest the pivot, so that a mixed rope keeps
// its key solver for the 8 joints nearest the load.
void buildRopeLoad(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    const BodyId ground = createGround(world);
    constexpr int kLinks = 30;
    constexpr int kSecondary = 22;
    const Vec2 pivot{-15.0f, 35.0f};
    ShapeDef linkShape;
    linkShape.density = 20.0f;  // 5 kg
    BodyId previous = ground;
    for (int i = 0; i <= kLinks; ++i) {
        const Vec2 anchor = pivot + Vec2{static_cast<float>(i), 0.0f};
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = anchor + Vec2{0.5f, 0.0f};
        const BodyId body = world.createBody(def);
        if (i < kLinks) {
            world.createShape(body, linkShape, Polygon::box(0.5f, 0.125f));
        } else {
            ShapeDef load;
            load.density = 120.0f / (kPi * 0.25f);  // 120 kg in a 0.5 m circle
            world.createShape(body, load, Circle{{0.0f, 0.0f}, 0.5f});
        }
        const JointId joint =
            world.createJoint(i < kSecondary ? options.secondaryJointAt(previous, body, anchor)
                                             : options.jointAt(previous, body, anchor));
        scene.joints.push_back(joint);
        scene.keyJoints.push_back(joint);
        scene.bodies.push_back(body);
        previous = body;
    }
    scene.disturbanceEndStep = 0;  // the release
}

// A 36 kg car whose wheels turn on pins under light hubs, each hub on a sprung prismatic
// suspension (4 Hz, damping ratio 0.7, travel -0.3 to +0.15 m), both wheels driven (25 rad/s, at
// most 150 N m) back and forth between x = -14 and 14 m over a 0.2 m bump every 3 m. Key: the
// two axles, which carry the car; secondary: the suspensions, which a game may let give.
void buildVehicle(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    keepContinuousOffForJoints(world);
    const BodyId ground = createGround(world);
    ShapeDef bump;
    bump.density = 0.0f;
    bump.friction = 0.9f;
    for (int i = -6; i <= 6; ++i) {
        world.createShape(ground, bump,
                          Polygon::box(0.6f, 0.2f, {3.0f * static_cast<float>(i), 0.0f}, 0.0f));
    }
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 1.6f};
    const BodyId chassis = world.createBody(def);
    ShapeDef body;
    body.density = 20.0f;  // 36 kg
    world.createShape(chassis, body, Polygon::box(1.5f, 0.3f));
    scene.bodies.push_back(chassis);

    ShapeDef hubShape;
    hubShape.density = 5.0f;  // 0.35 kg
    ShapeDef tyre;
    tyre.density = 4.0f;  // 2.5 kg
    tyre.friction = 0.9f;
    std::vector<JointId> axles;
    for (const float x : {-1.1f, 1.1f}) {
        const Vec2 centre{x, 0.75f};
        def.position = centre;
        const BodyId hub = world.createBody(def);
        world.createShape(hub, hubShape, Circle{{0.0f, 0.0f}, 0.15f});
        const BodyId wheel = world.createBody(def);
        world.createShape(wheel, tyre, Circle{{0.0f, 0.0f}, 0.45f});
        scene.bodies.push_back(hub);
        scene.bodies.push_back(wheel);

        PrismaticJointDef suspension =
            PrismaticJointDef::atWorldAnchor(chassis, hub, centre, {0.0f, 1.0f});
        suspension.spring = {true, 4.0f, 0.7f};
        suspension.limit = {true, -0.3f, 0.15f};
        suspension.positionSolver = options.secondarySolver.value_or(options.solver);
        suspension.biasFactor =
            options.secondarySolver ? std::optional<float>() : options.biasFactor;
        scene.joints.push_back(world.createJoint(suspension));

        RevoluteJointDef axle = options.jointAt(hub, wheel, centre);
        axle.motor = {true, -25.0f, 150.0f};
        const JointId joint = world.createJoint(axle);
        scene.joints.push_back(joint);
        scene.keyJoints.push_back(joint);
        axles.push_back(joint);
    }
    scene.beforeStep = [axles, chassis](Scene& s, int) {
        JointMotor motor = s.world->jointMotor(axles.front());
        const float x = s.world->bodyPosition(chassis).x;
        // A negative wheel speed (clockwise) drives the car to the right.
        if ((x > 14.0f && motor.speed < 0.0f) || (x < -14.0f && motor.speed > 0.0f)) {
            motor.speed = -motor.speed;
            for (const JointId axle : axles) s.world->setJointMotor(axle, motor);
        }
    };
}

}  // namespace pivot::scenes
