#include "strategies/velocity_phase.h"

namespace pivot {

void prepareVelocityBias(const Team& team, JointGroups& groups, const SolverPose* poses,
                         float invDt) {
    groups.forEachGroup([&](auto strategy, auto& group, int) {
        using S = decltype(strategy);
        const IndexRange mine = team.share(static_cast<int>(group.size()));
        for (int k = mine.begin; k < mine.end; ++k) S::prepareBias(group[k], poses, invDt);
    });
}

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
        using S = decltype(strategy);
        forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) S::solveVelocity(group[k], velocities);
        });
    });
}

}  // namespace pivot
