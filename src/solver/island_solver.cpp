#include "solver/island_solver.h"

#include <algorithm>
#include <cmath>

#include "pivot/constants.h"

namespace pivot {

namespace {

// Copy body state into the solver arrays; apply gravity, forces and damping to dynamic bodies
// (semi-implicit Euler: velocities first, positions later from the new velocities).
void integrateVelocities(Island& island, SlotPool<Body>& bodies, const StepContext& step) {
    const float h = step.dt;
    const std::size_t n = island.bodies.size();
    island.velocities.resize(n);
    island.positions.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Body& b = bodies[island.bodies[i]];
        b.center0 = b.center;  // for the broad phase's swept box
        b.angle0 = b.angle;
        Vec2 v = b.linearVelocity;
        float w = b.angularVelocity;
        if (b.type == BodyType::Dynamic) {
            v += h * b.invMass * (b.gravityScale * b.mass * step.gravity + b.force);
            w += h * b.invInertia * b.torque;
            // Damping, dv/dt = -c v, integrated with the Pade approximation
            // exp(-c h) ~ 1 / (1 + c h): stable for any c h >= 0.
            v *= 1.0f / (1.0f + h * b.linearDamping);
            w *= 1.0f / (1.0f + h * b.angularDamping);
        }
        island.positions[i] = {b.center, b.angle};
        island.velocities[i] = {v, w};
    }
}

// Build each joint's solver constraint in its strategy's group and apply the warm start.
void prepareJoints(Island& island, const SlotPool<Body>& bodies, SlotPool<RevoluteJoint>& joints,
                   const StepContext& step) {
    for (RevoluteConstraints& group : island.groups) group.clear();

    for (std::int32_t jointIndex : island.joints) {
        const RevoluteJoint& joint = joints[jointIndex];
        const Body& a = bodies[joint.bodyA()];
        const Body& b = bodies[joint.bodyB()];
        RevoluteConstraint c;
        c.jointIndex = jointIndex;
        c.biasFactor = joint.biasFactor();
        c.bodies.indexA = a.islandIndex;
        c.bodies.indexB = b.islandIndex;
        c.bodies.mA = a.invMass;
        c.bodies.mB = b.invMass;
        c.bodies.iA = a.invInertia;
        c.bodies.iB = b.invInertia;
        c.point.localRA = joint.localAnchorA - a.localCenter;
        c.point.localRB = joint.localAnchorB - b.localCenter;
        AnglePart& angle = c.angle;
        angle.referenceAngle = joint.referenceAngle;
        angle.limitEnabled = joint.enableLimit;
        angle.lower = joint.lowerAngle;
        angle.upper = joint.upperAngle;
        angle.motorEnabled = joint.enableMotor;
        angle.motorSpeed = joint.motorSpeed;
        angle.maxMotorImpulse = step.dt * joint.maxMotorTorque;
        angle.motorImpulse = joint.motorImpulse;
        angle.lowerImpulse = joint.lowerImpulse;
        angle.upperImpulse = joint.upperImpulse;
        preparePoint(c.bodies, c.point, island.positions.data());
        prepareAngle(c.bodies, angle, island.positions.data(), step.invDt);
        if (step.warmStarting) {
            // Impulses scale with the step: keep the force they stand for when dt changes.
            c.point.impulse = step.dtRatio * joint.impulse;
            angle.motorImpulse *= step.dtRatio;
            angle.lowerImpulse *= step.dtRatio;
            angle.upperImpulse *= step.dtRatio;
            warmStart(c, island.velocities.data());
        } else {
            angle.motorImpulse = 0.0f;
            angle.lowerImpulse = 0.0f;
            angle.upperImpulse = 0.0f;
        }
        island.groups[static_cast<int>(joint.solver)].push_back(c);
    }
    prepareVelocityBias(island.groups, island.positions.data(), step.invDt);
}

void storeImpulses(const Island& island, SlotPool<RevoluteJoint>& joints, float invDt) {
    for (const RevoluteConstraints& group : island.groups) {
        for (const RevoluteConstraint& c : group) {
            RevoluteJoint& joint = joints[c.jointIndex];
            joint.impulse = c.point.impulse;
            joint.motorImpulse = c.angle.motorImpulse;
            joint.lowerImpulse = c.angle.lowerImpulse;
            joint.upperImpulse = c.angle.upperImpulse;
            joint.impulseInvDt = invDt;
        }
    }
}

void prepareMouseJoints(Island& island, const SlotPool<Body>& bodies,
                        const SlotPool<MouseJoint>& mouseJoints, const StepContext& step) {
    island.mouseConstraints.clear();
    for (std::int32_t m : island.mouseJoints) {
        const MouseJoint& joint = mouseJoints[m];
        const Body& body = bodies[joint.body];
        MouseConstraint c;
        c.index = body.islandIndex;
        c.jointIndex = m;
        c.mB = body.invMass;
        c.iB = body.invInertia;
        prepareMouse(c, joint, body.mass, body.localCenter, island.positions.data(),
                     island.velocities.data(), step.dt, step.dtRatio, step.warmStarting);
        island.mouseConstraints.push_back(c);
    }
}

// Move every body by its velocity, limiting the move per step (kMaxTranslation,
// kMaxRotation). The limit scales the velocity itself so the next step starts from it.
void integratePositions(Island& island, const StepContext& step, IslandReport& report) {
    const float h = step.dt;
    for (std::size_t i = 0; i < island.bodies.size(); ++i) {
        SolverVelocity& vel = island.velocities[i];
        SolverPosition& pos = island.positions[i];
        Vec2 translation = h * vel.v;
        if (dot(translation, translation) > kMaxTranslation * kMaxTranslation) {
            vel.v *= kMaxTranslation / length(translation);
            ++report.translationClamps;
        }
        float rotation = h * vel.w;
        if (rotation * rotation > kMaxRotation * kMaxRotation) {
            vel.w *= kMaxRotation / std::fabs(rotation);
            ++report.rotationClamps;
        }
        pos.c += h * vel.v;
        pos.a += h * vel.w;
    }
}

// Bodies slower than the sleep tolerances accumulate rest time; once every body of the island
// has rested kTimeToSleep and the position phase converged, the whole island sleeps.
bool updateSleep(const Island& island, SlotPool<Body>& bodies, const StepContext& step,
                 bool positionSolved) {
    if (!step.enableSleep) return false;
    const float linearTolerance = kLinearSleepTolerance * kLinearSleepTolerance;
    const float angularTolerance = kAngularSleepTolerance * kAngularSleepTolerance;
    float minSleepTime = kTimeToSleep;
    bool anyMovable = false;
    for (std::int32_t index : island.bodies) {
        Body& b = bodies[index];
        if (b.type == BodyType::Static) continue;
        anyMovable = true;
        if (!b.allowSleep || b.angularVelocity * b.angularVelocity > angularTolerance ||
            dot(b.linearVelocity, b.linearVelocity) > linearTolerance) {
            b.sleepTime = 0.0f;
            minSleepTime = 0.0f;
        } else {
            b.sleepTime += step.dt;
            minSleepTime = std::min(minSleepTime, b.sleepTime);
        }
    }
    if (!anyMovable || minSleepTime < kTimeToSleep || !positionSolved) return false;
    for (std::int32_t index : island.bodies) {
        Body& b = bodies[index];
        if (b.type != BodyType::Static) putToSleep(b);
    }
    return true;
}

void writeBack(const Island& island, SlotPool<Body>& bodies) {
    for (std::size_t i = 0; i < island.bodies.size(); ++i) {
        Body& b = bodies[island.bodies[i]];
        if (b.type == BodyType::Static) continue;
        b.center = island.positions[i].c;
        b.angle = island.positions[i].a;
        b.linearVelocity = island.velocities[i].v;
        b.angularVelocity = island.velocities[i].w;
        synchronizeTransform(b);
    }
}

}  // namespace

IslandReport solveIsland(Island& island, SolverStorage& storage, const StepContext& step) {
    IslandReport report;
    SlotPool<Body>& bodies = storage.bodies;
    integrateVelocities(island, bodies, step);
    // Contacts are prepared and warm-started before joints, and solved after them in each
    // velocity sweep, as in Box2D 2.4.1 (see docs/position-correction.md).
    island.contactSolver.prepare(island.contacts, storage.contacts, bodies, storage.shapes, step,
                                 island.positions.data(), island.velocities.data());
    prepareJoints(island, bodies, storage.joints, step);
    prepareMouseJoints(island, bodies, storage.mouseJoints, step);
    for (int it = 0; it < step.velocityIterations; ++it) {
        // A mouse joint is the user's hand: solved first, so the rigid joints and contacts have
        // the last word on what the drag may do to them.
        for (MouseConstraint& c : island.mouseConstraints) {
            solveMouseVelocity(c, island.velocities.data());
        }
        solveVelocitySweep(island.groups, island.velocities.data());
        island.contactSolver.solveVelocities(island.velocities.data());
    }
    storeImpulses(island, storage.joints, step.invDt);
    island.contactSolver.storeImpulses(storage.contacts);
    for (const MouseConstraint& c : island.mouseConstraints) {
        storage.mouseJoints[c.jointIndex].impulse = c.impulse;
    }
    integratePositions(island, step, report);
    island.pseudoVelocities.resize(island.bodies.size());
    PositionPhaseResult phase =
        solvePositionPhase(island.groups, island.contactSolver, island.positions.data(),
                           island.pseudoVelocities, step.positionIterations, step.dt);
    report.positionIterations = phase.sweeps;
    writeBack(island, bodies);
    report.fellAsleep = updateSleep(island, bodies, step, phase.solved);
    return report;
}

}  // namespace pivot
