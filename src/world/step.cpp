// World::step: the stages of one time step.
//   1. contacts (contact_manager.cpp): find pairs for shapes added since the last step, drop
//      parted pairs, recompute manifolds;
//   2. islands (solver/stepper.cpp): build and solve them, sleeping those at rest;
//   3. contacts again: move the broad-phase boxes of the bodies that moved, find new pairs;
//   4. continuous collision (world/continuous_solver.h): bodies that passed into or through
//      what they should have stopped at are taken back to the impact and stepped on;
//   5. events, statistics, forces cleared, dt remembered for the next warm start.
#include <algorithm>
#include <chrono>

#include "constraints/step_context.h"
#include "core/buffer.h"
#include "world/world_impl.h"

namespace pivot {

// Every joint of this step's islands was solvable when the islands were built (the builder
// skips let-go joints), so the let-go ones among them were let go by this step: listed in
// island order, which is the same for any number of workers.
void World::Impl::recordLetGoJoints(const IslandSet::Range& island) {
    const IslandSet& islands = stepper.islands();
    for (std::int32_t k = island.jointBegin; k < island.jointEnd; ++k) {
        const std::int32_t index = islands.joints[static_cast<std::size_t>(k)];
        const Joint& joint = joints[index];
        if (joint.letGo)
            letGoEvents.push_back(
                {jointId(index), joint.letGoReason, joint.letGoAt, joint.letGoReaction});
    }
}

// Bodies held at the world's edge, and bodies whose solved state was discarded, in island
// order: the same for any number of workers.
void World::Impl::recordBodyEvents(const IslandSet::Range& island) {
    const IslandSet& islands = stepper.islands();
    for (std::int32_t k = island.bodyBegin; k < island.bodyEnd; ++k) {
        const std::int32_t index = islands.bodies[static_cast<std::size_t>(k)];
        Body& body = bodies[index];
        if (body.heldAtEdge) edgeEvents.push_back({bodyId(index), body.edgeReached});
        if (body.discarded) discarded.push_back(bodyId(index));
        body.heldAtEdge = body.discarded = false;
    }
}

// A warm step does not allocate: room for every contact and body there is.
void World::Impl::reserveEventBuffers() {
    reserveBuffer(hitEvents, static_cast<std::size_t>(contacts.capacity()));
    reserveBuffer(moveEvents, static_cast<std::size_t>(bodies.capacity()));
    if (hitEventShapeCount > 0) {
        resizeBuffer(hitMarks, static_cast<std::size_t>(contacts.capacity()));
    }
}

// After the whole step (continuous collision moves bodies and re-collides contacts): every
// non-static body simulated, in island order; the hits of contacts of hit-event shapes (at most
// one a contact), in island order, then impact order.
void World::Impl::recordHitAndMoveEvents() {
    const IslandSet& islands = stepper.islands();
    reserveEventBuffers();
    for (std::int32_t index : islands.bodies) {
        const Body& body = bodies[index];
        if (body.type == BodyType::Static) continue;
        moveEvents.push_back({bodyId(index), body.xf, !body.awake});
    }
    if (hitEventShapeCount == 0) return;
    auto record = [this](std::int32_t index, int point, float speed) {
        const Contact& c = contacts[index];
        if (!c.touching || !c.enabled || hitMarks[static_cast<std::size_t>(index)]) return;
        if (!shapes[c.shapeA].hitEvents && !shapes[c.shapeB].hitEvents) return;
        hitMarks[static_cast<std::size_t>(index)] = 1;
        const ContactData data = contactManager.contactData(c);
        const int shown = std::min(point, data.pointCount - 1);
        hitEvents.push_back(
            {data.shapeA, data.shapeB, data.points[shown].point, data.normal, speed});
    };
    for (std::int32_t index : islands.contacts) {
        // The fastest point the solver pushed on (an approach it did not resist is no hit).
        const Manifold& m = contacts[index].manifold;
        int fastest = -1;
        float speed = settings.hitEventThreshold;
        for (int i = 0; i < m.pointCount; ++i) {
            if (m.points[i].approachSpeed > speed && m.points[i].normalImpulse > 0.0f) {
                speed = m.points[i].approachSpeed;
                fastest = i;
            }
        }
        if (fastest >= 0) record(index, fastest, speed);
    }
    if (settings.enableContinuous &&
        settings.continuousCollision == ContinuousCollision::Substeps) {
        // Impacts: the bodies met within the step; their contact may have touched before.
        for (const ContinuousSolver::Impact& impact : continuous.impacts()) {
            if (impact.approachSpeed > settings.hitEventThreshold) {
                record(impact.contact, impact.point, impact.approachSpeed);
            }
        }
    }
    if (!hitEvents.empty()) std::fill(hitMarks.begin(), hitMarks.end(), std::uint8_t{0});
}

void World::Impl::step(float dt, int velocityIterations, int positionIterations) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const bool adapt = adaptWorkerCount && pool.workerCount() > 1;
    if (adapt) pool.setActiveWorkers(workerChooser.next());
    StepContext context;
    // With one substep, h is dt itself (dt / 1 is exact): the pipeline of Box2D 2.4.1.
    const float h = dt / static_cast<float>(settings.substepCount);
    context.dt = h;
    context.invDt = 1.0f / h;
    context.dtRatio = std::min(previousInvDt * h, 1.0f);
    context.substepCount = settings.substepCount;
    context.stepDt = dt;
    context.gravity = settings.gravity;
    context.velocityIterations = velocityIterations;
    context.positionIterations = positionIterations;
    context.warmStarting = settings.warmStarting;
    context.enableSleep = settings.enableSleep;
    context.contactCorrection = settings.contactCorrection;
    context.contactBiasFactor = settings.contactBiasFactor;
    context.contactHertz = settings.contactHertz;
    context.contactDampingRatio = settings.contactDampingRatio;
    context.contactPushSpeed = settings.contactPushSpeed;
    context.restitutionThreshold = settings.restitutionThreshold;
    context.jointLetGoSeparation = settings.jointLetGoSeparation;

    letGoEvents.clear();
    edgeEvents.clear();
    discarded.clear();
    hitEvents.clear();
    moveEvents.clear();
    contactManager.update();

    SolverStorage storage{bodies,      shapes,        joints, contacts, contactManager.census(),
                          mouseJoints, islandRevision};
    const StepTotals totals = stepper.solve(storage, context);
    stats = StepStats{};
    stats.islandCount = totals.islands;
    stats.bodyCount = totals.bodies;
    stats.jointCount = totals.joints;
    stats.translationClamps = totals.translationClamps;
    stats.rotationClamps = totals.rotationClamps;
    stats.letGoJointCount = totals.letGoJoints;
    stats.edgeBodyCount = totals.edgeBodies;
    stats.discardedBodyCount = totals.discardedBodies;
    stats.positionIterations = totals.positionIterations;
    stats.extraPositionSolves = totals.extraPositionSolves;
    const IslandSet& islands = stepper.islands();
    for (std::size_t i = 0; i < islands.ranges.size(); ++i) {
        const IslandReport& report = stepper.report(static_cast<int>(i));
        if (report.letGoJoints > 0) recordLetGoJoints(islands.ranges[i]);
        if (report.edgeBodies > 0 || report.discardedBodies > 0) {
            recordBodyEvents(islands.ranges[i]);
        }
    }

    // Only Substeps pairs the sweeps of shapes that moved past their margin: FastBodies
    // searches the trees itself, for the few bodies that moved far.
    const bool substepped =
        settings.enableContinuous && settings.continuousCollision == ContinuousCollision::Substeps;
    contactManager.afterSolve(islands.bodies, substepped);
    // Continuous collision moves bodies after the solver held them within the world's edge,
    // and holds those it moves past it.
    auto recordHeldAtEdge = [this](const std::vector<std::int32_t>& held) {
        for (std::int32_t index : held) {
            Body& body = bodies[index];
            edgeEvents.push_back({bodyId(index), body.edgeReached});
            body.heldAtEdge = false;
            ++stats.edgeBodyCount;
        }
    };
    if (settings.enableContinuous && !substepped) {
        stats.impactCount = fastBodies.solve(islands.bodies, bodies, shapes, contactManager);
        recordHeldAtEdge(fastBodies.bodiesHeldAtEdge());
    } else if (substepped) {
        stats.impactCount =
            continuous.solve(bodies, shapes, contacts, contactManager, pool, context);
        recordHeldAtEdge(continuous.bodiesHeldAtEdge());
        for (std::int32_t index : continuous.discardedBodies()) {
            discarded.push_back(bodyId(index));
            ++stats.discardedBodyCount;
        }
    }

    recordHitAndMoveEvents();

    // Forces apply for one step.
    bodies.forEach([this](std::int32_t, Body& b) {
        b.force = Vec2{};
        b.torque = 0.0f;
        if (b.type != BodyType::Static && !b.awake) ++stats.sleepingBodyCount;
    });
    stats.contactCount = contacts.size();
    stats.touchingCount = contactManager.touchingCount();
    stats.workersUsed = pool.activeWorkers();
    previousInvDt = context.invDt;
    if (adapt) workerChooser.record(std::chrono::duration<double>(Clock::now() - start).count());
}

}  // namespace pivot
