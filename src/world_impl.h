// World's private state. world.cpp holds the public facade (checks, then changes); the step
// pipeline is in step.cpp.
#pragma once

#include <cstdint>

#include "body.h"
#include "joints/revolute_joint.h"
#include "pivot/world.h"
#include "shape.h"
#include "slot_pool.h"
#include "solver/island_builder.h"
#include "solver/island_solver.h"

namespace pivot {

struct World::Impl {
    explicit Impl(const WorldDef& def);

    std::uint32_t id;  // stamped into every handle this world issues
    Vec2 gravity;
    PositionSolver defaultPositionSolver;
    bool warmStarting;

    SlotPool<Body> bodies;
    SlotPool<Shape> shapes;
    SlotPool<RevoluteJoint> joints;

    float previousInvDt = 0.0f;  // 1/dt of the last step; 0 before the first
    StepStats stats;
    IslandBuilder islandBuilder;
    Island island;

    void step(float dt, int velocityIterations, int positionIterations);

    // Handle checks: the slot index of a live object this world issued, or pivot::Error.
    std::int32_t bodyIndex(const char* call, BodyId id) const;
    std::int32_t shapeIndex(const char* call, ShapeId id) const;
    std::int32_t jointIndex(const char* call, JointId id) const;

    BodyId bodyId(std::int32_t index) const { return {index, bodies.generation(index), id}; }
    ShapeId shapeId(std::int32_t index) const { return {index, shapes.generation(index), id}; }
    JointId jointId(std::int32_t index) const { return {index, joints.generation(index), id}; }

    void linkJoint(std::int32_t jointIndex);
    void unlinkJoint(std::int32_t jointIndex);
    void removeJoint(std::int32_t jointIndex);
    void removeShape(std::int32_t shapeIndex);
};

}  // namespace pivot
