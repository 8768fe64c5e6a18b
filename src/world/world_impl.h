// World's private state. The public facade is split by concept: world.cpp (lifetime, step,
// settings), world_bodies.cpp, world_shapes.cpp, world_joints.cpp, world_contacts.cpp; the
// contact bookkeeping is in contact_manager.cpp and the step pipeline in step.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "collision/broad_phase.h"
#include "core/buffer.h"
#include "core/pair_map.h"
#include "core/slot_pool.h"
#include "core/task_pool.h"
#include "core/validation.h"
#include "islands/island_builder.h"
#include "joints/mouse_joint.h"
#include "joints/revolute_joint.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/shape.h"
#include "pivot/world.h"
#include "solver/island_solver.h"

namespace pivot {

struct World::Impl {
    explicit Impl(const WorldDef& def);

    std::uint32_t id;  // stamped into every handle this world issues
    Vec2 gravity;
    PositionSolver defaultPositionSolver;
    bool warmStarting;
    ContactCorrection contactCorrection;
    float contactBiasFactor;
    float restitutionThreshold;
    bool enableSleep;
    float jointLetGoSeparation;  // m; 0: never

    SlotPool<Body> bodies;
    SlotPool<Shape> shapes;
    SlotPool<RevoluteJoint> joints;
    SlotPool<Contact> contacts;
    SlotPool<MouseJoint> mouseJoints;
    BroadPhase broadPhase;
    PairMap contactPairs;  // shape pair -> contact index
    // How many shapes carry each category bit: a moved shape whose mask admits none of the
    // categories present (and no group can override) has nothing to meet, and is not queried.
    std::array<std::int32_t, 16> categoryCounts{};
    void countCategories(const Filter& filter, int delta);
    std::uint16_t presentCategories() const;
    bool newShapes = false;  // pairs to find before the next step's contact update

    std::vector<ContactEvent> beginEvents;
    std::vector<ContactEvent> endEvents;
    std::vector<JointLetGoEvent> letGoEvents;  // joints let go by the last step
    std::vector<WorldEdgeEvent> edgeEvents;    // bodies held at the world's edge by it
    std::vector<BodyId> discarded;             // bodies whose solved state it discarded

    float previousInvDt = 0.0f;  // 1/dt of the last step; 0 before the first
    StepStats stats;
    TaskPool pool;
    IslandBuilder islandBuilder;
    IslandSet islands;
    std::vector<IslandWorkspace> workspaces;    // one per worker
    std::vector<IslandReport> reports;          // one per island of the current step
    std::vector<int> smallIslands;              // islands solved whole by one worker
    std::vector<std::uint8_t> contactOutcomes;  // updateContacts' first phase, per contact slot
    BufferBounds reservedFor;                   // the pool capacities the island set was sized for
    BufferBounds reservedWorkspaceFor;          // the island totals the workspaces were sized for
    /// Sizes the island set for the world's pool capacities (see buffer.h), when they grew.
    void reserveStepBuffers();
    /// Sizes the workspaces for this step's island totals, when they passed the last record.
    void reserveWorkspaces();

    void step(float dt, int velocityIterations, int positionIterations);
    void recordLetGoJoints(const IslandSet::Range& island);
    void recordBodyEvents(const IslandSet::Range& island);

    // Handle checks: the slot index of a live object this world issued, or pivot::Error.
    std::int32_t bodyIndex(const char* call, BodyId id) const;
    std::int32_t shapeIndex(const char* call, ShapeId id) const;
    std::int32_t jointIndex(const char* call, JointId id) const;
    std::int32_t mouseJointIndex(const char* call, MouseJointId id) const;

    BodyId bodyId(std::int32_t index) const { return {index, bodies.generation(index), id}; }
    ShapeId shapeId(std::int32_t index) const { return {index, shapes.generation(index), id}; }
    JointId jointId(std::int32_t index) const { return {index, joints.generation(index), id}; }
    MouseJointId mouseJointId(std::int32_t index) const {
        return {index, mouseJoints.generation(index), id};
    }

    void removeJoint(std::int32_t jointIndex);
    void removeShape(std::int32_t shapeIndex);
    void removeMouseJoint(std::int32_t mouseIndex);
    void wakeAll();

    // Contact bookkeeping (contact_manager.cpp).
    /// A broad-phase pair: makes a contact unless one exists or the pair may not collide.
    void addPair(std::int32_t shapeA, std::int32_t shapeB);
    void destroyContact(std::int32_t contactIndex);
    /// Re-filters flagged contacts, drops those whose boxes parted, and recomputes the
    /// manifolds of contacts with an awake body.
    void updateContacts();
    void findNewContacts();
    /// Moves a body's broad-phase boxes to its current transform, covering the whole motion
    /// since the last sync when `swept` (a step), or not (a teleport).
    void synchronizeShapes(std::int32_t bodyIndex, bool swept);
    /// synchronizeShapes for every body solved this step, with the boxes computed and the
    /// containment tests made on every worker; only the re-insertions are made in turn.
    void synchronizeSolvedBodies();
    struct ShapeMove {
        AABB swept;
        Vec2 displacement;
        bool needed = false;
    };
    std::vector<ShapeMove> shapeMoves;  // per shape slot, for synchronizeSolvedBodies
    /// Whether two bodies may collide at all: one must be dynamic, and no joint between them
    /// may forbid it.
    bool bodiesMayCollide(std::int32_t bodyA, std::int32_t bodyB) const;
    /// Flags the contacts between two bodies for re-filtering and makes the broad phase report
    /// their shapes again (after a joint between them appeared or went).
    void refilterBodyPair(std::int32_t bodyA, std::int32_t bodyB);
    /// Flags every contact of a body for re-filtering, wakes the bodies it touches or is jointed
    /// to, and makes the broad phase report its shapes again (after its type changed).
    void refilterBody(std::int32_t body);
};

/// Checks a handle against a pool; returns the slot index or throws pivot::Error.
template <typename Tag, typename T>
std::int32_t checkHandle(const char* call, const char* what, detail::Handle<Tag> id,
                         const SlotPool<T>& pool, std::uint32_t worldId) {
    // The common case first: the messages are built only when a check fails, because every
    // query goes through here.
    if (!id.isNull() && id.world == worldId && pool.isAlive(id.index) &&
        pool.generation(id.index) == id.generation) {
        return id.index;
    }
    const std::string name(what);
    if (id.isNull()) fail(call, name + " id is null (default-constructed)");
    if (id.world != worldId) {
        fail(call, name + " id was issued by another world (world " + std::to_string(id.world) +
                       ", this is world " + std::to_string(worldId) + ")");
    }
    if (id.index < 0 || id.index >= pool.capacity()) {
        fail(call, name + " id has index " + std::to_string(id.index) +
                       ", which this world never issued");
    }
    if (!pool.isAlive(id.index)) {
        fail(call, name + " id is stale: " + name + " " + std::to_string(id.index) +
                       " (generation " + std::to_string(id.generation) + ") was destroyed");
    }
    fail(call, name + " id is stale: " + name + " " + std::to_string(id.index) + " (generation " +
                   std::to_string(id.generation) +
                   ") was destroyed; the slot now holds generation " +
                   std::to_string(pool.generation(id.index)));
}

}  // namespace pivot
