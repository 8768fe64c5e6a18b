// The mouse joint: a soft point constraint pulling a body point p towards a target t.
//
//   C = p - t = cB + rB - t,   Cdot = vB + wB x rB,   J = [I  skew(rB)]
// As a spring of angular frequency w = 2 pi hertz and damping ratio z on the body's mass m:
// stiffness k = m w^2, damping d = 2 m z w. Implicit integration of the spring over the step
// turns the hard constraint K P = -Cdot into the soft one
//   (K + gamma I) P = -(Cdot + bias + gamma P_acc),  M = (K + gamma I)^-1
// with the compliance gamma = 1 / (h (d + h k)) (how much the constraint may give per unit
// impulse) and bias = beta C, beta = h k gamma (the share of the error the spring removes per
// second). The accumulated impulse is capped at h * maxForce. There is no position phase: the
// spring is the correction.
//
// Box2D 2.4.1 forms k = m w^2 first. For a heavy body and a stiff spring (1e17 kg at 1e10 Hz,
// inside the input limits) that overflows, and beta = inf * 0 is NaN. Dividing out m first,
//   gamma = (1/m) / (h w (2 z + h w)),   beta = w / (2 z + h w),
// gives the same quantities with every intermediate inside float range (h w <= 6.3e10).
#pragma once

#include <cmath>
#include <cstdint>

#include "constraints/solver_body.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

struct MouseJoint {
    std::int32_t body = -1;
    std::int32_t next = -1;  // the body's next mouse joint
    Vec2 localAnchor;        // the pulled point, origin-relative in the body's frame
    Vec2 target;
    float maxForce = 0.0f;
    float hertz = 0.0f;
    float dampingRatio = 0.0f;
    Vec2 impulse;  // accumulated, for warm starting
};

struct MouseConstraint {
    std::int32_t index = 0;  // solver index of the body
    std::int32_t jointIndex = 0;
    float mB = 0.0f;
    float iB = 0.0f;
    Vec2 rB;
    Mat22 mass;  // (K + gamma I)^-1
    Vec2 bias;
    float gamma = 0.0f;
    float maxImpulse = 0.0f;
    Vec2 impulse;
};

/// Start of the step: the soft constraint at the current pose, and the warm start.
inline void prepareMouse(MouseConstraint& c, const MouseJoint& joint, Vec2 localCenter,
                         const SolverPose* positions, SolverVelocity* velocities, float dt,
                         float dtRatio, bool warmStarting) {
    const SolverPose& p = positions[c.index];
    const float omega = 2.0f * kPi * joint.hertz;
    const float hw = dt * omega;
    const float spring = 2.0f * joint.dampingRatio + hw;
    c.gamma = c.mB / (hw * spring);
    float beta = omega / spring;
    if (c.mB == 0.0f || !std::isfinite(c.gamma)) {
        // A body without mass (no longer dynamic), or a spring so soft that its compliance is
        // not a float (1e-30 Hz): nothing is pulled.
        c.mB = c.iB = 0.0f;
        c.gamma = beta = 0.0f;
    }

    c.rB = rotate(Rot(p.a), joint.localAnchor - localCenter);
    Mat22 K;
    K.cx.x = c.mB + c.iB * c.rB.y * c.rB.y + c.gamma;
    K.cx.y = -c.iB * c.rB.x * c.rB.y;
    K.cy.x = K.cx.y;
    K.cy.y = c.mB + c.iB * c.rB.x * c.rB.x + c.gamma;
    c.mass = K.inverse();
    c.bias = beta * (p.c + c.rB - joint.target);
    c.maxImpulse = dt * joint.maxForce;

    c.impulse = warmStarting ? dtRatio * joint.impulse : Vec2{};
    SolverVelocity& v = velocities[c.index];
    v.v += c.mB * c.impulse;
    v.w += c.iB * cross(c.rB, c.impulse);
}

inline void solveMouseVelocity(MouseConstraint& c, SolverVelocity* velocities) {
    SolverVelocity& v = velocities[c.index];
    Vec2 cdot = v.v + cross(v.w, c.rB);
    Vec2 P = c.mass * (-(cdot + c.bias + c.gamma * c.impulse));
    Vec2 old = c.impulse;
    c.impulse += P;
    float length2 = dot(c.impulse, c.impulse);
    if (length2 > c.maxImpulse * c.maxImpulse) c.impulse *= c.maxImpulse / std::sqrt(length2);
    P = c.impulse - old;
    v.v += c.mB * P;
    v.w += c.iB * cross(c.rB, P);
}

}  // namespace pivot
