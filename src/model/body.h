// Body storage. The solver works on the centre of mass (center, angle); the origin frame xf is
// derived from it after each step, because users place bodies by their origin.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "collision/time_of_impact.h"
#include "core/slot_pool.h"
#include "model/island_revision.h"
#include "model/shape.h"
#include "pivot/body.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

struct Body {
    BodyType type = BodyType::Static;
    Transform xf;      // frame of the body origin
    Vec2 localCenter;  // centre of mass in the body frame
    Vec2 center;       // centre of mass in the world
    float angle = 0.0f;
    Vec2 linearVelocity;  // of the centre of mass
    float angularVelocity = 0.0f;
    Vec2 force;  // accumulated until the end of the next step
    float torque = 0.0f;

    float mass = 0.0f;
    float invMass = 0.0f;
    float inertia = 0.0f;  // about the centre of mass
    float invInertia = 0.0f;

    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    bool fixedRotation = false;
    std::uint64_t userData = 0;

    // Continuous collision (world/continuous_solver.h). The step's motion is the sweep from
    // (center0, angle0) to (center, angle); alpha0 is the fraction of the step at which the
    // sweep now starts, once a time of impact has moved its start forward.
    Vec2 center0;
    float angle0 = 0.0f;
    float alpha0 = 0.0f;
    bool bullet = false;     // kept from tunnelling through dynamic bodies too
    bool continuous = true;  // takes part in continuous collision at all
    // The smallest ShapeExtent::min and largest ShapeExtent::max of a dynamic body's shapes
    // about its centre of mass (0 for other bodies), kept with the mass: what FastBodies asks.
    float minExtent = 0.0f;
    float maxExtent = 0.0f;

    std::int32_t shapeList = -1;    // head of the body's shape list
    std::int32_t jointList = -1;    // head of the body's joint edge list (see body_edge.h)
    std::int32_t contactList = -1;  // head of the body's contact edge list
    std::int32_t mouseList = -1;    // head of the body's mouse joints (MouseJoint::next)
    std::int32_t shapeCount = 0;
    std::int32_t islandIndex = -1;  // solver index within the island being solved

    // Sleeping: a body slower than the sleep tolerances accumulates sleepTime; an island whose
    // bodies all reach kTimeToSleep goes to sleep and is skipped until something wakes it.
    bool awake = true;
    bool allowSleep = true;
    float sleepTime = 0.0f;

    // Set by the step that held the body at the world's edge (holdAtWorldEdge), with the origin
    // it would have reached, or that discarded its non-finite solved state; the step lists it
    // (World::worldEdgeEvents, World::discardedBodies) and clears them.
    bool heldAtEdge = false;
    Vec2 edgeReached;
    bool discarded = false;
};

/// Recompute the origin frame from the centre of mass and angle.
inline void synchronizeTransform(Body& body) {
    body.xf.q = Rot(body.angle);
    body.xf.p = body.center - rotate(body.xf.q, body.localCenter);
}

/// The body is where it is with no motion behind it (created, teleported, its centre of mass
/// moved): the sweep starts where it ends.
inline void restartSweep(Body& body) {
    body.center0 = body.center;
    body.angle0 = body.angle;
}

/// The body's motion this step as continuous collision sweeps it: from (center0, angle0), where
/// the step's motion started (or an impact left it, at alpha0 of the step), to where it is.
inline Sweep sweepOf(const Body& b) {
    Sweep s;
    s.localCenter = b.localCenter;
    s.c0 = b.center0;
    s.c = b.center;
    s.a0 = b.angle0;
    s.a = b.angle;
    s.alpha0 = b.alpha0;
    return s;
}

/// Continuous collision's roles (world/continuous_solver.h). A body that can stop another in
/// mid-step: any but a dynamic non-bullet.
inline bool stopsTunnelling(const Body& body) {
    return body.bullet || body.type != BodyType::Dynamic;
}
/// One that moves, too: a kinematic body or a bullet.
inline bool movesAndStopsTunnelling(const Body& body) {
    return body.type != BodyType::Static && stopsTunnelling(body);
}
/// A dynamic body left out of continuous collision (BodyDef::continuous false).
inline bool optedOutOfContinuous(const Body& body) {
    return body.type == BodyType::Dynamic && !body.continuous;
}

/// Flushes a denormal to zero: the API refuses denormals, so the engine must not produce any in
/// a state the caller can read back and set again.
inline float flushDenormal(float value) {
    return std::fabs(value) < std::numeric_limits<float>::min() ? 0.0f : value;
}
inline Vec2 flushDenormal(Vec2 value) {
    return {flushDenormal(value.x), flushDenormal(value.y)};
}

/// An angle beyond +-kMaxMagnitude reduced by whole turns to (-pi, pi]: the same rotation as an
/// angle the API accepts. Position corrections of a light body on a long lever can turn it by
/// more than kMaxMagnitude rad in a step, where a float angle no longer resolves a turn anyway.
inline float angleWithinLimits(float angle) {
    if (std::fabs(angle) <= kMaxMagnitude) return angle;
    return static_cast<float>(
        std::remainder(static_cast<double>(angle), 2.0 * 3.14159265358979323846));
}

/// Holds a solved linear velocity within kMaxSpeed, the most the API accepts. Returns whether it
/// had to.
inline bool holdLinearSpeed(Vec2& v) {
    if (lengthSquared(v) <= kMaxSpeed * kMaxSpeed) return false;
    v *= kMaxSpeed / length(v);
    // The scaling may round a component just past the limit.
    v = {std::fmin(std::fmax(v.x, -kMaxSpeed), kMaxSpeed),
         std::fmin(std::fmax(v.y, -kMaxSpeed), kMaxSpeed)};
    return true;
}
/// The same for an angular velocity and kMaxAngularSpeed.
inline bool holdAngularSpeed(float& w) {
    if (std::fabs(w) <= kMaxAngularSpeed) return false;
    w = std::copysign(kMaxAngularSpeed, w);
    return true;
}

/// Keeps the body's origin within +-kMaxCoordinate, the limit setBodyTransform checks: a body
/// that went further is put back on the edge it crossed (its centre of mass with it), and its
/// velocity outwards across that edge is stopped. Returns whether it had to.
bool holdAtWorldEdge(Body& body);

/// Sleep: no motion and no pending push until something wakes the body. The islands change:
/// the caller counts it in the world's IslandRevision (the stepper does so after its islands
/// are solved, since islands fall asleep on several workers at once).
inline void putToSleep(Body& body) {
    body.awake = false;
    body.sleepTime = 0.0f;
    body.linearVelocity = Vec2{};
    body.angularVelocity = 0.0f;
    body.force = Vec2{};
    body.torque = 0.0f;
}

/// Wake a body; static bodies have nothing to wake. A sleeping body waking changes the islands.
inline void wakeUp(Body& body, IslandRevision& islands) {
    if (body.type == BodyType::Static) return;
    if (!body.awake) islands.bump();
    body.awake = true;
    body.sleepTime = 0.0f;
}

/// Recompute mass, centre of mass and inertia from the body's type and shapes. Moving the
/// centre of mass keeps the velocity of the centre consistent with the body's rotation.
void updateBodyMass(Body& body, const SlotPool<Shape>& shapes);

/// A change to a body's type or shapes not made yet, so that what updateBodyMass would make of
/// the body can be checked before anything changes.
struct MassChange {
    BodyType type;
    const Shape* added = nullptr;  // a shape about to be attached (at the head of the list)
    std::int32_t removed = -1;     // a shape about to be destroyed
    std::int32_t reweighed = -1;   // a shape about to get `density`
    float density = 0.0f;
};

/// The body as updateBodyMass would leave it after `change`; nothing is changed.
Body bodyAfterMassChange(const Body& body, const SlotPool<Shape>& shapes, const MassChange& change);

}  // namespace pivot
