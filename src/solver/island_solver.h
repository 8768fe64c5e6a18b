// Solving one island: a set of awake bodies connected by joints and touching contacts,
// independent of every other island for this step. The stages run in the order of
// docs/position-correction.md. Islands share nothing they write, so several can be solved at
// once, each in its own workspace.
#pragma once

#include <array>
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

/// The solver indices of a constraint's two bodies within its island.
using BodyPair = std::array<std::int32_t, 2>;

/// Every island of a step, island after island in flat arrays. Built by IslandBuilder; the
/// solver indices are recorded here rather than in the bodies, because a static body belongs
/// to every island that touches it, with a different index in each.
struct IslandSet {
    struct Range {
        std::int32_t bodyBegin, bodyEnd;
        std::int32_t contactBegin, contactEnd;
        std::int32_t jointBegin, jointEnd;
        std::int32_t mouseBegin, mouseEnd;
    };
    std::vector<std::int32_t> bodies;    // body pool indices; solver index = position - bodyBegin
    std::vector<std::int32_t> contacts;  // touching contacts, in the order they were reached
    std::vector<BodyPair> contactBodies;
    std::vector<std::int32_t> joints;  // revolute joints, in the order they were reached
    std::vector<BodyPair> jointBodies;
    std::vector<std::int32_t> mouseJoints;
    std::vector<std::int32_t> mouseBodies;  // solver index of each mouse joint's body
    std::vector<Range> ranges;

    void clear();
};

/// The solver's arrays for one island at a time. One per worker, reused for every island of
/// every step, so after the first steps solving allocates nothing.
struct IslandWorkspace {
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

/// Advances island `index` of `set` by one step, stores its joints' and contacts' impulses and
/// updates its bodies' sleep timers (putting it to sleep when it has rested long enough).
IslandReport solveIsland(const IslandSet& set, int index, IslandWorkspace& workspace,
                         SolverStorage& storage, const StepContext& step);

}  // namespace pivot
