#include "solver/island_solver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "constraints/rotation_lanes.h"
#include "core/buffer.h"
#include "core/fresh_copy.h"
#include "core/prefetch.h"
#include "islands/graph_coloring.h"
#include "pivot/constants.h"
#include "solver/body_motion.h"

namespace pivot {

namespace {

std::atomic<bool> jointRemeasuring{true};
std::atomic<bool> loneBodyShortcut{true};

// Whether the substep after a first one re-measures the joints kept across substeps instead of
// rebuilding them (without warm starting, each substep's impulses start at zero: rebuilt).
bool laterSubstepsRemeasure(const StepContext& step) {
    return step.warmStarting && jointRemeasuring.load(std::memory_order_relaxed);
}

// Runs f(island, range) on the part of `mine` (solver slots) in each island of the bundle.
template <typename F>
void forEachMemberPart(const IslandSchedule& schedule, IndexRange mine, F&& f) {
    if (schedule.memberCount == 1) {
        f(0, mine);
        return;
    }
    for (int m = 0; m < schedule.memberCount; ++m) {
        const int begin = std::max(mine.begin, schedule.memberSlotStart[m]);
        const int end = std::min(mine.end, schedule.memberSlotStart[m + 1]);
        if (begin < end) f(m, IndexRange{begin, end});
    }
}

// The island of the bundle that joint `at` (in solving order) belongs to.
int jointMember(const IslandSchedule& schedule, std::size_t at) {
    return schedule.memberCount == 1 ? 0 : schedule.jointMember[at];
}

// Copy body state into the solver slots, with private copies of the bodies that never move
// (nothing integrates them, so a copy is simply the body's own state); with `keepStart`, the
// poses also into stepStart.
void loadBodies(const Team& team, const IslandView& island, IslandWorkspace& work,
                const SlotPool<Body>& bodies, const StepContext& step, bool keepStart) {
    const auto load = [&](std::size_t slot, const Body& b) {
        work.positions[slot] = {b.center, b.angle};
        work.velocities[slot] = {b.linearVelocity, b.angularVelocity};
        work.bodyInputs[slot] = {b.localCenter, b.invMass, b.invInertia, work.velocities[slot]};
        if (keepStart) work.stepStart[slot] = work.positions[slot];
    };
    // The bodies are scattered over their pool: each is asked for a few bodies ahead.
    constexpr int kBodiesAhead = 8;
    team.forBlocks(island.bodyCount, [&](IndexRange mine) {
        for (int i = mine.begin; i < mine.end; ++i) {
            if (i + kBodiesAhead < mine.end) {
                prefetch(&bodies[island.bodies[i + kBodiesAhead]], sizeof(Body));
            }
            const Body& b = bodies[island.bodies[i]];
            load(static_cast<std::size_t>(i), b);
            work.drives[static_cast<std::size_t>(i)] = velocityDrive(b, step);
        }
    });
    const std::vector<std::int32_t>& copies = work.schedule.fixedCopies;
    team.forBlocks(static_cast<int>(copies.size()), [&](IndexRange mine) {
        for (int k = mine.begin; k < mine.end; ++k) {
            load(static_cast<std::size_t>(island.bodyCount + k), bodies[island.bodies[copies[k]]]);
        }
    });
}

// Where each solver slot has moved since the start of the step (for contacts built once a step,
// which only substepped worlds do: the rotations by the polynomial, constraints/rotation_lanes.h).
void measureMotion(const Team& team, IslandWorkspace& work) {
    team.forBlocks(static_cast<int>(work.positions.size()), [&](IndexRange mine) {
        for (int i = mine.begin; i < mine.end; ++i) {
            work.motion[i].dp = work.positions[i].c - work.stepStart[i].c;
        }
        polynomialRotations(
            mine.begin, mine.end, [&](int i) { return work.positions[i].a - work.stepStart[i].a; },
            [&](int i, Rot q) { work.motion[i].dq = q; });
    });
}

// Each slot's rotation, once, for the contacts' and joints' set-up (which would otherwise compute
// both of its bodies' for every constraint). A substepped world, which has no Box2D 2.4.1 bits
// to keep, measures them by the polynomial, several at a time (constraints/rotation_lanes.h).
void measureRotations(const Team& team, IslandWorkspace& work, const StepContext& step) {
    const bool polynomial = step.substepCount > 1;
    team.forBlocks(static_cast<int>(work.positions.size()), [&](IndexRange mine) {
        if (polynomial) {
            polynomialRotations(
                mine.begin, mine.end, [&](int i) { return work.positions[i].a; },
                [&](int i, Rot q) { work.rotations[i] = q; });
        } else {
            for (int i = mine.begin; i < mine.end; ++i) {
                work.rotations[i] = Rot(work.positions[i].a);
            }
        }
    });
}

// Gravity, forces and damping over one substep, on the dynamic bodies' solver velocities
// (semi-implicit Euler: velocities first, positions later from the new velocities).
void integrateVelocities(const Team& team, const IslandView& island, IslandWorkspace& work) {
    team.forBlocks(island.bodyCount, [&](IndexRange mine) {
        for (int i = mine.begin; i < mine.end; ++i) {
            integrateVelocity(work.drives[static_cast<std::size_t>(i)], work.velocities[i]);
        }
    });
}

// Whether a step that reaches `joint` at a separation of sqrt(separationSquared) lets it go:
// beyond its let-go separation, when it has one. (Its stored reactions are finite:
// storeJointImpulses lets go of a joint whose are not.) A let-go joint acts on nothing for the
// rest of this step (makeInert) and is in no island after it.
bool beyondLetGoSeparation(const Joint& joint, float separationSquared, const StepContext& step) {
    const float limit = joint.letGoSeparation(step.jointLetGoSeparation);
    return limit > 0.0f && !(separationSquared <= limit * limit);
}

// Whether constraints of type C under strategy S are kept from one substep to the next and
// measured again at the current poses (the same values as a rebuild, without reading the joint
// and its bodies again), instead of rebuilt.
template <typename S, typename C>
constexpr bool keptAcrossSubsteps() {
    return S::kKeptAcrossSubsteps && CanRemeasure<C>::value;
}

// A kept constraint at a later substep: measured at the current poses (or left inert if its
// joint was let go: work.jointLetGo says which, so the joint is not read), its bias from them.
template <typename S, typename C>
void remeasureKept(C& c, bool letGo, const SolverPose* poses, const Rot* rotations,
                   const StepContext& step) {
    if (letGo) {
        c.makeInert();
    } else if constexpr (RemeasuresWithRotations<C>::value) {
        if (rotations) {
            c.remeasure(poses, rotations, step);
        } else {
            c.remeasure(poses, step);
        }
    } else {
        c.remeasure(poses, step);
    }
    S::prepareBias(c, poses, step.invDt);
}

// Build each joint's solver constraint in its group (no velocity is touched: the warm start
// comes after, in warmStartJoints). The first substep of a step lets go of the joints beyond
// their let-go separation; later substeps rebuild each constraint at the current poses from the
// impulses the substep before stored, except the kept ones (keptAcrossSubsteps), which the warm
// start re-measures (warmStartRemeasuring). `rotations`, when given, holds each slot's rotation
// at these poses (measureRotations): joints that can take them do, instead of two sines each.
// Each member prepares the share of every colour that its sweeps solve first (forBatchShares),
// so a constraint's lines stay on one core: cut by forBlocks instead, the set-up wrote half of
// the constraints on the other core, and `joint_grid`'s soft step on two workers was 15% slower
// (the same holds for the joints' other passes over a whole group).
void prepareJoints(const Team& team, IslandWorkspace& work, SlotPool<Joint>& joints,
                   const StepContext& step, bool firstSubstep, bool remeasure, const Rot* rotations,
                   IslandReport* reports) {
    const IslandSchedule& schedule = work.schedule;
    const SolverPose* poses = work.positions.data();
    const SolverBodyInputs* inputs = work.bodyInputs.data();
    // The joints are read from their pool in colour order, scattered: each is asked for a few
    // joints ahead (a joint is several cache lines, and the set-up between two is long).
    constexpr int kJointsAhead = 4;
    work.groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        using C = typename std::decay_t<decltype(group)>::value_type;
        if constexpr (keptAcrossSubsteps<S, C>()) {
            if (remeasure) return;  // warmStartRemeasuring's
        }
        team.forBatchShares(schedule.jointBatches[g], [&](IndexRange mine) {
            for (int k = mine.begin; k < mine.end; ++k) {
                const std::size_t at = static_cast<std::size_t>(schedule.groupStart[g] + k);
                if (k + kJointsAhead < mine.end) {
                    prefetch(&joints[schedule.jointIds[at + kJointsAhead]], sizeof(Joint));
                }
                const std::int32_t jointIndex = schedule.jointIds[at];
                auto& joint = joints[jointIndex];
                C& c = group[k];
                resetToDefault(c);
                const JointSlots& slots = schedule.jointPairs[at];
                float separationSquared;
                if constexpr (PreparesWithRotations<C>::value) {
                    separationSquared =
                        rotations
                            ? c.prepare(joint, jointIndex, inputs, slots, poses, rotations, step)
                            : c.prepare(joint, jointIndex, inputs, slots, poses, step);
                } else {
                    separationSquared = c.prepare(joint, jointIndex, inputs, slots, poses, step);
                }
                S::prepareSoftness(c, joint, step);
                if (!firstSubstep && joint.letGo) {
                    c.makeInert();
                } else if (firstSubstep && beyondLetGoSeparation(joint, separationSquared, step)) {
                    joint.letGoFor(JointLetGoReason::Separation, std::sqrt(separationSquared));
                    ++reports[jointMember(schedule, at)].letGoJoints;
                    c.makeInert();
                } else {
                    const bool warm = S::kWarmStart || isVelocityOnly<C>();
                    c.startImpulses(joint, step.warmStarting && warm, step.dtRatio);
                }
                work.jointLetGo[at] = joint.letGo ? 1 : 0;
                // The strategy's bias from the error at these poses (the constraint's own).
                S::prepareBias(c, poses, step.invDt);
            }
        });
    });
}

// The warm start of a later substep whose kept constraints re-measure (prepareJoints left them):
// each is measured in the block that warm-starts it, so its lines and its bodies' are read once
// for both. The re-measure reads the poses only, which nothing in between writes (the contacts'
// warm start writes velocities), so the values are prepareJoints' own. Done in a pass of their
// own, the re-measures were more than half of the joints' set-up time in `joint_grid`'s soft step.
void warmStartRemeasuring(const Team& team, IslandWorkspace& work, const StepContext& step,
                          const Rot* rotations, SolverVelocity* velocities) {
    const IslandSchedule& schedule = work.schedule;
    const SolverPose* poses = work.positions.data();
    work.groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        using C = typename std::decay_t<decltype(group)>::value_type;
        const std::uint8_t* letGo = work.jointLetGo.data() + schedule.groupStart[g];
        forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) {
                if constexpr (keptAcrossSubsteps<S, C>()) {
                    remeasureKept<S>(group[k], letGo[k] != 0, poses, rotations, step);
                }
                group[k].warmStart(velocities);
            }
        });
    });
}

// A joint whose impulses (or the force and torque they stand for) went non-finite during the
// step is let go: it keeps nothing. Strategies that relax or solve XPBD store after the position
// phase (`afterPositionPhase`), so that what it adds counts; the others before it, as the velocity
// phase left them (the pseudo-velocity pass reuses their accumulators, and ModifiedNGS's frozen
// mass re-measures the directions the reactions are reported along).
//
// Constraints the next substep re-measures keep their impulses themselves: in an island where no
// joint can break, they are stored (and checked) at the last substep only. Writing every joint
// back at every substep was a sixth of `joint_grid`'s soft step. Their impulses go non-finite
// only when the island diverged, and then their bodies' solved state is not finite either (they
// are discarded at the end of the step); the joint is let go then.
void storeJointImpulses(const Team& team, IslandWorkspace& work, SlotPool<Joint>& joints,
                        const SlotPool<Body>& bodies, const StepContext& step, int substep,
                        bool afterPositionPhase, IslandReport* reports) {
    const bool lastSubstep = substep == step.substepCount - 1;
    const bool nextRemeasures =
        !lastSubstep && laterSubstepsRemeasure(step) && !work.schedule.jointsMayBreak;
    const float invDt = step.invDt;
    work.groups.forEachGroup([&](auto strategy, auto& group, int g) {
        using S = decltype(strategy);
        using C = typename std::decay_t<decltype(group)>::value_type;
        if (S::kStoreAfterPositionPhase != afterPositionPhase) return;
        if constexpr (S::kKeptAcrossSubsteps && CanRemeasure<C>::value) {
            if (nextRemeasures) return;
        }
        const std::int32_t start = work.schedule.groupStart[g];
        team.forBatchShares(work.schedule.jointBatches[g], [&](IndexRange mine) {
            for (int k = mine.begin; k < mine.end; ++k) {
                const auto& c = group[k];
                auto& joint = joints[c.jointIndex];
                // Let go when this step prepared it: it keeps no impulse (an inert constraint's
                // zero impulse can still be 0 * inf = NaN when its island diverged).
                if (joint.letGo) continue;
                c.storeImpulses(joint, invDt);
                const std::size_t at = static_cast<std::size_t>(start + k);
                std::uint8_t& letGo = work.jointLetGo[at];
                IslandReport& report = reports[jointMember(work.schedule, at)];
                // The bodies are still at their start-of-step poses (written back later).
                if (!joint.template hasFiniteReactionsAs<typename C::Storage>()) {
                    joint.letGoFor(JointLetGoReason::NonFinite, joint.separation(bodies));
                    letGo = 1;
                    ++report.letGoJoints;
                } else if (joint.breakForce > 0.0f || joint.breakTorque > 0.0f) {
                    // The thresholds are for the force over the step, the mean of its substeps'
                    // (each substep's impulse over the substep): an impact given within one
                    // substep reads the same at any substep count. With one substep the mean is
                    // that substep's force, bit for bit.
                    if (substep == 0) {
                        joint.stepForceSum = joint.reactionForce();
                        joint.stepTorqueSum = joint.reactionTorque();
                    } else {
                        joint.stepForceSum += joint.reactionForce();
                        joint.stepTorqueSum += joint.reactionTorque();
                    }
                    if (!lastSubstep) continue;
                    const float substeps = static_cast<float>(step.substepCount);
                    // Finite components can still square past the float range: such a force is
                    // reported as the largest float.
                    const float force = std::min(length(joint.stepForceSum) / substeps,
                                                 std::numeric_limits<float>::max());
                    const float torque = std::fabs(joint.stepTorqueSum) / substeps;
                    const bool forceBroke = joint.breakForce > 0.0f && force > joint.breakForce;
                    if (forceBroke || (joint.breakTorque > 0.0f && torque > joint.breakTorque)) {
                        joint.letGoFor(
                            forceBroke ? JointLetGoReason::Force : JointLetGoReason::Torque,
                            joint.separation(bodies), forceBroke ? force : torque);
                        letGo = 1;
                        ++report.letGoJoints;
                    }
                }
            }
        });
    });
}

// Mouse joints are few and share no stage with other constraints: the leader solves them.
void prepareMouseJoints(const IslandView& island, IslandWorkspace& work,
                        const SlotPool<Body>& bodies, const SlotPool<MouseJoint>& mouseJoints,
                        const StepContext& step) {
    for (int k = 0; k < island.mouseCount; ++k) {
        const std::int32_t m = island.mouseJoints[k];
        const MouseJoint& joint = mouseJoints[m];
        const Body& body = bodies[joint.body];
        MouseConstraint& c = work.mouseConstraints[k];
        c = MouseConstraint{};
        c.index = island.mouseBodies[k];
        c.jointIndex = m;
        c.mB = body.invMass;
        c.iB = body.invInertia;
        prepareMouse(c, joint, body.localCenter, work.positions.data(), work.velocities.data(),
                     step.dt, step.dtRatio, step.warmStarting);
    }
}

// Move every body by its velocity, limiting the move per step (integratePosition).
void integratePositions(const Team& team, IslandWorkspace& work, const StepContext& step,
                        IslandReport* reports) {
    const MotionLimits limits(step);
    team.forBlocks(static_cast<int>(work.velocities.size()), [&](IndexRange mine) {
        forEachMemberPart(work.schedule, mine, [&](int member, IndexRange part) {
            for (int i = part.begin; i < part.end; ++i) {
                integratePosition(work.velocities[i], work.positions[i], step.dt, limits,
                                  reports[member]);
            }
        });
    });
}

// Bodies slower than the sleep tolerances accumulate rest time; once every body of the island
// has rested kTimeToSleep and the position phase converged, the whole island sleeps.
bool updateSleep(const std::int32_t* islandBodies, int bodyCount, SlotPool<Body>& bodies,
                 const StepContext& step, bool positionSolved) {
    if (!step.enableSleep) return false;
    const float linearTolerance = kLinearSleepTolerance * kLinearSleepTolerance;
    const float angularTolerance = kAngularSleepTolerance * kAngularSleepTolerance;
    float minSleepTime = kTimeToSleep;
    bool anyMovable = false;
    for (int i = 0; i < bodyCount; ++i) {
        Body& b = bodies[islandBodies[i]];
        if (b.type == BodyType::Static) continue;
        anyMovable = true;
        if (!b.allowSleep || b.angularVelocity * b.angularVelocity > angularTolerance ||
            dot(b.linearVelocity, b.linearVelocity) > linearTolerance) {
            b.sleepTime = 0.0f;
            minSleepTime = 0.0f;
        } else {
            b.sleepTime += step.stepDt;
            minSleepTime = std::min(minSleepTime, b.sleepTime);
        }
    }
    if (!anyMovable || minSleepTime < kTimeToSleep || !positionSolved) return false;
    for (int i = 0; i < bodyCount; ++i) {
        Body& b = bodies[islandBodies[i]];
        if (b.type != BodyType::Static) putToSleep(b);
    }
    return true;
}

// Every body's solved state back into the body (writeBackBody).
void writeBack(const Team& team, const IslandView& island, const IslandWorkspace& work,
               SlotPool<Body>& bodies, IslandReport* reports) {
    team.forBlocks(island.bodyCount, [&](IndexRange mine) {
        forEachMemberPart(work.schedule, mine, [&](int member, IndexRange part) {
            for (int i = part.begin; i < part.end; ++i) {
                Body& b = bodies[island.bodies[i]];
                if (b.type != BodyType::Static) {
                    writeBackBody(b, work.positions[i], work.velocities[i], reports[member]);
                }
            }
        });
    });
}

// One substep (the whole step when there is one): forces, constraints built at the current
// poses, warm start, velocity iterations, impulses stored, integration, then the position phase
// of each strategy.
void solveSubstep(const Team& team, const IslandView& island, IslandWorkspace& work,
                  SolverStorage& storage, const StepContext& step, int substep,
                  IslandReport* mine) {
    const IslandSchedule& schedule = work.schedule;
    SlotPool<Body>& bodies = storage.bodies;
    const bool firstSubstep = substep == 0;
    const bool lastSubstep = substep == step.substepCount - 1;
    const bool contactsBuilt = !firstSubstep && work.contactSolver.builtOncePerStep();
    // Joints kept across substeps are re-measured at this substep, in the warm start's pass.
    // Built or re-measured, they read each body's rotation from work.rotations where that costs
    // fewer sines and cosines than two per joint (or where the contacts have them measured).
    const bool remeasure = !firstSubstep && laterSubstepsRemeasure(step);
    const bool rotationsForJoints =
        island.jointCount > 0 && 2 * island.jointCount >= island.bodyCount;
    bool rotationsMeasured = false;
    integrateVelocities(team, island, work);
    if (contactsBuilt) {
        measureMotion(team, work);
    } else if (island.contactCount > 0) {
        measureRotations(team, work, step);
        rotationsMeasured = true;
    }
    if (rotationsForJoints && !rotationsMeasured) {
        measureRotations(team, work, step);
        rotationsMeasured = true;
    }
    team.sync();
    team.forBatchShares(schedule.contactBatches, [&](IndexRange range) {
        if (contactsBuilt) {
            work.contactSolver.updateSeparations(range, work.motion.data());
        } else {
            work.contactSolver.prepare(
                range, schedule.contactIds.data(), schedule.contactPairs.data(), storage.contacts,
                work.bodyInputs.data(), step, work.positions.data(), work.rotations.data());
        }
    });
    prepareJoints(team, work, storage.joints, step, firstSubstep, remeasure,
                  rotationsMeasured ? work.rotations.data() : nullptr, mine);
    team.sync();

    // Warm start: contacts, then joints, then mouse joints; each velocity sweep then solves
    // contacts after joints, as Box2D 2.4.1 does (see docs/position-correction.md).
    SolverVelocity* velocities = work.velocities.data();
    forEachBatchSaying(team, schedule.contactBatches, [&](IndexRange range, bool independent) {
        work.contactSolver.warmStart(range, velocities, independent);
    });
    if (remeasure) {
        warmStartRemeasuring(team, work, step, rotationsMeasured ? work.rotations.data() : nullptr,
                             velocities);
    } else {
        warmStartJoints(team, work.groups, schedule, velocities);
    }
    const bool hasMouse = island.mouseCount > 0;
    if (hasMouse) {
        team.once([&] { prepareMouseJoints(island, work, bodies, storage.mouseJoints, step); });
        team.sync();
    }
    for (int it = 0; it < step.velocityIterations; ++it) {
        // A mouse joint is the user's hand: solved first, so the rigid joints and contacts have
        // the last word on what the drag may do to them.
        if (hasMouse) {
            team.once([&] {
                for (MouseConstraint& c : work.mouseConstraints) solveMouseVelocity(c, velocities);
            });
            team.sync();
        }
        solveVelocitySweep(team, work.groups, schedule, velocities);
        forEachBatchSaying(team, schedule.contactBatches, [&](IndexRange range, bool independent) {
            work.contactSolver.solveVelocities(range, velocities, independent);
        });
    }

    storeJointImpulses(team, work, storage.joints, bodies, step, substep, false, mine);
    if (hasMouse) {
        team.once([&] {
            for (const MouseConstraint& c : work.mouseConstraints) {
                storage.mouseJoints[c.jointIndex].impulse =
                    isFinite(c.impulse) ? c.impulse : Vec2{};
            }
        });
    }
    integratePositions(team, work, step, mine);
    team.sync();

    // What it did, island by island, is left in work.positionScratch.memberResults.
    solvePositionPhase(team, work.groups, schedule, work.contactSolver, work.positions.data(),
                       velocities, work.positionScratch, step.positionIterations, step.dt, substep);
    // After the relax sweeps, which add to the impulses (the contacts' NGS solves do not).
    storeJointImpulses(team, work, storage.joints, bodies, step, substep, true, mine);
    // Constraints rebuilt each substep read the impulses back from the manifolds; those built
    // once a step keep them until its end, where they also keep the first substep's approach.
    const bool builtOnce = work.contactSolver.builtOncePerStep();
    if (!builtOnce || lastSubstep) {
        team.forBatchShares(schedule.contactBatches, [&](IndexRange range) {
            work.contactSolver.storeImpulses(range, storage.contacts, builtOnce || firstSubstep);
        });
    }
    // The next substep's set-up reads the poses and stored impulses this one wrote; the write
    // back, the bodies the let-go joints above measured their separation on.
    team.sync();
}

}  // namespace

void setJointRemeasuring(bool enabled) {
    jointRemeasuring = enabled;
}

void setLoneBodyShortcut(bool enabled) {
    loneBodyShortcut = enabled;
}

bool loneBodyShortcutOn() {
    return loneBodyShortcut.load(std::memory_order_relaxed);
}

void reserveWorkspace(IslandWorkspace& work, const BufferBounds& bound) {
    work.scheduler.reserve(bound);
    work.schedule.reserve(bound);
    work.velocities.reserve(bound.bodies);
    work.positions.reserve(bound.bodies);
    work.bodyInputs.reserve(bound.bodies);
    work.drives.reserve(bound.bodies);
    work.stepStart.reserve(bound.bodies);
    work.motion.reserve(bound.bodies);
    work.rotations.reserve(bound.bodies);
    work.positionScratch.pseudo.reserve(bound.bodies);
    work.positionScratch.xpbdStart.reserve(bound.bodies);
    work.mouseConstraints.reserve(bound.mouseJoints);
    work.positionScratch.memberResults.reserve(kMostBundleMembers);
    reserveBuffer(work.memberReports, kMostBundleMembers);
    // A batch per colour, and the overflow's.
    work.contactSolver.reserve(bound.contacts, GraphColoring::kMaxColors + 1);
}

void planIsland(const IslandSet& set, int first, int count, IslandWorkspace& work,
                const SolverStorage& storage, const StepContext& step, int teamSize,
                std::uint64_t islandRevision) {
    const IslandView island = set.view(first, count);
    IslandSchedule& schedule = work.schedule;
    const bool planned = islandRevision != IslandWorkspace::kNeverPlanned &&
                         work.plannedAt == islandRevision && work.plannedIsland == first &&
                         work.plannedCount == count;
    if (!planned) {
        work.scheduler.plan(island, &set.ranges[static_cast<std::size_t>(first)], count,
                            storage.bodies, storage.joints, storage.contacts.capacity(), schedule);
        work.plannedIsland = first;
        work.plannedCount = count;
        work.plannedAt = islandRevision;
    }
    const std::size_t slots = static_cast<std::size_t>(schedule.slotCount(island));
    resizeBuffer(work.velocities, slots);
    resizeBuffer(work.positions, slots);
    resizeBuffer(work.bodyInputs, slots);
    resizeBuffer(work.drives, slots);
    resizeBuffer(work.stepStart, slots);
    resizeBuffer(work.motion, slots);
    resizeBuffer(work.rotations, slots);
    work.groups.resize(schedule.groupStart);
    resizeBuffer(work.jointLetGo, schedule.jointIds.size());
    work.contactSolver.reset(island.contactCount, step, &schedule.contactBatches,
                             schedule.contactsColored);
    resizeBuffer(work.mouseConstraints, static_cast<std::size_t>(island.mouseCount));
    resizeBuffer(work.positionScratch.pseudo, slots);
    resizeBuffer(work.positionScratch.xpbdStart, slots);
    work.positionScratch.clearSweepFlags(static_cast<std::size_t>(step.substepCount) *
                                         static_cast<std::size_t>(step.positionIterations));
    resizeBuffer(work.positionScratch.memberResults, static_cast<std::size_t>(count));
    resizeBuffer(work.memberReports, static_cast<std::size_t>(teamSize * count));
    std::fill(work.memberReports.begin(), work.memberReports.end(), IslandReport{});
}

void solveIslands(const Team& team, const IslandSet& set, int first, int count,
                  IslandWorkspace& work, SolverStorage& storage, const StepContext& step,
                  IslandReport* reports) {
    const IslandView island = set.view(first, count);
    SlotPool<Body>& bodies = storage.bodies;
    // Zeroed by planIsland: a member that joins late, or not at all, adds nothing.
    IslandReport* mine = work.memberReports.data() + team.member() * count;

    loadBodies(team, island, work, bodies, step,
               work.contactSolver.builtOncePerStep() && step.substepCount > 1);
    team.sync();
    // Later substeps warm-start from the substep before, of the same length.
    StepContext later = step;
    later.dtRatio = 1.0f;
    // Per island of the bundle: its position sweeps over the step, and whether its last
    // substep's position phase was solved.
    std::array<int, kMostBundleMembers> positionSweeps{};
    std::array<int, kMostBundleMembers> extraSolves{};
    const std::vector<PositionPhaseResult>& phases = work.positionScratch.memberResults;
    for (int substep = 0; substep < step.substepCount; ++substep) {
        solveSubstep(team, island, work, storage, substep == 0 ? step : later, substep, mine);
        if (!team.leader()) continue;  // the leader alone reports, and reads the phases
        for (int m = 0; m < count; ++m) {
            positionSweeps[m] += phases[m].sweeps;
            extraSolves[m] += phases[m].extraSolves;
        }
    }
    writeBack(team, island, work, bodies, mine);
    team.sync();
    if (!team.leader()) return;

    const int teamSize = static_cast<int>(work.memberReports.size()) / count;
    for (int m = 0; m < count; ++m) {
        IslandReport report;
        for (int t = 0; t < teamSize; ++t) {
            const IslandReport& member = work.memberReports[t * count + m];
            report.translationClamps += member.translationClamps;
            report.rotationClamps += member.rotationClamps;
            report.letGoJoints += member.letGoJoints;
            report.edgeBodies += member.edgeBodies;
            report.discardedBodies += member.discardedBodies;
        }
        report.positionIterations = positionSweeps[m];
        report.extraPositionSolves = extraSolves[m];
        const IslandSet::Range& r = set.ranges[static_cast<std::size_t>(first + m)];
        report.fellAsleep = updateSleep(set.bodies.data() + r.bodyBegin, r.bodyEnd - r.bodyBegin,
                                        bodies, step, phases[m].solved);
        reports[m] = report;
    }
}

IslandReport solveIsland(const Team& team, const IslandSet& set, int index, IslandWorkspace& work,
                         SolverStorage& storage, const StepContext& step) {
    IslandReport report;
    solveIslands(team, set, index, 1, work, storage, step, &report);
    return report;
}

IslandReport solveLoneBody(const IslandSet& set, int index, SlotPool<Body>& bodies,
                           const StepContext& step) {
    const IslandView island = set.view(index);
    Body& b = bodies[island.bodies[0]];
    SolverPose pose{b.center, b.angle};
    SolverVelocity velocity{b.linearVelocity, b.angularVelocity};
    const MotionLimits limits(step);
    const VelocityDrive drive = velocityDrive(b, step);
    IslandReport report;
    for (int substep = 0; substep < step.substepCount; ++substep) {
        integrateVelocity(drive, velocity);
        integratePosition(velocity, pose, step.dt, limits, report);
    }
    if (b.type != BodyType::Static) writeBackBody(b, pose, velocity, report);
    // With no constraint, the position phase is solved at once, without a sweep.
    report.fellAsleep = updateSleep(island.bodies, 1, bodies, step, true);
    return report;
}

}  // namespace pivot
