#include "strategies/position_phase.h"

#include <algorithm>

namespace pivot {

namespace {

void solvePseudoVelocityPass(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                             SolverPose* poses, std::vector<SolverVelocity>& pseudo, int iterations,
                             float h) {
    bool any = false;
    groups.forEachGroup([&](auto strategy, auto& group, int) {
        any = any || (decltype(strategy)::kPseudoVelocityPass && !group.empty());
    });
    if (!any) return;
    const int slotCount = static_cast<int>(pseudo.size());
    team.forBlocks(slotCount, [&](IndexRange slots) {
        std::fill(pseudo.begin() + slots.begin, pseudo.begin() + slots.end, SolverVelocity{});
    });

    const float invH = 1.0f / h;
    groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        if constexpr (S::kPseudoVelocityPass) {
            team.forBatchShares(schedule.jointBatches[g], [&](IndexRange mine) {
                for (int k = mine.begin; k < mine.end; ++k) S::beginPass(group[k], poses, invH);
            });
        }
    });
    team.sync();
    for (int it = 0; it < iterations; ++it) {
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kPseudoVelocityPass) {
                forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
                    for (int k = range.begin; k < range.end; ++k) {
                        S::solvePass(group[k], pseudo.data());
                    }
                });
            }
        });
    }
    // Bodies no pass joint touches have zero pseudo velocity: adding it is a no-op.
    team.forBlocks(slotCount, [&](IndexRange slots) {
        for (int i = slots.begin; i < slots.end; ++i) {
            poses[i].c += h * pseudo[i].v;
            poses[i].a += h * pseudo[i].w;
        }
    });
    team.sync();
}

void solveRelaxSweeps(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                      ContactSolver& contacts, SolverVelocity* velocities, int iterations) {
    bool any = contacts.relaxes();
    groups.forEachGroup([&](auto strategy, auto& group, int) {
        any = any || (decltype(strategy)::kRelax && !group.empty());
    });
    if (!any) return;
    for (int it = 0; it < iterations; ++it) {
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kRelax) {
                forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
                    for (int k = range.begin; k < range.end; ++k) S::relax(group[k], velocities);
                });
            }
        });
        if (contacts.relaxes()) {
            forEachBatchSaying(team, schedule.contactBatches,
                               [&](IndexRange range, bool independent) {
                                   contacts.relax(range, velocities, independent);
                               });
        }
    }
}

void solveXpbdSweeps(const Team& team, JointGroups& groups, const IslandSchedule& schedule,
                     SolverPose* poses, SolverVelocity* velocities, std::vector<SolverPose>& start,
                     int iterations, float h) {
    bool any = false;
    groups.forEachGroup([&](auto strategy, auto& group, int) {
        any = any || (decltype(strategy)::kXpbdSweeps && !group.empty());
    });
    if (!any || iterations == 0) return;
    const int slotCount = static_cast<int>(start.size());
    team.forBlocks(slotCount, [&](IndexRange slots) {
        std::copy(poses + slots.begin, poses + slots.end, start.begin() + slots.begin);
    });
    team.sync();
    for (int it = 0; it < iterations; ++it) {
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kXpbdSweeps) {
                forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
                    for (int k = range.begin; k < range.end; ++k) {
                        S::solveCompliant(group[k], poses);
                    }
                });
            }
        });
    }
    const float invH = 1.0f / h;
    groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        if constexpr (S::kXpbdSweeps) {
            team.forBatchShares(schedule.jointBatches[g], [&](IndexRange mine) {
                for (int k = mine.begin; k < mine.end; ++k) group[k].takeXpbdReactions(invH);
            });
        }
    });
    // The moves become motion (position-based dynamics derives velocities from positions).
    // Bodies no XPBD joint moved get zero.
    team.forBlocks(slotCount, [&](IndexRange slots) {
        for (int i = slots.begin; i < slots.end; ++i) {
            velocities[i].v += invH * (poses[i].c - start[i].c);
            velocities[i].w += invH * (poses[i].a - start[i].a);
        }
    });
    team.sync();
}

// A bundle's NGS sweeps, on one thread: the sweep above, skipping the islands already solved.
PositionPhaseResult solveMemberSweeps(JointGroups& groups, const IslandSchedule& schedule,
                                      ContactSolver& contacts, SolverPose* poses,
                                      std::vector<PositionPhaseResult>& results, int iterations) {
    const int count = schedule.memberCount;
    const std::vector<std::int32_t>& contactStart = schedule.memberContactStart;
    // An island with nothing for NGS to check is solved without a sweep.
    std::array<std::uint8_t, kMostBundleMembers> active{};
    if (contacts.hasPositionConstraints()) {
        for (int m = 0; m < count; ++m) active[m] = contactStart[m + 1] > contactStart[m];
    }
    groups.forEachGroup([&](auto strategy, auto& group, int g) {
        if constexpr (decltype(strategy)::kNgsSweeps) {
            const std::int32_t start = schedule.groupStart[g];
            for (int k = 0; k < static_cast<int>(group.size()); ++k) {
                active[schedule.jointMember[static_cast<std::size_t>(start + k)]] = 1;
            }
        }
    });
    int activeCount = 0;
    for (int m = 0; m < count; ++m) {
        results[m] = {0, active[m] == 0};
        activeCount += active[m];
    }

    std::array<std::uint8_t, kMostBundleMembers> failed{};
    for (int sweep = 1; sweep <= iterations && activeCount > 0; ++sweep) {
        failed.fill(0);
        for (int m = 0; m < count; ++m) {
            if (!active[m] || contactStart[m + 1] == contactStart[m]) continue;
            const float smallest =
                contacts.solvePositions({contactStart[m], contactStart[m + 1]}, poses, false);
            if (!ContactSolver::withinTolerance(smallest)) failed[m] = 1;
        }
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kNgsSweeps) {
                const std::uint8_t* member = schedule.jointMember.data() + schedule.groupStart[g];
                for (int k = 0; k < static_cast<int>(group.size()); ++k) {
                    if (!active[member[k]]) continue;
                    if (!S::solvePosition(group[k], poses)) failed[member[k]] = 1;
                }
            }
        });
        for (int m = 0; m < count; ++m) {
            if (!active[m]) continue;
            results[m].sweeps = sweep;
            if (!failed[m]) {
                results[m].solved = true;
                active[m] = 0;
                --activeCount;
            }
        }
    }
    PositionPhaseResult result{0, true};
    for (int m = 0; m < count; ++m) {
        result.sweeps = std::max(result.sweeps, results[m].sweeps);
        result.solved = result.solved && results[m].solved;
    }
    return result;
}

// Step 5: the sweeps over the NGS joints that ask for more than the world's. `results` has each
// island's shared sweeps (one entry per bundle member); an island whose shared sweeps ended
// within tolerance needs none, and each island stops as soon as its asking joints are within
// slop, as it would alone. On one thread.
void solveExtraSweeps(JointGroups& groups, const IslandSchedule& schedule, SolverPose* poses,
                      std::vector<PositionPhaseResult>& results) {
    const int count = schedule.memberCount;
    std::array<std::uint8_t, kMostBundleMembers> active{};
    int activeCount = 0;
    for (int m = 0; m < count; ++m) {
        active[m] = results[m].solved ? 0 : 1;
        activeCount += active[m];
    }
    for (int sweep = 0; sweep < schedule.mostExtraSweeps && activeCount > 0; ++sweep) {
        std::array<std::uint8_t, kMostBundleMembers> failed{};
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kNgsSweeps) {
                const std::int32_t start = schedule.groupStart[g];
                for (int k = 0; k < static_cast<int>(group.size()); ++k) {
                    const std::size_t at = static_cast<std::size_t>(start + k);
                    if (schedule.extraSweeps[at] <= sweep) continue;
                    const int m = count > 1 ? schedule.jointMember[at] : 0;
                    if (!active[m]) continue;
                    ++results[m].extraSolves;
                    if (!S::solvePosition(group[k], poses)) failed[m] = 1;
                }
            }
        });
        for (int m = 0; m < count; ++m) {
            if (active[m] && !failed[m]) {
                active[m] = 0;
                --activeCount;
            }
        }
    }
}

}  // namespace

PositionPhaseResult solvePositionPhase(const Team& team, JointGroups& groups,
                                       const IslandSchedule& schedule, ContactSolver& contacts,
                                       SolverPose* poses, SolverVelocity* velocities,
                                       PositionPhaseScratch& scratch, int iterations, float h,
                                       int substep) {
    solveRelaxSweeps(team, groups, schedule, contacts, velocities, iterations);
    solvePseudoVelocityPass(team, groups, schedule, poses, scratch.pseudo, iterations, h);
    solveXpbdSweeps(team, groups, schedule, poses, velocities, scratch.xpbdStart, iterations, h);

    PositionPhaseResult result;
    bool anyJoint = false;
    groups.forEachGroup([&](auto strategy, auto& group, int) {
        anyJoint = anyJoint || (decltype(strategy)::kNgsSweeps && !group.empty());
    });
    if (!anyJoint && !contacts.hasPositionConstraints()) {
        result.solved = true;
        if (team.leader()) {
            std::fill(scratch.memberResults.begin(), scratch.memberResults.end(), result);
        }
        return result;
    }

    groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        if constexpr (S::kNgsSweeps) {
            team.forBatchShares(schedule.jointBatches[g], [&](IndexRange mine) {
                for (int k = mine.begin; k < mine.end; ++k) S::beginSweeps(group[k], poses);
            });
        }
    });
    team.sync();
    if (schedule.memberCount > 1) {
        PositionPhaseResult bundle = solveMemberSweeps(groups, schedule, contacts, poses,
                                                       scratch.memberResults, iterations);
        if (schedule.mostExtraSweeps > 0) {
            solveExtraSweeps(groups, schedule, poses, scratch.memberResults);
        }
        return bundle;
    }

    // A sweep is solved when no block of it found a contact out of tolerance (NaN included)
    // or a joint beyond slop: the same answer however the sweep was cut into blocks.
    while (result.sweeps < iterations) {
        std::atomic<std::uint8_t>& failed =
            scratch.sweepFailed[static_cast<std::size_t>(substep * iterations + result.sweeps)];
        ++result.sweeps;
        forEachBatchSaying(team, schedule.contactBatches, [&](IndexRange range, bool independent) {
            const float smallest = contacts.solvePositions(range, poses, independent);
            if (!ContactSolver::withinTolerance(smallest))
                failed.store(1, std::memory_order_relaxed);
        });
        groups.forEachGroup([&](auto strategy, auto& group, int g) {
            using S = decltype(strategy);
            if constexpr (S::kNgsSweeps) {
                forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
                    bool withinSlop = true;
                    for (int k = range.begin; k < range.end; ++k) {
                        // Evaluated for every joint: each solve moves the bodies, whatever the
                        // others report.
                        bool ok = S::solvePosition(group[k], poses);
                        withinSlop = withinSlop && ok;
                    }
                    if (!withinSlop) failed.store(1, std::memory_order_relaxed);
                });
            }
        });
        // Every block of the sweep is finished (the batches' syncs): its flags are in.
        if (failed.load(std::memory_order_relaxed) == 0) {
            result.solved = true;
            break;
        }
    }
    if (schedule.mostExtraSweeps > 0 && !result.solved) {
        // One block, so one member runs every extra sweep, in solving order; sync() waits for
        // blocks, not for members, so the work must be one.
        team.forBlocks(1, 1, [&](IndexRange) {
            scratch.memberResults[0] = result;
            solveExtraSweeps(groups, schedule, poses, scratch.memberResults);
        });
        team.sync();
        result.extraSolves = scratch.memberResults[0].extraSolves;
        return result;
    }
    if (team.leader()) scratch.memberResults[0] = result;  // every member found the same
    return result;
}

}  // namespace pivot
