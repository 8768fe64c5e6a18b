// World::step: the stages of one time step.
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

    stats = StepStats{};
    islandBuilder.forEachIsland(bodies, joints, island, [&](Island& current) {
        IslandReport report = solveIsland(current, bodies, joints, context);
        ++stats.islandCount;
        stats.bodyCount += static_cast<int>(current.bodies.size());
        stats.jointCount += static_cast<int>(current.joints.size());
        stats.translationClamps += report.translationClamps;
        stats.rotationClamps += report.rotationClamps;
        if (report.positionIterations > stats.positionIterations) {
            stats.positionIterations = report.positionIterations;
        }
    });

    // Forces apply for one step.
    bodies.forEach([](std::int32_t, Body& b) {
        b.force = Vec2{};
        b.torque = 0.0f;
    });
    previousInvDt = context.invDt;
}

}  // namespace pivot
