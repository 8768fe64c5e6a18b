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
#include "joints/gear_constraint.h"
#include "joints/joint.h"
#include "joints/prismatic_constraint.h"
#include "joints/pulley_constraint.h"
#include "joints/revolute_constraint.h"
#include "joints/velocity_constraints.h"
#include "joints/weld_constraint.h"
#include "joints/wheel_constraint.h"
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

using JointConstraintTypes = JointTypeList<RevoluteConstraint, DistanceConstraint, PulleyConstraint,
                                           FrictionConstraint, MotorConstraint, PrismaticConstraint,
                                           WeldConstraint, WheelConstraint, GearConstraint>;

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
// the alternatives of JointData, so that a stored joint's type index is its constraint's; and
// JointData follows the public JointType.
template <typename List>
struct StoragesOf;
template <typename... Constraints>
struct StoragesOf<JointTypeList<Constraints...>> {
    using type = std::variant<typename Constraints::Storage...>;
};
static_assert(std::is_same_v<StoragesOf<JointConstraintTypes>::type, JointData>,
              "JointData and JointConstraintTypes list the joint types in the same order");

template <JointType type, typename Storage>
constexpr bool storedAt() {
    return std::is_same_v<std::variant_alternative_t<static_cast<int>(type), JointData>, Storage>;
}
static_assert(storedAt<JointType::Revolute, RevoluteJoint>() &&
                  storedAt<JointType::Distance, DistanceJoint>() &&
                  storedAt<JointType::Pulley, PulleyJoint>() &&
                  storedAt<JointType::Friction, FrictionJoint>() &&
                  storedAt<JointType::Motor, MotorJoint>() &&
                  storedAt<JointType::Prismatic, PrismaticJoint>() &&
                  storedAt<JointType::Weld, WeldJoint>() &&
                  storedAt<JointType::Wheel, WheelJoint>() &&
                  storedAt<JointType::Gear, GearJoint>(),
              "JointData lists the joint types in the order of the public JointType");

}  // namespace pivot
