// The joint types the solver knows, as one list. The strategies' phases, the island schedule and
// the island solver loop over it, so a new joint type is added here (with its storage and its
// constraint) and in no strategy code.
//
// An island's joints are solved in groups, one per strategy and joint type: strategy by
// strategy in PositionSolver order (docs/position-correction.md gives the reasons for that
// order), type by type in this list's order within a strategy, and in the island's order
// within a group.
#pragma once

#include "joints/revolute_constraint.h"
#include "joints/revolute_joint.h"
#include "pivot/solvers.h"

namespace pivot {

template <typename T>
struct TypeTag {
    using type = T;
};

template <typename... Constraints>
struct JointTypeList {
    static constexpr int kCount = sizeof...(Constraints);
    /// Calls f(TypeTag<Constraint>{}, typeIndex) for each type in order.
    template <typename F>
    static void forEach(F&& f) {
        int index = 0;
        (f(TypeTag<Constraints>{}, index++), ...);
    }
};

using JointConstraintTypes = JointTypeList<RevoluteConstraint>;

constexpr int kJointTypeCount = JointConstraintTypes::kCount;
constexpr int kJointGroupCount = kPositionSolverCount * kJointTypeCount;

/// The group of a joint of type `typeIndex` that chose `solver`.
constexpr int jointGroup(int solver, int typeIndex) {
    return solver * kJointTypeCount + typeIndex;
}

/// A stored joint's group.
inline int jointGroup(const RevoluteJoint& joint) {
    return jointGroup(static_cast<int>(joint.solver), 0);
}

}  // namespace pivot
