#include "solver/island_solver.h"

#include <algorithm>
#include <cmath>

#include "pivot/constants.h"

namespace pivot {

void IslandSet::clear() {
    bodies.clear();
    contacts.clear();
    contactBodies.clear();
    joints.clear();
    jointBodies.clear();
    mouseJoints.clear();
    mouseBodies.clear();
    ranges.clear();
}

namespace {

// One island's slice of an IslandSet.
struct IslandView {
    const std::int32_t* bodies;
    int bodyCount;
    const std::int32_t* contacts;
    const BodyPair* contactBodies;
    int contactCount;
    const std::int32_t* joints;
    const BodyPair* jointBodies;
    int jointCount;
    const std::int32_t* mouseJoints;
    const std::int32_t* mouseBodies;
    int mouseCount;
};

IslandView viewOf(const IslandSet& set, int index) {
    const IslandSet::Range& r = set.ranges[index];
    return {set.bodies.data() + r.bodyBegin,
            r.bodyEnd - r.bodyBegin,
            set.contacts.data() + r.contactBegin,
            set.contactBodies.data() + r.contactBegin,
            r.contactEnd - r.contactBegin,
            set.joints.data() + r.jointBegin,
            set.jointBodies.data() + r.jointBegin,
            r.jointEnd - r.jointBegin,
            set.mouseJoints.data() + r.mouseBegin,
            set.mouseBodies.data() + r.mouseBegin,
            r.mouseEnd - r.mouseBegin};
}

// Copy body state into the solver arrays; apply gravity, forces and damping to dynamic bodies
// (semi-implicit Euler: velocities first, positions later from the new velocities).
void integrateVelocities(const IslandView& island, IslandWorkspace& work, SlotPool<Body>& bodies,
                         const StepContext& step) {
    const float h = step.dt;
    const std::size_t n = static_cast<std::size_t>(island.bodyCount);
    work.velocities.resize(n);
    work.positions.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Body& b = bodies[island.bodies[i]];
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
        work.positions[i] = {b.center, b.angle};
        work.velocities[i] = {v, w};
    }
}

// Build each joint's solver constraint in its strategy's group and apply the warm start.
void prepareJoints(const IslandView& island, IslandWorkspace& work, const SlotPool<Body>& bodies,
                   const SlotPool<RevoluteJoint>& joints, const StepContext& step) {
    for (RevoluteConstraints& group : work.groups) group.clear();

    for (int j = 0; j < island.jointCount; ++j) {
        const std::int32_t jointIndex = island.joints[j];
        const RevoluteJoint& joint = joints[jointIndex];
        const Body& a = bodies[joint.bodyA()];
        const Body& b = bodies[joint.bodyB()];
        RevoluteConstraint c;
        c.jointIndex = jointIndex;
        c.biasFactor = joint.biasFactor();
        c.bodies.indexA = island.jointBodies[j][0];
        c.bodies.indexB = island.jointBodies[j][1];
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
        preparePoint(c.bodies, c.point, work.positions.data());
        prepareAngle(c.bodies, angle, work.positions.data(), step.invDt);
        if (step.warmStarting) {
            // Impulses scale with the step: keep the force they stand for when dt changes.
            c.point.impulse = step.dtRatio * joint.impulse;
            angle.motorImpulse *= step.dtRatio;
            angle.lowerImpulse *= step.dtRatio;
            angle.upperImpulse *= step.dtRatio;
            warmStart(c, work.velocities.data());
        } else {
            angle.motorImpulse = 0.0f;
            angle.lowerImpulse = 0.0f;
            angle.upperImpulse = 0.0f;
        }
        work.groups[static_cast<int>(joint.solver)].push_back(c);
    }
    prepareVelocityBias(work.groups, work.positions.data(), step.invDt);
}

void storeImpulses(const IslandWorkspace& work, SlotPool<RevoluteJoint>& joints, float invDt) {
    for (const RevoluteConstraints& group : work.groups) {
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

void prepareMouseJoints(const IslandView& island, IslandWorkspace& work,
                        const SlotPool<Body>& bodies, const SlotPool<MouseJoint>& mouseJoints,
                        const StepContext& step) {
    work.mouseConstraints.clear();
    for (int k = 0; k < island.mouseCount; ++k) {
        const std::int32_t m = island.mouseJoints[k];
        const MouseJoint& joint = mouseJoints[m];
        const Body& body = bodies[joint.body];
        MouseConstraint c;
        c.index = island.mouseBodies[k];
        c.jointIndex = m;
        c.mB = body.invMass;
        c.iB = body.invInertia;
        prepareMouse(c, joint, body.mass, body.localCenter, work.positions.data(),
                     work.velocities.data(), step.dt, step.dtRatio, step.warmStarting);
        work.mouseConstraints.push_back(c);
    }
}

// Move every body by its velocity, limiting the move per step (kMaxTranslation,
// kMaxRotation). The limit scales the velocity itself so the next step starts from it.
void integratePositions(IslandWorkspace& work, const StepContext& step, IslandReport& report) {
    const float h = step.dt;
    for (std::size_t i = 0; i < work.velocities.size(); ++i) {
        SolverVelocity& vel = work.velocities[i];
        SolverPosition& pos = work.positions[i];
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
bool updateSleep(const IslandView& island, SlotPool<Body>& bodies, const StepContext& step,
                 bool positionSolved) {
    if (!step.enableSleep) return false;
    const float linearTolerance = kLinearSleepTolerance * kLinearSleepTolerance;
    const float angularTolerance = kAngularSleepTolerance * kAngularSleepTolerance;
    float minSleepTime = kTimeToSleep;
    bool anyMovable = false;
    for (int i = 0; i < island.bodyCount; ++i) {
        Body& b = bodies[island.bodies[i]];
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
    for (int i = 0; i < island.bodyCount; ++i) {
        Body& b = bodies[island.bodies[i]];
        if (b.type != BodyType::Static) putToSleep(b);
    }
    return true;
}

void writeBack(const IslandView& island, const IslandWorkspace& work, SlotPool<Body>& bodies) {
    for (int i = 0; i < island.bodyCount; ++i) {
        Body& b = bodies[island.bodies[i]];
        if (b.type == BodyType::Static) continue;
        b.center = work.positions[i].c;
        b.angle = work.positions[i].a;
        b.linearVelocity = work.velocities[i].v;
        b.angularVelocity = work.velocities[i].w;
        synchronizeTransform(b);
    }
}

}  // namespace

IslandReport solveIsland(const IslandSet& set, int index, IslandWorkspace& work,
                         SolverStorage& storage, const StepContext& step) {
    const IslandView island = viewOf(set, index);
    IslandReport report;
    SlotPool<Body>& bodies = storage.bodies;
    integrateVelocities(island, work, bodies, step);
    // Contacts are prepared and warm-started before joints, and solved after them in each
    // velocity sweep, as in Box2D 2.4.1 (see docs/position-correction.md).
    work.contactSolver.prepare(island.contacts, island.contactBodies, island.contactCount,
                               storage.contacts, bodies, storage.shapes, step,
                               work.positions.data(), work.velocities.data());
    prepareJoints(island, work, bodies, storage.joints, step);
    prepareMouseJoints(island, work, bodies, storage.mouseJoints, step);
    for (int it = 0; it < step.velocityIterations; ++it) {
        // A mouse joint is the user's hand: solved first, so the rigid joints and contacts have
        // the last word on what the drag may do to them.
        for (MouseConstraint& c : work.mouseConstraints)
            solveMouseVelocity(c, work.velocities.data());
        solveVelocitySweep(work.groups, work.velocities.data());
        work.contactSolver.solveVelocities(work.velocities.data());
    }
    storeImpulses(work, storage.joints, step.invDt);
    work.contactSolver.storeImpulses(storage.contacts);
    for (const MouseConstraint& c : work.mouseConstraints) {
        storage.mouseJoints[c.jointIndex].impulse = c.impulse;
    }
    integratePositions(work, step, report);
    work.pseudoVelocities.resize(work.velocities.size());
    PositionPhaseResult phase =
        solvePositionPhase(work.groups, work.contactSolver, work.positions.data(),
                           work.pseudoVelocities, step.positionIterations, step.dt);
    report.positionIterations = phase.sweeps;
    writeBack(island, work, bodies);
    report.fellAsleep = updateSleep(island, bodies, step, phase.solved);
    return report;
}

}  // namespace pivot
