// Solving one island: a set of awake bodies connected by joints and touching contacts,
// independent of every other island for this step. The stages run in the order of
// docs/position-correction.md.
#pragma once

#include <cstdint>
#include <vector>

#include "body.h"
#include "contact.h"
#include "joints/mouse_joint.h"
#include "joints/revolute_joint.h"
#include "shape.h"
#include "slot_pool.h"
#include "solver/contact_solver.h"
#include "solver/position_solver.h"
#include "solver/solver_types.h"

namespace pivot {

/// The object pools the solver reads and writes.
struct SolverStorage {
    SlotPool<Body>& bodies;
    const SlotPool<Shape>& shapes;
    SlotPool<RevoluteJoint>& joints;
    SlotPool<Contact>& contacts;
    SlotPool<MouseJoint>& mouseJoints;
};

/// One island's members and the solver's arrays for it. Kept by the world and reused for
/// every island of every step, so after the first steps solving allocates nothing.
struct Island {
    std::vector<std::int32_t> bodies;    // body pool indices; the position is the solver index
    std::vector<std::int32_t> contacts;  // touching contacts, in the order they were reached
    std::vector<std::int32_t> joints;    // joint pool indices, in the order they were reached
    std::vector<std::int32_t> mouseJoints;
    std::vector<SolverVelocity> velocities;
    std::vector<SolverPosition> positions;
    std::vector<SolverVelocity> pseudoVelocities;
    ConstraintGroups groups;
    std::vector<MouseConstraint> mouseConstraints;
    ContactSolver contactSolver;
};

struct IslandReport {
    int translationClamps = 0;
    int rotationClamps = 0;
    int positionIterations = 0;
    bool fellAsleep = false;
};

/// Advances the island's bodies by one step, stores the joints' and contacts' impulses and
/// updates the bodies' sleep timers (putting the island to sleep when it has rested long
/// enough). Each body's islandIndex must hold its position in island.bodies.
IslandReport solveIsland(Island& island, SolverStorage& storage, const StepContext& step);

}  // namespace pivot
