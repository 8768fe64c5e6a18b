// World's private state: the settings, the object pools, who may call in (world_access.h), and
// the parts that work on them: the contact manager (broad phase, pairs, narrow phase, contact
// events), the stepper (islands and their solving, on the task pool) and continuous collision.
// The public facade is split by concept: world.cpp (lifetime, settings), world_bodies.cpp,
// world_shapes.cpp, world_joints.cpp, world_mouse.cpp, world_contacts.cpp; step.cpp runs the
// stages of a step; world_snapshot.cpp writes, reads and hashes the state.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/buffer.h"
#include "core/slot_pool.h"
#include "core/task_pool.h"
#include "core/validation.h"
#include "core/worker_count_chooser.h"
#include "joints/joint.h"
#include "joints/mouse_joint.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/island_revision.h"
#include "model/shape.h"
#include "pivot/world.h"
#include "solver/stepper.h"
#include "world/contact_manager.h"
#include "world/continuous_solver.h"
#include "world/fast_body_sweeps.h"
#include "world/world_access.h"
#include "world/world_settings.h"

namespace pivot {

struct World::Impl {
    explicit Impl(const WorldDef& def);

    // Stamped into every handle this world issues; a new one after restoring another world's
    // snapshot (World::restore), so that no handle from before names a restored object.
    std::uint32_t id;
    WorldSettings settings;  // one rule each (world_settings.h)

    // Who may call in while a step, a query's callback or debugDraw's drawing is under way:
    // every public call checks it first (world_access.h says the rule).
    WorldAccess access;
    /// Refuses a change during a step, or from debugDraw's drawing calls.
    void requireChange(const char* call) const {
        access.requireChange(call, WorldAccess::Change::State);
    }
    /// Refuses a change of structure (world_access.h) during a step, a query's callback or
    /// debugDraw's drawing calls.
    void requireStructureChange(const char* call) const {
        access.requireChange(call, WorldAccess::Change::Structure);
    }
    /// Refuses a read during a step, but from its pre-solve and custom-filter callbacks.
    void requireRead(const char* call) const { access.requireRead(call); }

    SlotPool<Body> bodies;
    SlotPool<Shape> shapes;
    SlotPool<Joint> joints;
    SlotPool<Contact> contacts;
    SlotPool<MouseJoint> mouseJoints;
    IslandRevision islandRevision;  // before the parts that count in it
    TaskPool pool;                  // before the parts that share it
    bool adaptWorkerCount;
    WorkerCountChooser workerChooser;
    ContactManager contactManager;
    Stepper stepper;
    ContinuousSolver continuous;
    FastBodySweeps fastBodies;  // ContinuousCollision::FastBodies' continuous collision

    std::vector<JointLetGoEvent> letGoEvents;  // joints let go by the last step
    std::vector<WorldEdgeEvent> edgeEvents;    // bodies held at the world's edge by it
    std::vector<BodyId> discarded;             // bodies whose solved state it discarded
    std::vector<ContactHitEvent> hitEvents;    // contacts of hit-event shapes hit in it
    std::vector<BodyMoveEvent> moveEvents;     // bodies it simulated
    std::vector<std::uint8_t> hitMarks;        // per contact slot: hit reported this step
    int hitEventShapeCount = 0;  // shapes with ShapeDef::enableHitEvents (none: no hit search)

    // 1/h of the last step's substeps (1/dt with one substep); 0 before the first step
    float previousInvDt = 0.0f;
    StepStats stats;

    void step(float dt, int velocityIterations, int positionIterations);
    void recordLetGoJoints(const IslandSet::Range& island);
    void recordBodyEvents(const IslandSet::Range& island);
    void recordHitAndMoveEvents();
    /// Reserves the event lists and marks a step fills, for the pools' present capacities.
    void reserveEventBuffers();

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

    /// A joint's slot index after checking that it is of `type`, or pivot::Error naming both
    /// types.
    std::int32_t jointIndexOfType(const char* call, JointId id, JointType type) const;
    /// As jointIndexOfType, for calls that two types answer.
    std::int32_t jointIndexOfTypes(const char* call, JointId id, JointType type,
                                   JointType other) const;
    /// A friction or motor joint's slot index, or pivot::Error.
    std::int32_t velocityJointIndex(const char* call, JointId id) const;
    template <typename T>
    T& jointData(const char* call, JointId id, JointType type) {
        return std::get<T>(joints[jointIndexOfType(call, id, type)].data);
    }

    /// Stores a checked joint, links it to its bodies and wakes them.
    JointId addJoint(const Joint& joint);
    void removeJoint(std::int32_t jointIndex);
    /// Removes the gear joints built on the joint (waking their bodies), then the joint.
    void removeJointAndItsGears(std::int32_t jointIndex);
    void removeShape(std::int32_t shapeIndex);
    void removeMouseJoint(std::int32_t mouseIndex);
    void wakeAll();
    /// Wakes a joint's two bodies (a joint changed by the API acts at once).
    void wakeJointBodies(const Joint& joint) {
        wakeUp(bodies[joint.bodyA()], islandRevision);
        wakeUp(bodies[joint.bodyB()], islandRevision);
    }

    /// The one path of a joint setter. Refusals come first, in this order, each before anything
    /// changes: a world that may not change now (requireChange), a joint `find` refuses (its
    /// slot index, or pivot::Error for a dead, foreign or other-typed id), a value `check`
    /// refuses (given the joint). Then `apply` changes the joint, and its bodies wake: a joint
    /// changed by the API acts at once.
    template <typename Find, typename Check, typename Apply>
    void setJoint(const char* call, Find&& find, Check&& check, Apply&& apply) {
        requireChange(call);
        Joint& joint = joints[find()];
        check(joint);
        apply(joint);
        wakeJointBodies(joint);
    }
    /// setJoint for the data of one joint type: `check()` checks the value, `apply(data)` sets it.
    template <typename T, typename Check, typename Apply>
    void setJointData(const char* call, JointId id, JointType type, Check&& check, Apply&& apply) {
        setJoint(
            call, [&] { return jointIndexOfType(call, id, type); }, [&](const Joint&) { check(); },
            [&](Joint& joint) { apply(std::get<T>(joint.data)); });
    }
};

/// A world id never used before in this process (pivot::Error from `call` once they run out).
std::uint32_t newWorldId(const char* call);

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
        fail(call, name +
                       " id was issued by another world, or by this one before it restored "
                       "another world's snapshot (world " +
                       std::to_string(id.world) + ", this is world " + std::to_string(worldId) +
                       ")");
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
