// The joints' part of the velocity phase, for every strategy and joint type: the bias set-up,
// the warm start and the velocity iterations.
//
// Every stage takes the Team solving the island and the island's schedule: a member solves its
// share of each batch and the team syncs after each batch (a team of one just runs the loops).
#pragma once

#include "constraints/solver_body.h"
#include "islands/island_schedule.h"
#include "islands/team.h"
#include "strategies/joint_groups.h"

namespace pivot {

/// Applies every joint's warm-start impulse, group by group.
void warmStartJoints(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                     SolverVelocity* velocities);

/// One velocity iteration over every group, accumulating impulses.
void solveVelocitySweep(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                        SolverVelocity* velocities);

}  // namespace pivot
