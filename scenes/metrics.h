// Measurements of a scene as it runs: joint separation, energy, blow-up, cost.
#pragma once

#include <functional>

#include "scene.h"

namespace pivot::scenes {

/// Speed (m/s) beyond which a body counts as runaway. At 60 Hz the translation clamp holds
/// bodies below 120 m/s, so only a broken solver gets near this.
constexpr float kRunawaySpeed = 1.0e4f;

/// The closing stretch of a run over which its settled error is measured, s.
constexpr double kSettleSeconds = 2.0;
/// A joint further apart than this at the end of a run has come apart, m: a link's length in
/// the chains, far beyond any error a holding joint shows (centimetres), far below the tens of
/// metres a torn chain stretches to.
constexpr double kTornSeparation = 1.0;

/// Kinetic plus gravitational potential energy of the scene's bodies, J, with potential
/// measured from y = 0 along the world's gravity: sum 1/2 m v^2 + 1/2 I w^2 - m g.c.
double mechanicalEnergy(const Scene& scene);

/// Largest |anchorB - anchorA| over the scene's joints, m; and the sum of squares (for RMS).
struct SeparationSample {
    double max = 0.0;
    double sumSquares = 0.0;
    int count = 0;
};
SeparationSample sampleSeparation(const Scene& scene);
/// The same over the scene's joints that `solver` solves now (the browser testbed's plot, one
/// line per solver: joints may change solver as the scene runs); count 0 if none does.
SeparationSample sampleSeparation(const Scene& scene, PositionSolver solver);

/// True when any body has a non-finite pose or velocity, or moves faster than kRunawaySpeed.
bool isBlownUp(const Scene& scene);

struct RunSettings {
    int steps = 600;
    float hz = 60.0f;
    int velocityIterations = kBox2D241VelocityIterations;
    int positionIterations = kBox2D241PositionIterations;
};

struct RunMetrics {
    int steps = 0;                 ///< steps taken (a run stops at the first blown-up step)
    double maxSeparation = 0;      ///< m, over all joints and steps
    double maxSideSeparation = 0;  ///< m, over Scene::sideJoints and all steps
    double rmsSeparation = 0;      ///< m, over all joints and steps
    double finalSeparation = 0;    ///< m, largest over joints after the last step
    /// m, largest over joints and the last kSettleSeconds of the run (the whole run if shorter)
    double settledSeparation = 0;
    double energyStart = 0;  ///< J, before the first step
    double energyEnd = 0;    ///< J, after the last step
    bool blewUp = false;
    long translationClamps = 0;         ///< body-steps limited by kMaxTranslation
    long rotationClamps = 0;            ///< body-steps limited by kMaxRotation
    double meanPositionIterations = 0;  ///< NGS sweeps per step actually run
    /// Joint solves per step of the extra sweeps joints asked for (StepStats::extraPositionSolves)
    double meanExtraPositionSolves = 0;
    double microsecondsPerStep = 0;  ///< mean wall time of World::step alone
    /// rad, the furthest any limited joint went beyond its limits.
    double maxLimitViolation = 0;
    /// s from the end of the scene's disturbance until every joint is back within kLinearSlop
    /// for the rest of the run: kNever if it is not back at the end, kNotApplicable if the
    /// scene has no disturbance.
    double recoverySeconds = kNotApplicable;
    /// m/s, RMS speed of the scene's bodies once it should be at rest (kNotApplicable if it
    /// never should be).
    double jitter = kNotApplicable;
    /// m, the deepest overlap of any touching contact after any step, and over the last
    /// kSettleSeconds (0 without contacts).
    double maxPenetration = 0;
    double settledPenetration = 0;
    /// m/s, the fastest any of the scene's bodies moved after a step (a stack pushed apart:
    /// its pop-out speed).
    double maxSpeed = 0;
    /// m, how far the scene's bodies' centre of mass (mass-weighted) ended below where it began:
    /// a stack that holds loses its drop and settling; one that collapses, metres. (Bodies a
    /// scene adds as it runs count at the end only: read it on scenes that add none.)
    double heightLost = 0;

    static constexpr double kNever = -1.0;
    static constexpr double kNotApplicable = -2.0;

    double energyDrift() const { return energyEnd - energyStart; }
    /// Settled further apart than kTornSeparation, or blown up.
    bool torn() const { return blewUp || !(settledSeparation <= kTornSeparation); }
    /// Body-steps cut short by the translation or the rotation clamp (a body clamped in both
    /// counts twice): where these are many, the clamps, not the solver, shape the run.
    long clampedBodySteps() const { return translationClamps + rotationClamps; }
};

/// rad, how far the scene's limited joints are beyond their limits now (0 within).
double limitViolation(const Scene& scene);

/// Steps the scene, measuring after every step. `afterStep(stepIndex)`, when given, runs after
/// each step's measurements (for time series).
RunMetrics runScene(Scene& scene, const RunSettings& settings,
                    const std::function<void(int)>& afterStep = {});

}  // namespace pivot::scenes
