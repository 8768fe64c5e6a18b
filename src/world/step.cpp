// World::step: the stages of one time step.
//   1. find pairs for shapes added since the last step;
//   2. update contacts (narrow phase): drop parted pairs, recompute manifolds;
//   3. build and solve islands (solver/island_solver.cpp), sleeping those at rest;
//   4. move the broad-phase boxes of the bodies that moved and find new pairs;
//   5. clear forces, count, remember dt for the next warm start.
#include <algorithm>

#include "constraints/step_context.h"
#include "core/buffer.h"
#include "world/world_impl.h"

namespace pivot {

namespace {
// Below this many island bodies in a step, the islands are solved on the calling thread.
constexpr std::size_t kParallelBodies = 512;

// A count that grew past the last reservation is reserved for rounded up to a power of two,
// so a count that grows one at a time reserves again only when it has doubled.
std::size_t withRoom(std::size_t reserved, std::size_t needed) {
    if (needed <= reserved) return reserved;
    std::size_t rounded = 16;
    while (rounded < needed) rounded *= 2;
    return rounded;
}
BufferBounds withRoom(const BufferBounds& reserved, const BufferBounds& needed) {
    return {withRoom(reserved.bodies, needed.bodies), withRoom(reserved.joints, needed.joints),
            withRoom(reserved.contacts, needed.contacts),
            withRoom(reserved.mouseJoints, needed.mouseJoints)};
}
}  // namespace

void World::Impl::reserveStepBuffers() {
    const auto count = [](std::int32_t n) { return static_cast<std::size_t>(n); };
    const BufferBounds bound =
        withRoom(reservedFor, {count(bodies.capacity()), count(joints.capacity()),
                               count(contacts.capacity()), count(mouseJoints.capacity())});
    if (bound == reservedFor) return;
    reservedFor = bound;
    islands.reserve(bound);
    islandBuilder.reserve(bound);
    reports.reserve(bound.bodies);
    smallIslands.reserve(bound.bodies);
}

// The solver's arrays hold one island at a time, and no island holds more than all of this
// step's islands together: a workspace reserved for those totals never grows while it solves,
// whatever the islands merge and split into. The totals themselves (awake bodies, touching
// contacts) reach a record now and then, and the reservation then at least doubles.
void World::Impl::reserveWorkspaces() {
    BufferBounds& reserved = reservedWorkspaceFor;
    const BufferBounds bound =
        withRoom(reserved, {islands.bodies.size(), islands.joints.size(), islands.contacts.size(),
                            islands.mouseJoints.size()});
    if (bound == reserved) return;
    reserved = bound;
    // The first workspace may solve any island. With several workers the others solve only
    // islands too small to be coloured: fewer than kColoringThreshold joints and contacts, and
    // (being connected) at most one more body than that besides the static bodies they touch.
    reserveWorkspace(workspaces[0], reserved);
    const std::size_t small = kColoringThreshold;
    const BufferBounds smallIsland{std::min(reserved.bodies, 2 * small),
                                   std::min(reserved.joints, small),
                                   std::min(reserved.contacts, small), reserved.mouseJoints};
    for (std::size_t w = 1; w < workspaces.size(); ++w) {
        reserveWorkspace(workspaces[w], smallIsland);
    }
}

// Every joint of this step's islands was solvable when the islands were built (the builder
// skips let-go joints), so the let-go ones among them were let go by this step: listed in
// island order, which is the same for any number of workers.
void World::Impl::recordLetGoJoints(const IslandSet::Range& island) {
    for (std::int32_t k = island.jointBegin; k < island.jointEnd; ++k) {
        const std::int32_t index = islands.joints[static_cast<std::size_t>(k)];
        const RevoluteJoint& joint = joints[index];
        if (joint.letGo) letGoEvents.push_back({jointId(index), joint.letGoReason, joint.letGoAt});
    }
}

// Bodies held at the world's edge, and bodies whose solved state was discarded, in island
// order: the same for any number of workers.
void World::Impl::recordBodyEvents(const IslandSet::Range& island) {
    for (std::int32_t k = island.bodyBegin; k < island.bodyEnd; ++k) {
        const std::int32_t index = islands.bodies[static_cast<std::size_t>(k)];
        Body& body = bodies[index];
        if (body.heldAtEdge) edgeEvents.push_back({bodyId(index), body.edgeReached});
        if (body.discarded) discarded.push_back(bodyId(index));
        body.heldAtEdge = body.discarded = false;
    }
}

void World::Impl::step(float dt, int velocityIterations, int positionIterations) {
    StepContext context;
    context.dt = dt;
    context.invDt = 1.0f / dt;
    context.dtRatio = std::min(previousInvDt * dt, 1.0f);
    context.gravity = gravity;
    context.velocityIterations = velocityIterations;
    context.positionIterations = positionIterations;
    context.warmStarting = warmStarting;
    context.enableSleep = enableSleep;
    context.contactCorrection = contactCorrection;
    context.contactBiasFactor = contactBiasFactor;
    context.restitutionThreshold = restitutionThreshold;
    context.jointLetGoSeparation = jointLetGoSeparation;

    beginEvents.clear();
    endEvents.clear();
    letGoEvents.clear();
    edgeEvents.clear();
    discarded.clear();
    if (newShapes) {
        findNewContacts();
        newShapes = false;
    }
    updateContacts();

    stats = StepStats{};
    reserveStepBuffers();
    SolverStorage storage{bodies, shapes, joints, contacts, mouseJoints};
    islandBuilder.build(storage, islands);
    reserveWorkspaces();
    const int islandCount = static_cast<int>(islands.ranges.size());
    resizeBuffer(reports, static_cast<std::size_t>(islandCount));
    // A coloured island is solved by every worker together, one island at a time; the others
    // are shared out among the workers whole. Sharing out costs a hand-off per step: worth it
    // only with enough bodies to solve.
    const bool teams = pool.workerCount() > 1;
    smallIslands.clear();
    for (int i = 0; i < islandCount; ++i) {
        if (!teams || !isColored(islands.view(i))) {
            smallIslands.push_back(i);
            continue;
        }
        IslandWorkspace& workspace = workspaces[0];
        planIsland(islands, i, workspace, storage, context, pool.workerCount());
        pool.region([&](int member) {
            IslandReport report =
                solveIsland(Team(pool, member), islands, i, workspace, storage, context);
            if (member == 0) reports[i] = report;
        });
    }
    const int smallCount = static_cast<int>(smallIslands.size());
    const int islandsPerChunk = islands.bodies.size() < kParallelBodies ? smallCount : 1;
    pool.parallelFor(smallCount, islandsPerChunk, [&](int begin, int end, int worker) {
        for (int k = begin; k < end; ++k) {
            const int i = smallIslands[k];
            reports[i] = solveIsland(islands, i, workspaces[worker], storage, context);
        }
    });
    for (int i = 0; i < islandCount; ++i) {
        const IslandReport& report = reports[i];
        const IslandSet::Range& r = islands.ranges[i];
        ++stats.islandCount;
        stats.bodyCount += r.bodyEnd - r.bodyBegin;
        stats.jointCount += r.jointEnd - r.jointBegin;
        stats.translationClamps += report.translationClamps;
        stats.rotationClamps += report.rotationClamps;
        stats.letGoJointCount += report.letGoJoints;
        if (report.letGoJoints > 0) recordLetGoJoints(r);
        stats.edgeBodyCount += report.edgeBodies;
        stats.discardedBodyCount += report.discardedBodies;
        if (report.edgeBodies > 0 || report.discardedBodies > 0) recordBodyEvents(r);
        if (report.positionIterations > stats.positionIterations) {
            stats.positionIterations = report.positionIterations;
        }
    }

    // Every non-static body solved this step moved: sweep its broad-phase boxes.
    synchronizeSolvedBodies();
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
