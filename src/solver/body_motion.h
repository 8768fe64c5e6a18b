// One body's part of a step, outside its constraints: forces and damping on its velocity, its
// move by that velocity within the step's limits, and its solved state written back. The island
// solver applies them to each body of an island; a body alone in its island (no contact, no
// joint) gets nothing else, and is solved by them directly (solveLoneBody), to the same bits.
#pragma once

#include <cmath>

#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "model/body.h"
#include "pivot/constants.h"
#include "solver/island_report.h"

namespace pivot {

/// What gravity, forces and damping do to a dynamic body's velocity over one substep, the same
/// at every substep of a step: worked out once, when the island loads its bodies, so that later
/// substeps need not read the body again.
struct VelocityDrive {
    Vec2 dv;  // h / m (gravity's force + the applied force)
    float dw = 0.0f;
    float linearFactor = 1.0f;  // 1 / (1 + h c), the damping's
    float angularFactor = 1.0f;
    bool dynamic = false;  // only dynamic bodies are driven
};

inline VelocityDrive velocityDrive(const Body& b, const StepContext& step) {
    if (b.type != BodyType::Dynamic) return VelocityDrive{};
    const float h = step.dt;
    VelocityDrive d;
    d.dv = h * b.invMass * (b.gravityScale * b.mass * step.gravity + b.force);
    d.dw = h * b.invInertia * b.torque;
    // Damping, dv/dt = -c v, integrated with the Pade approximation
    // exp(-c h) ~ 1 / (1 + c h): stable for any c h >= 0.
    d.linearFactor = 1.0f / (1.0f + h * b.linearDamping);
    d.angularFactor = 1.0f / (1.0f + h * b.angularDamping);
    d.dynamic = true;
    return d;
}

/// Gravity, forces and damping over one substep on a solver velocity (semi-implicit Euler:
/// velocities first, positions later from the new velocities).
inline void integrateVelocity(const VelocityDrive& d, SolverVelocity& velocity) {
    if (!d.dynamic) return;
    velocity = {(velocity.v + d.dv) * d.linearFactor, (velocity.w + d.dw) * d.angularFactor};
}

/// How far a body may move in one substep: its share of the step's limit (kMaxTranslation,
/// kMaxRotation), so that the fastest speed does not depend on the substep count (divided by 1,
/// the limits are exactly the constants).
struct MotionLimits {
    explicit MotionLimits(const StepContext& step)
        : maxTranslation(kMaxTranslation / static_cast<float>(step.substepCount)),
          maxRotation(kMaxRotation / static_cast<float>(step.substepCount)) {}
    float maxTranslation;
    float maxRotation;
};

/// Moves a body by its velocity over `h`, within `limits`. The limit scales the velocity itself,
/// so the next substep starts from it; each clamp is counted in `report`.
inline void integratePosition(SolverVelocity& vel, SolverPose& pos, float h,
                              const MotionLimits& limits, IslandReport& report) {
    Vec2 translation = h * vel.v;
    if (dot(translation, translation) > limits.maxTranslation * limits.maxTranslation) {
        vel.v *= limits.maxTranslation / length(translation);
        ++report.translationClamps;
    }
    float rotation = h * vel.w;
    if (rotation * rotation > limits.maxRotation * limits.maxRotation) {
        vel.w *= limits.maxRotation / std::fabs(rotation);
        ++report.rotationClamps;
    }
    pos.c += h * vel.v;
    pos.a += h * vel.w;
}

/// Writes a movable body's solved pose and velocity back. One whose solved state is not finite
/// keeps the pose it started the step with (a dynamic one at rest): NaN never reaches the
/// bodies, the broad phase or the next step. Denormals are flushed to zero, angles past
/// kMaxMagnitude reduced by whole turns, and a body that left the world's coordinate limits is
/// held at the edge, so that every state written back is one the API would accept
/// (angleWithinLimits, holdAtWorldEdge).
inline void writeBackBody(Body& b, const SolverPose& p, const SolverVelocity& v,
                          IslandReport& report) {
    restartSweep(b);  // the step's motion starts where the body was (continuous collision)
    if (!isFinite(p.c) || !std::isfinite(p.a) || !isFinite(v.v) || !std::isfinite(v.w)) {
        // A kinematic body keeps the velocity its owner set; a dynamic one stops.
        if (b.type == BodyType::Dynamic) {
            b.linearVelocity = Vec2{};
            b.angularVelocity = 0.0f;
        }
        b.discarded = true;
        ++report.discardedBodies;
        return;
    }
    b.center = flushDenormal(p.c);
    b.angle = flushDenormal(angleWithinLimits(p.a));
    // Relax sweeps (soft step) act after integration's limit: what they leave is held within
    // the speeds the API takes, and counted with the clamps.
    Vec2 linear = v.v;
    float angular = v.w;
    if (holdLinearSpeed(linear)) ++report.translationClamps;
    if (holdAngularSpeed(angular)) ++report.rotationClamps;
    b.linearVelocity = flushDenormal(linear);
    b.angularVelocity = flushDenormal(angular);
    synchronizeTransform(b);
    b.xf.p = flushDenormal(b.xf.p);
    const bool inside =
        std::fabs(b.xf.p.x) <= kMaxCoordinate && std::fabs(b.xf.p.y) <= kMaxCoordinate;
    if (!inside && holdAtWorldEdge(b)) ++report.edgeBodies;
}

}  // namespace pivot
