// The joint types the solver knows, as one list. The strategies' phases, the island schedule and
// the island solver loop over it, so a new joint type is added here (with its storage and its
// constraint) and in no strategy code.
//
// An island's joints are solved in groups, one per strategy and joint type: strategy by
// strategy in PositionSolver order (docs/position-correction.md gives the reasons for that
// order), type by type in this list's order within a strategy, and in the island's order
// within a group.
#pragma once

#include <type_traits>
#include <variant>

#include "joints/distance_constraint.h"
#include "joints/joint.h"
#include "joints/pulley_constraint.h"
#include "joints/revolute_constraint.h"
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

using JointConstraintTypes =
    JointTypeList<RevoluteConstraint, DistanceConstraint, PulleyConstraint>;

constexpr int kJointTypeCount = JointConstraintTypes::kCount;
constexpr int kJointGroupCount = kPositionSolverCount * kJointTypeCount;

/// The group of a joint of type `typeIndex` that chose `solver`.
constexpr int jointGroup(int solver, int typeIndex) {
    return solver * kJointTypeCount + typeIndex;
}

/// A stored joint's group.
inline int jointGroup(const Joint& joint) {
    return jointGroup(static_cast<int>(joint.solver), joint.typeIndex());
}

// Each joint type's constraint names its storage (Constraint::Storage), in the same order as
// the alternatives of JointData, so that a stored joint's type index is its constraint's.
template <typename List, typename Data>
struct StorageOrderMatches;
template <typename... Constraints, typename... Storages>
struct StorageOrderMatches<JointTypeList<Constraints...>, std::variant<Storages...>> {
    static constexpr bool value = sizeof...(Constraints) == sizeof...(Storages) &&
                                  (std::is_same_v<typename Constraints::Storage, Storages> && ...);
};
static_assert(StorageOrderMatches<JointConstraintTypes, JointData>::value,
              "JointData and JointConstraintTypes list the joint types in the same order");
static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<int>(JointType::Distance), JointData>,
                   DistanceJoint>,
    "JointData lists the joint types in the order of the public JointType");

}  // namespace pivot
