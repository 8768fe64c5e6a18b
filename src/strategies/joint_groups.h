// One island's joint constraints for one step, in one array per strategy and joint type
// (joints/joint_types.h gives the order). Each stage of a phase is then a plain loop over an
// array: no joint pays for a virtual call, or a branch on its strategy or type, inside an
// iteration loop.
#pragma once

#include <array>
#include <tuple>
#include <vector>

#include "core/buffer.h"
#include "joints/joint_types.h"
#include "strategies/position_strategies.h"

namespace pivot {

template <typename List>
struct JointArrays;
template <typename... Constraints>
struct JointArrays<JointTypeList<Constraints...>> {
    using type = std::tuple<std::array<std::vector<Constraints>, kPositionSolverCount>...>;
};

class JointGroups {
public:
    template <typename C>
    std::vector<C>& of(PositionSolver solver) {
        return std::get<std::array<std::vector<C>, kPositionSolverCount>>(
            arrays_)[static_cast<int>(solver)];
    }

    /// Calls f(array, group) for each joint type's array of strategy S, in type order.
    template <typename S, typename F>
    void forEachType(F&& f) {
        JointConstraintTypes::forEach([&](auto tag, int type) {
            using C = typename decltype(tag)::type;
            f(of<C>(S::kSolver), jointGroup(static_cast<int>(S::kSolver), type));
        });
    }

    /// Calls f(strategy, array, group) for every group that has joints this step, in solving
    /// order. (Most islands use one or two of the groups: skipping the rest keeps an island's
    /// fixed cost from growing with the number of strategies and joint types.)
    template <typename F>
    void forEachGroup(F&& f) {
        if (jointCount_ == 0) return;  // most islands of a contact scene: no group to look at
        PositionStrategies::forEach([&](auto strategy) {
            using S = decltype(strategy);
            forEachType<S>([&](auto& array, int group) {
                if (!array.empty()) f(strategy, array, group);
            });
        });
    }

    /// forEachGroup over every group, empty ones included (to size them).
    template <typename F>
    void forEachGroupIncludingEmpty(F&& f) {
        PositionStrategies::forEach([&](auto strategy) {
            using S = decltype(strategy);
            forEachType<S>([&](auto& array, int group) { f(strategy, array, group); });
        });
    }

    /// Sizes each array for its group, [groupStart[g], groupStart[g + 1]) of the schedule.
    void resize(const std::array<std::int32_t, kJointGroupCount + 1>& groupStart) {
        const std::int32_t jointCount = groupStart[kJointGroupCount];
        if (jointCount == 0 && jointCount_ == 0) return;  // every array empty already
        jointCount_ = jointCount;
        forEachGroupIncludingEmpty([&](auto, auto& array, int g) {
            resizeBuffer(array, static_cast<std::size_t>(groupStart[g + 1] - groupStart[g]));
        });
    }

private:
    JointArrays<JointConstraintTypes>::type arrays_;
    std::int32_t jointCount_ = 0;  // over every array, as last sized by resize
};

}  // namespace pivot
