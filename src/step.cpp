// World::step: the stages of one time step.
//   1. find pairs for shapes added since the last step;
//   2. update contacts (narrow phase): drop parted pairs, recompute manifolds;
//   3. build and solve islands (solver/island_solver.cpp), sleeping those at rest;
//   4. move the broad-phase boxes of the bodies that moved and find new pairs;
//   5. clear forces, count, remember dt for the next warm start.
#include "world_impl.h"

namespace pivot {

void World::Impl::step(float dt, int velocityIterations, int positionIterations) {
    StepContext context;
    context.dt = dt;
    context.invDt = 1.0f / dt;
    context.dtRatio = previousInvDt * dt;
    context.gravity = gravity;
    context.velocityIterations = velocityIterations;
    context.positionIterations = positionIterations;
    context.warmStarting = warmStarting;
    context.enableSleep = enableSleep;
    context.contactCorrection = contactCorrection;
    context.contactBiasFactor = contactBiasFactor;
    context.restitutionThreshold = restitutionThreshold;

    beginEvents.clear();
    endEvents.clear();
    if (newShapes) {
        findNewContacts();
        newShapes = false;
    }
    updateContacts();

    stats = StepStats{};
    solvedBodies.clear();
    SolverStorage storage{bodies, shapes, joints, contacts, mouseJoints};
    islandBuilder.forEachIsland(storage, island, [&](Island& current) {
        IslandReport report = solveIsland(current, storage, context);
        ++stats.islandCount;
        stats.bodyCount += static_cast<int>(current.bodies.size());
        stats.jointCount += static_cast<int>(current.joints.size());
        stats.translationClamps += report.translationClamps;
        stats.rotationClamps += report.rotationClamps;
        if (report.positionIterations > stats.positionIterations) {
            stats.positionIterations = report.positionIterations;
        }
        for (std::int32_t b : current.bodies) {
            if (bodies[b].type != BodyType::Static) solvedBodies.push_back(b);
        }
    });

    for (std::int32_t b : solvedBodies) synchronizeShapes(b);
    findNewContacts();

    // Forces apply for one step.
    bodies.forEach([this](std::int32_t, Body& b) {
        b.force = Vec2{};
        b.torque = 0.0f;
        if (b.type != BodyType::Static && !b.awake) ++stats.sleepingBodyCount;
    });
    contacts.forEach([this](std::int32_t, const Contact& c) {
        ++stats.contactCount;
        if (c.touching) ++stats.touchingCount;
    });
    previousInvDt = context.invDt;
}

}  // namespace pivot
