#include "strategies/velocity_phase.h"

namespace pivot {

namespace {
// One velocity iteration over one group. A function of its own, rather than a lambda nested in
// the loop over groups, gives the compiler the same tight loop for every group.
template <typename S, typename C>
void sweepGroup(const Team& team, const std::vector<Batch>& batches, C* constraints,
                SolverVelocity* velocities) {
    for (const Batch& batch : batches) {
        team.forBlocks(batch, [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) {
                S::solveVelocity(constraints[k], velocities);
            }
        });
        team.sync();
    }
}
}  // namespace

void warmStartJoints(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                     SolverVelocity* velocities) {
    groups.forEachGroup([&](auto, auto& group, int g) {
        forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) group[k].warmStart(velocities);
        });
    });
}

void solveVelocitySweep(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                        SolverVelocity* velocities) {
    groups.forEachGroup([&](auto strategy, auto& group, int g) {
        sweepGroup<decltype(strategy)>(team, schedule.jointBatches[g], group.data(), velocities);
    });
}

}  // namespace pivot
