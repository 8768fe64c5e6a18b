// Scenes shared by the testbed, the tests and (later) the benchmarks, so that what is
// measured is what is tested. A scene builds into a fresh World and records the bodies and
// joints that its metrics look at.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::scenes {

/// How a scene is built: the joint solver and bias for every joint, the contact correction,
/// the time step, gravity.
struct SceneOptions {
    PositionSolver solver = PositionSolver::FullNGS;
    std::optional<float> biasFactor;  ///< unset: the solver's default
    ContactCorrection contactCorrection = ContactCorrection::NGS;
    float hz = 60.0f;
    Vec2 gravity{0.0f, -10.0f};
    int workerCount = 1;                                         ///< WorldDef::workerCount
    int substepCount = 1;                                        ///< WorldDef::substepCount
    BroadPhaseBoxes broadPhaseBoxes = BroadPhaseBoxes::Compact;  ///< WorldDef's
    /// WorldDef's continuous collision policy (the default: Substeps, Box2D 2.4.1's).
    ContinuousCollision continuousCollision = ContinuousCollision::Substeps;
    /// Continuous collision switched on or off after the scene is built; unset: as the scene
    /// has it (on, unless the scene calls keepContinuousOffForJoints).
    std::optional<bool> continuous;
    /// A seed for a perturbed run (scenes/perturbation.h): 0 builds the scene exactly; others
    /// tilt and scale gravity and scale the initial velocities by about 1e-3.
    std::uint32_t perturbation = 0;
    /// Mixing: the solver of the joints a scene marks secondary (a ragdoll's elbows and knees,
    /// a bridge's decorative chains, a rope's links far from its load), at that solver's default
    /// bias; unset: `solver` for every joint.
    std::optional<PositionSolver> secondarySolver;
    /// Mixing's second knob: the extraPositionIterations of the joints a scene does not mark
    /// secondary (jointAt's); secondary joints ask for none.
    int keyExtraIterations = 0;

    /// A revolute joint def at a world anchor carrying this scene's solver and bias.
    RevoluteJointDef jointAt(BodyId a, BodyId b, Vec2 anchor) const;
    /// The same for a joint the scene marks secondary (secondarySolver).
    RevoluteJointDef secondaryJointAt(BodyId a, BodyId b, Vec2 anchor) const;
    /// A distance joint def between the bodies' origins carrying this scene's solver and bias.
    DistanceJointDef distanceJoint(BodyId a, BodyId b) const;
    /// A gear joint def coupling two joints by `ratio`, carrying this scene's solver and bias.
    GearJointDef gear(JointId joint1, JointId joint2, float ratio) const;
};

struct Scene {
    std::string name;
    std::unique_ptr<World> world;
    std::vector<BodyId> bodies;  ///< the dynamic bodies (energy, blow-up checks)
    std::vector<JointId> joints;
    /// Called before each step with the step's index (0 first), for scenes where something
    /// happens during the run (a body dropped in, a drive torque). May add bodies and joints.
    std::function<void(Scene&, int)> beforeStep;
    /// The step after which the scene's disturbance is over (a drag released, a box landed):
    /// the joints' recovery is timed from it. -1: the scene has no disturbance.
    int disturbanceEndStep = -1;
    /// The step from which the scene should be at rest: body speeds after it count as jitter.
    /// -1: the scene is never meant to be at rest.
    int restFromStep = -1;
    /// Where the scene is built: its bodies stay within a few tens of metres of it (the soak's
    /// bound and the figures' views are measured from here).
    Vec2 origin;
    /// The joints that matter, whose error the mixing study measures (the scenes built for it
    /// name them; empty elsewhere).
    std::vector<JointId> keyJoints;
    /// Joints measured apart from `joints` (RunMetrics::maxSideSeparation): the mixing study
    /// puts the joints that matter less here, to show what they pay.
    std::vector<JointId> sideJoints;
};

/// A Scene::beforeStep that reverses a revolute or wheel joint's motor every `steps` steps.
std::function<void(Scene&, int)> reverseMotorEvery(JointId joint, int steps);

using SceneBuilder = void (*)(Scene& scene, const SceneOptions& options);

struct SceneInfo {
    const char* name;
    const char* description;
    SceneBuilder build;
};

/// Every scene, in the order the testbed's full table lists them.
const std::vector<SceneInfo>& allScenes();
/// nullptr when there is no scene of that name.
const SceneInfo* findScene(std::string_view name);
/// Makes the world (gravity from options) and builds the scene into it.
Scene buildScene(const SceneInfo& info, const SceneOptions& options);

// The individual scenes (defined in their own files).
void buildPendulum(Scene& scene, const SceneOptions& options);
/// The pendulum spun at `spin` rad/s about its pivot (buildPendulum uses 100).
void buildSpinningPendulum(Scene& scene, const SceneOptions& options, float spin);
void buildLimitedPendulum(Scene& scene, const SceneOptions& options);
void buildDoublePendulum(Scene& scene, const SceneOptions& options);
void buildMotorWheel(Scene& scene, const SceneOptions& options);
void buildBridge(Scene& scene, const SceneOptions& options);
void buildChain(Scene& scene, const SceneOptions& options);
void buildFarChain(Scene& scene, const SceneOptions& options);
void buildBridgeHeavy(Scene& scene, const SceneOptions& options);
void buildBridgeCrate(Scene& scene, const SceneOptions& options);
void buildPyramid(Scene& scene, const SceneOptions& options);
void buildTumbler(Scene& scene, const SceneOptions& options);
void buildPendulumDrag(Scene& scene, const SceneOptions& options);
void buildChainDrag(Scene& scene, const SceneOptions& options);
void buildRagdoll(Scene& scene, const SceneOptions& options);
void buildMotorizedRagdoll(Scene& scene, const SceneOptions& options);
void buildDistancePendulum(Scene& scene, const SceneOptions& options);
void buildRope(Scene& scene, const SceneOptions& options);
void buildPlankRope(Scene& scene, const SceneOptions& options);
void buildSlowPendulum(Scene& scene, const SceneOptions& options);
void buildOffsetDistancePendulum(Scene& scene, const SceneOptions& options);
void buildPulley(Scene& scene, const SceneOptions& options);
void buildElevator(Scene& scene, const SceneOptions& options);
void buildPulleyGear(Scene& scene, const SceneOptions& options);
void buildStretchedChain(Scene& scene, const SceneOptions& options);
void buildBallChain(Scene& scene, const SceneOptions& options);
void buildHangingStretchedChain(Scene& scene, const SceneOptions& options);
void buildLightOnHeavy(Scene& scene, const SceneOptions& options);
void buildLongBridge(Scene& scene, const SceneOptions& options);
void buildRamps(Scene& scene, const SceneOptions& options);
void buildBullets(Scene& scene, const SceneOptions& options);
void buildPlatformer(Scene& scene, const SceneOptions& options);
void buildHeavyStack(Scene& scene, const SceneOptions& options);
void buildOverlapRecovery(Scene& scene, const SceneOptions& options);
/// Not in the table: the gear joint's Box2D reference case (gear_train.cpp).
void buildGearTrain(Scene& scene, const SceneOptions& options);
void buildWeldBeam(Scene& scene, const SceneOptions& options);
void buildCar(Scene& scene, const SceneOptions& options);
void buildTopDown(Scene& scene, const SceneOptions& options);
void buildMotorDrive(Scene& scene, const SceneOptions& options);
/// 20 light links holding a ball 3,000 times heavier.
void buildMassRatio(Scene& scene, const SceneOptions& options);
// Built for the mixing study (mixing_scenes.cpp): each names its keyJoints and marks the others
// secondary.
void buildRagdollPile(Scene& scene, const SceneOptions& options);
void buildBridgeChains(Scene& scene, const SceneOptions& options);
void buildRopeLoad(Scene& scene, const SceneOptions& options);
void buildVehicle(Scene& scene, const SceneOptions& options);
void buildJointGrid(Scene& scene, const SceneOptions& options);
/// One ragdoll (ragdoll.cpp's) at `origin`, thrown with `velocity` and `spin` about its chest,
/// its parts in collision group `group` (negative: they never collide with each other). Its neck,
/// shoulders and hips are key joints on scene.keyJoints; elbows and knees are secondary.
void addRagdoll(Scene& scene, const SceneOptions& options, Vec2 origin, Vec2 velocity, float spin,
                bool motorized, int group);

/// The step index of time t (s) at the scene's rate.
inline int stepAt(const SceneOptions& options, float seconds) {
    return static_cast<int>(seconds * options.hz + 0.5f);
}

}  // namespace pivot::scenes
