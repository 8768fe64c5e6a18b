// Tuning constants, each with its unit and the reason for its value. The values are those of
// Box2D 2.4.1 (published constants), so that pivot2d's FullNGS joint can reproduce that
// engine's reference revolute joint step for step. Change them knowing that every scene,
// test tolerance and recorded hash depends on them.
#pragma once

#include "pivot/math.h"

namespace pivot {

/// Metres. Position error a joint or contact may keep: corrections stop once errors are below
/// it, which avoids jitter from chasing round-off. Also the NGS early-exit threshold.
/// Normally 0.5 cm; it is tuned for bodies of 0.1 m to 10 m and moving objects up to ~10 m.
constexpr float kLinearSlop = 0.005f;

/// Radians. Angular error an angle limit may keep (2 degrees), for the same reason.
constexpr float kAngularSlop = 2.0f / 180.0f * kPi;

/// Radians. The largest angle-limit correction in one position iteration (8 degrees): large
/// jumps in angle overshoot, so the limit is approached over several iterations.
constexpr float kMaxAngularCorrection = 8.0f / 180.0f * kPi;

/// Metres per step. The largest distance a body may move in one step. Larger velocities are
/// scaled down (the velocity itself, not just the move), which keeps a fast body from
/// tunnelling or exploding the solver. At 60 Hz this is 120 m/s.
constexpr float kMaxTranslation = 2.0f;

/// Radians per step. The largest rotation of a body in one step (a quarter turn); at 60 Hz
/// this is about 94 rad/s. Same reason as kMaxTranslation.
constexpr float kMaxRotation = 0.5f * kPi;

/// Metres. The largest position correction a contact applies in one NGS solve: a deep overlap
/// is resolved over several steps instead of launching bodies apart.
constexpr float kMaxLinearCorrection = 0.2f;

/// Metres. Every polygon collides as if rounded by this skin (twice the linear slop), so that
/// resting polygons keep a small gap and contacts exist before the shapes' cores touch. It does
/// not change mass properties.
constexpr float kPolygonRadius = 2.0f * kLinearSlop;

/// Metres. Broad-phase boxes are fattened by this margin, so a shape that moves a little does
/// not need its box updated every step.
constexpr float kAabbMargin = 0.1f;

/// Metres. BroadPhaseBoxes::Compact's margins, Box2D v3's: a moving shape's box is fattened by
/// v3's margin (0.05 m) plus the speculative distance v3 adds to every box (4 linear slops,
/// 0.02 m); a static shape's by the speculative distance twice, since static shapes never move
/// out of their boxes. Tighter boxes make fewer pairs that never touch.
constexpr float kCompactAabbMargin = 0.07f;
constexpr float kCompactStaticAabbMargin = 0.04f;

/// Broad-phase boxes are also stretched along a body's motion by this many steps' worth of
/// displacement, predicting where it will be.
constexpr float kAabbMotionFactor = 4.0f;

/// m/s. A contact closing faster than this bounces with its restitution; slower contacts are
/// treated as inelastic so resting bodies do not jitter.
constexpr float kRestitutionThreshold = 1.0f;
/// m/s: WorldDef::hitEventThreshold's default (Box2D v3's).
constexpr float kDefaultHitEventThreshold = 1.0f;

/// Sleeping: a body slower than these for kTimeToSleep seconds may sleep, with its island.
constexpr float kLinearSleepTolerance = 0.01f;                 ///< m/s
constexpr float kAngularSleepTolerance = 2.0f / 180.0f * kPi;  ///< rad/s
constexpr float kTimeToSleep = 0.5f;                           ///< s

/// Default bias factor of contact position correction (both the Baumgarte velocity bias and
/// the NGS position solve): contacts remove a fifth of their penetration beyond the slop per
/// step or solve, which keeps stacks from popping apart.
constexpr float kDefaultContactBias = 0.2f;

/// The maximum number of vertices of a convex polygon. Small and fixed so polygons are
/// stored inline without allocation.
constexpr int kMaxPolygonVertices = 8;

/// Default bias factors (dimensionless fraction of the position error removed per step or per
/// solve). 0.2 for the velocity-level methods (the seed note's value: larger makes a bridge
/// less stable, smaller makes joints spongy); 1.0 for the NGS methods, which correct the
/// error they re-measure and need no tuning.
constexpr float kDefaultBaumgarteBias = 0.2f;
constexpr float kDefaultPseudoVelocityBias = 0.2f;
constexpr float kDefaultNgsBias = 1.0f;

/// Soft step's defaults (PositionSolver::SoftStep, ContactCorrection::Soft), Box2D v3's: a joint's
/// position error is a spring of 60 Hz at damping ratio 2 on the joint's own effective mass,
/// a contact's penetration one of 30 Hz at damping ratio 10 that never pushes apart faster than
/// 3 m/s. Joints are stiffer than contacts because a stack may yield a little where a chain
/// must not; both are heavily damped (a ratio of 1 is critical) so the correction never
/// overshoots into a bounce. Each is used at most at kMaxSoftHertzShare of the substep rate.
constexpr float kDefaultJointHertz = 60.0f;
constexpr float kDefaultJointDampingRatio = 2.0f;
constexpr float kDefaultContactHertz = 30.0f;
constexpr float kDefaultContactDampingRatio = 10.0f;
constexpr float kDefaultContactPushSpeed = 3.0f;  ///< m/s
/// A soft row's stiffness is at most this share of the substep rate (hertz <= share / h): with
/// omega h <= pi, a row at damping ratio 2 corrects at most pi / (4 + pi), 44%, of its error per
/// substep, so it cannot throw the bodies past it the way a full correction can.
constexpr float kMaxSoftHertzShare = 0.5f;

/// A pulley joint's ratio lies in [kMinPulleyRatio, 1 / kMinPulleyRatio]: beyond, one side's
/// share of the effective mass vanishes and the constraint is as good as one-sided.
constexpr float kMinPulleyRatio = 0.01f;
/// m: a pulley side shorter than this has no reliable direction (its rope's angle is lost in
/// the rounding of the positions), and is not held.
constexpr float kMinPulleyLength = 10.0f * kLinearSlop;

/// A gear joint's |ratio| lies in [kMinGearRatio, 1 / kMinGearRatio], for the same reason.
constexpr float kMinGearRatio = 0.01f;

/// WorldDef's defaults: each World::step is 8 substeps, each with 2 velocity iterations and 1
/// position iteration. The cheapest split found where a 36 kg crate dropped on a bridge of 0.4 kg
/// planks stays on it and a rope of 30 links holding 24 times a link's mass keeps every pin
/// within 2 cm (docs/position-correction.md, "Defaults"); it costs about 2.2 to 2.9 times as much
/// as Box2D 2.4.1's one step of 8 and 3 iterations, which meets neither.
constexpr int kDefaultSubstepCount = 8;
constexpr int kDefaultVelocityIterations = 2;
constexpr int kDefaultPositionIterations = 1;

/// Box2D 2.4.1's budget: one substep of 8 velocity and 3 position iterations
/// (WorldDef::box2d241()).
constexpr int kBox2D241VelocityIterations = 8;
constexpr int kBox2D241PositionIterations = 3;

/// Upper bound on iteration counts accepted by World::step: more is certainly a mistake
/// (a negative number cast to unsigned, say) and would stall the caller.
constexpr int kMaxIterations = 1000;

/// The most substeps a step may be split into (WorldDef::substepCount). Each substep repeats
/// the whole solve, so beyond this the cost, not the accuracy, is what changes.
constexpr int kMaxSubsteps = 64;

// Input limits. These are pivot2d's own (Box2D has no such checks): every number the API takes
// must be finite and within them, or the call throws pivot::Error. They are far beyond anything
// a game builds, and they keep each product a step forms from them (mass times length squared,
// inverse inertia times torque, ...) inside float range. They cannot stop a solver diverging on
// constraints that contradict each other; docs/reliability.md gives what the fuzzing found.

/// Metres. The largest |x| or |y| of a position, anchor, point, target, polygon vertex, circle
/// centre or radius. At 1e5 m neighbouring floats are 7.8 mm apart, more than kLinearSlop:
/// further out, joints and contacts could not hold their slop. Simulation may carry a body
/// beyond it (nothing stops a fall), with the precision that implies.
constexpr float kMaxCoordinate = 1.0e5f;

/// kg/m^2. A shape's density is 0 (no mass) or within [kMinDensity, kMaxDensity]: the range of
/// real materials spread over any thickness a 2D world means, and narrow enough that the
/// lightest allowed shape (a kLinearSlop sliver) still has an inverse mass and inverse inertia
/// that are finite floats, and the heaviest an inertia that is.
constexpr float kMinDensity = 1.0e-6f;
constexpr float kMaxDensity = 1.0e6f;

/// The largest magnitude of every other number the API takes: forces (N),
/// torques (N m), impulses (N s, N m s), angles (rad), damping (1/s), the restitution
/// threshold (m/s), joint limits, motor speed and torque, let-go separations (m), and the mouse
/// joint's force, frequency and damping ratio. It also bounds what calls accumulate on a body
/// between steps: the velocity that impulses add up to, and the pending force and torque.
constexpr float kMaxMagnitude = 1.0e10f;

/// m/s and rad/s. The largest linear and angular speed the API takes (a body's velocities, a
/// motor's speed), and the most that impulses may add up to. They bound momentum: the heaviest
/// shape (kMaxDensity over a kMaxCoordinate box, 4e16 kg) at this speed, over the shortest step,
/// is a force of 4e27 N, and times the longest lever arm a torque of 1e33 N m, both well inside
/// float range; at kMaxMagnitude m/s and a 1e-6 s step a joint's reaction overflowed. Both
/// are above anything the engine produces (kMaxTranslation and kMaxRotation per kMinTimeStep:
/// 2e5 m/s, 1.6e5 rad/s), so every velocity the engine reports can be set again.
constexpr float kMaxSpeed = 1.0e6f;
constexpr float kMaxAngularSpeed = 1.0e6f;

/// How far from unit length a rotation (Rot, a Transform's q) the API takes may be: |s^2 + c^2 -
/// 1| at most this. Rot(angle) and every rotation the engine reports are well within it; a
/// rotation outside it would stretch or collapse the shape it turns, and is refused rather than
/// normalised, so that what the call computes is what it was given.
constexpr float kMaxRotationError = 1.0e-4f;

/// The largest friction coefficient (real materials stay below 2). The friction impulse is up
/// to this times the normal impulse, and the larger limit of kMaxMagnitude let it overflow.
constexpr float kMaxFriction = 100.0f;

/// m/s^2 and a factor. Gravity and a body's gravity scale are bounded separately so that their
/// product, the acceleration a step gives the body, stays within kMaxMagnitude like every
/// other rate: at 1e10 x 1e10 a heavy body's momentum overflowed within a step. 1e5 m/s^2 is
/// ten thousand g.
constexpr float kMaxGravity = 1.0e5f;
constexpr float kMaxGravityScale = 1.0e5f;

/// Seconds. The longest time step World::step accepts. A longer one is a unit mistake (ms for
/// s): kMaxTranslation per step would cap every body below 2 m/s.
constexpr float kMaxTimeStep = 1.0f;

/// Seconds. The shortest time step World::step accepts (a hundred thousand steps per simulated
/// second). A step forms 1/dt: in joint and contact reactions (impulse / dt), in Baumgarte's
/// bias (error / dt) and in the per-step clamps (kMaxTranslation / dt, the fastest the engine
/// moves a body). Above this they stay far inside float range for every accepted input (see
/// kMaxSpeed); at 1e-40 s, 1/dt was infinite. A shorter step is a mistake (the remainder of a
/// fixed-step accumulator, a unit slip): skip the step, or carry the time over to the next one.
constexpr float kMinTimeStep = 1.0e-5f;

}  // namespace pivot
