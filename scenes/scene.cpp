#include "scene.h"

#include "perturbation.h"

namespace pivot::scenes {

RevoluteJointDef SceneOptions::jointAt(BodyId a, BodyId b, Vec2 anchor) const {
    RevoluteJointDef def = RevoluteJointDef::atWorldAnchor(a, b, anchor);
    def.positionSolver = solver;
    def.biasFactor = biasFactor;
    def.extraPositionIterations = keyExtraIterations;
    return def;
}

RevoluteJointDef SceneOptions::secondaryJointAt(BodyId a, BodyId b, Vec2 anchor) const {
    RevoluteJointDef def = jointAt(a, b, anchor);
    def.extraPositionIterations = 0;
    if (secondarySolver) {
        def.positionSolver = *secondarySolver;
        def.biasFactor.reset();
    }
    return def;
}

GearJointDef SceneOptions::gear(JointId joint1, JointId joint2, float ratio) const {
    GearJointDef def;
    def.joint1 = joint1;
    def.joint2 = joint2;
    def.ratio = ratio;
    def.positionSolver = solver;
    def.biasFactor = biasFactor;
    return def;
}

std::function<void(Scene&, int)> reverseMotorEvery(JointId joint, int steps) {
    return [joint, steps](Scene& scene, int step) {
        if (step == 0 || step % steps != 0) return;
        JointMotor motor = scene.world->jointMotor(joint);
        motor.speed = -motor.speed;
        scene.world->setJointMotor(joint, motor);
    };
}

DistanceJointDef SceneOptions::distanceJoint(BodyId a, BodyId b) const {
    DistanceJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.positionSolver = solver;
    def.biasFactor = biasFactor;
    return def;
}

const std::vector<SceneInfo>& allScenes() {
    static const std::vector<SceneInfo> scenes = {
        {"pendulum", "1 m ball on a massless 5 m stick, spun at 100 rad/s about the pivot",
         buildPendulum},
        {"pendulum_20",
         "the pendulum spun at 20 rad/s: 100 m/s, below the speed clamps that act at 100 rad/s",
         buildSlowPendulum},
        {"pendulum_limit", "the pendulum released level, swinging into a -60 degree limit",
         buildLimitedPendulum},
        {"double_pendulum", "two 1 m balls on 2.5 m sticks, released level (chaotic)",
         buildDoublePendulum},
        {"motor_wheel", "a motor turning an eccentric wheel against gravity", buildMotorWheel},
        {"bridge", "30 planks 1.0 x 0.25 m jointed end to end, both ends pinned", buildBridge},
        {"chain", "30 links 1 m apart pinned at one end, released horizontally", buildChain},
        {"long_bridge", "160 planks of the bridge's kind pinned end to end, 160 m of deck at 40 m",
         buildLongBridge},
        {"bridge_heavy", "the bridge; after 2 s a box of 4x its mass falls on its middle from 5 m",
         buildBridgeHeavy},
        {"bridge_crate",
         "20 planks of 0.4 kg pinned end to end, a 36 kg crate released 2 m above their middle",
         buildBridgeCrate},
        {"pyramid", "1 m boxes stacked 20 rows high on the ground", buildPyramid},
        {"tumbler", "a box pinned at its centre and turned slowly, tumbling 200 small boxes",
         buildTumbler},
        {"pendulum_drag",
         "the pendulum's ball dragged round a 3 m circle, up to 4 rev/s, released at 3 s",
         buildPendulumDrag},
        {"chain_drag", "the chain's free end yanked and whirled at 1-4 s, then released",
         buildChainDrag},
        {"ragdoll", "a 10-body ragdoll with limited joints thrown at a wall and the ground",
         buildRagdoll},
        {"ragdoll_motorized", "the ragdoll with a holding motor in every joint",
         buildMotorizedRagdoll},
        {"ragdoll_pile", "six ragdolls dropped one above the other into a 5 m pit",
         buildRagdollPile},
        {"distance_pendulum",
         "the pendulum on a 5 m distance joint (a rod) instead of a pin, spun at 100 rad/s",
         buildDistancePendulum},
        {"distance_pendulum_offset",
         "the distance pendulum with its rod tied to the ball's rim, so that its effective mass "
         "changes as the ball turns",
         buildOffsetDistancePendulum},
        {"rope", "30 beads tied by 0.5-1 m ropes (distance joint limits), released level",
         buildRope},
        {"plank_rope",
         "30 planks of 0.4 m tied end to end by 0.3-0.6 m ropes, released level (the ropes' "
         "effective masses change with the pose)",
         buildPlankRope},
        {"pulley", "two boxes on a 1.5:1 pulley, the lighter hung off its wheel and swinging",
         buildPulley},
        {"top_down", "12 boxes sliding and spinning on a table seen from above (friction joints)",
         buildTopDown},
        {"motor_drive", "a plank driven round a figure of eight by a motor joint", buildMotorDrive},
        {"weld_beam",
         "ten boxes welded into a cantilever out of a wall, a box of 20x their mass welded at "
         "the tip",
         buildWeldBeam},
        {"car",
         "a car on two sprung wheel joints driven back and forth over bumps, its rear wheel "
         "motorised",
         buildCar},
        {"elevator",
         "a platform on a prismatic joint carrying an off-centre load up and down between limits",
         buildElevator},
        {"pulley_gear",
         "a motorised wheel geared to a bigger one geared to a rack on a limited slide, the rack "
         "hung on a pulley against a swinging counterweight",
         buildPulleyGear},
        {"stretched_chain",
         "40 links hung from the ground and released level, every joint starting 1 m apart",
         buildStretchedChain},
        {"stretched_chain_hanging",
         "the stretched chain hung straight down, every joint 1 m open, released at rest",
         buildHangingStretchedChain},
        {"ball_chain", "40 links released level holding a ball of 600 times a link's mass",
         buildBallChain},
        {"rope_load",
         "30 planks of 5 kg pinned end to end holding a 120 kg ball (24 times a link), released "
         "level",
         buildRopeLoad},
        {"joint_grid",
         "12 x 12 circles each pinned to its neighbours above and on its left, hanging from the "
         "middle of the top row",
         buildJointGrid},
        {"mass_ratio",
         "20 links released level holding a ball of 3,000 times a link's mass by its rim",
         buildMassRatio},
        {"heavy_stack", "six 1 kg boxes stacked under a 100 kg box", buildHeavyStack},
        {"light_on_heavy", "six 1 kg boxes stacked on a 100 kg box", buildLightOnHeavy},
        {"overlap_recovery",
         "a pyramid of ten boxes created a quarter of a box deep into each other and the ground",
         buildOverlapRecovery},
        {"bridge_chains",
         "the bridge with a swinging chain of six links hanging from every fifth plank",
         buildBridgeChains},
        {"vehicle",
         "a car on pinned wheels under hubs that slide on sprung prismatic suspensions, driven "
         "back and forth over bumps",
         buildVehicle},
        {"far_chain", "the chain 30 km from the origin, where floats are 2 mm apart",
         buildFarChain},
        {"ramps",
         "balls, boxes and a capsule down a chain-shape ramp, over a bump and into a hanging chain",
         buildRamps},
        {"bullets", "a pyramid shot at by ten bullets at 120 m/s (continuous collision)",
         buildBullets},
        {"platformer",
         "a capsule character runs over chain terrain and one-way platforms, picks up a coin; "
         "a crate breaks the bridge behind it",
         buildPlatformer},
    };
    return scenes;
}

const SceneInfo* findScene(std::string_view name) {
    for (const SceneInfo& info : allScenes()) {
        if (name == info.name) return &info;
    }
    return nullptr;
}

Scene buildScene(const SceneInfo& info, const SceneOptions& options) {
    Scene scene;
    scene.name = info.name;
    // Box2D 2.4.1's iteration counts for World::step(dt); the runners give their own
    // (RunSettings), the substeps and boxes come from the options.
    WorldDef def;
    def.velocityIterations = kBox2D241VelocityIterations;
    def.positionIterations = kBox2D241PositionIterations;
    def.gravity = perturbedGravity(options.gravity, options.perturbation);
    def.defaultPositionSolver = options.solver;
    def.contactCorrection = options.contactCorrection;
    def.workerCount = options.workerCount;
    def.substepCount = options.substepCount;
    def.broadPhaseBoxes = options.broadPhaseBoxes;
    def.continuousCollision = options.continuousCollision;
    scene.world = std::make_unique<World>(def);
    info.build(scene, options);
    if (options.continuous) scene.world->setContinuousEnabled(*options.continuous);
    perturbVelocities(scene, options.perturbation);
    return scene;
}

}  // namespace pivot::scenes
