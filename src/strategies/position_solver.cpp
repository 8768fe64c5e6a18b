#include "strategies/position_solver.h"

#include <algorithm>

#include "pivot/constants.h"

namespace pivot {

namespace {

constexpr int kBaumgarte = static_cast<int>(PositionSolver::Baumgarte);
constexpr int kPseudoVelocity = static_cast<int>(PositionSolver::PseudoVelocity);
constexpr int kModifiedNgs = static_cast<int>(PositionSolver::ModifiedNGS);
constexpr int kFullNgs = static_cast<int>(PositionSolver::FullNGS);

// Baumgarte: the joint's errors at the start of the step, fed back as velocities.
void prepareBaumgarteBias(RevoluteConstraints& group, IndexRange range, const SolverPose* positions,
                          float invDt) {
    for (int k = range.begin; k < range.end; ++k) {
        RevoluteConstraint& c = group[k];
        const SolverPose& A = positions[c.bodies.indexA];
        const SolverPose& B = positions[c.bodies.indexB];
        Vec2 C = B.c + c.point.rB - A.c - c.point.rA;  // rA, rB were set for this pose
        c.point.bias = (c.biasFactor * invDt) * C;
        prepareLimitBaumgarteBias(c.angle, c.biasFactor, invDt);
    }
}

template <bool withBias>
void solveVelocityRange(RevoluteConstraints& group, IndexRange range, SolverVelocity* velocities) {
    for (int k = range.begin; k < range.end; ++k) {
        RevoluteConstraint& c = group[k];
        solveRevoluteVelocity(c, velocities, withBias ? c.point.bias : Vec2{});
    }
}

// PseudoVelocity: the velocity solve again, on velocities that only move positions. The
// velocity phase's impulses are stored by now, so its accumulators and bias fields are free to
// hold the pass's own (which start at zero: no warm start).
void solvePseudoVelocityPass(const Team& team, RevoluteConstraints& group,
                             const std::vector<Batch>& batches, SolverPose* positions,
                             std::vector<SolverVelocity>& pseudo, int iterations, float h) {
    if (group.empty()) return;
    const IndexRange slots = team.share(static_cast<int>(pseudo.size()));
    std::fill(pseudo.begin() + slots.begin, pseudo.begin() + slots.end, SolverVelocity{});

    const float invH = 1.0f / h;
    const IndexRange mine = team.share(static_cast<int>(group.size()));
    for (int k = mine.begin; k < mine.end; ++k) {
        RevoluteConstraint& c = group[k];
        Vec2 C = preparePoint(c.bodies, c.point, positions);
        c.point.bias = (c.biasFactor * invH) * C;
        AnglePart& a = c.angle;
        a.angle = jointAngle(a, positions, c.bodies);
        a.lowerImpulse = 0.0f;
        a.upperImpulse = 0.0f;
        a.lowerTerm = std::max(a.angle - a.lower, 0.0f) * invH;
        a.upperTerm = std::max(a.upper - a.angle, 0.0f) * invH;
        prepareLimitBaumgarteBias(a, c.biasFactor, invH);
    }
    team.sync();
    for (int it = 0; it < iterations; ++it) {
        forEachBatch(team, batches, [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) {
                RevoluteConstraint& c = group[k];
                solveAngleVelocity<false>(c.bodies, c.angle, pseudo.data());
                solvePointVelocity(c.bodies, c.point, pseudo.data(), c.point.bias);
            }
        });
    }
    // Bodies no pseudo-velocity joint touches have zero pseudo velocity: adding it is a no-op.
    for (int i = slots.begin; i < slots.end; ++i) {
        positions[i].c += h * pseudo[i].v;
        positions[i].a += h * pseudo[i].w;
    }
    team.sync();
}

// NGS: one sweep of position-level solves over a range. Returns whether every joint was within
// slop.
template <bool rebuildMass>
bool solveNgsRange(const RevoluteConstraints& group, IndexRange range, SolverPose* positions) {
    bool withinSlop = true;
    for (int k = range.begin; k < range.end; ++k) {
        // Evaluated for every joint: each solve moves the bodies, whatever the others report.
        bool ok = solveRevolutePosition<rebuildMass>(group[k], positions);
        withinSlop = withinSlop && ok;
    }
    return withinSlop;
}

}  // namespace

void prepareVelocityBias(const Team& team, ConstraintGroups& groups, const SolverPose* positions,
                         float invDt) {
    RevoluteConstraints& group = groups[kBaumgarte];
    prepareBaumgarteBias(group, team.share(static_cast<int>(group.size())), positions, invDt);
}

void warmStartJoints(const Team& team, const ConstraintGroups& groups,
                     const IslandSchedule& schedule, SolverVelocity* velocities) {
    for (int g = 0; g < kPositionSolverCount; ++g) {
        forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
            for (int k = range.begin; k < range.end; ++k) warmStart(groups[g][k], velocities);
        });
    }
}

void solveVelocitySweep(const Team& team, ConstraintGroups& groups, const IslandSchedule& schedule,
                        SolverVelocity* velocities) {
    forEachBatch(team, schedule.jointBatches[kBaumgarte], [&](IndexRange range) {
        solveVelocityRange<true>(groups[kBaumgarte], range, velocities);
    });
    for (int g : {kPseudoVelocity, kModifiedNgs, kFullNgs}) {
        forEachBatch(team, schedule.jointBatches[g], [&](IndexRange range) {
            solveVelocityRange<false>(groups[g], range, velocities);
        });
    }
}

PositionPhaseResult solvePositionPhase(const Team& team, ConstraintGroups& groups,
                                       const IslandSchedule& schedule,
                                       const ContactSolver& contacts, SolverPose* positions,
                                       PositionPhaseScratch& scratch, int iterations, float h) {
    solvePseudoVelocityPass(team, groups[kPseudoVelocity], schedule.jointBatches[kPseudoVelocity],
                            positions, scratch.pseudo, iterations, h);

    RevoluteConstraints& modified = groups[kModifiedNgs];
    RevoluteConstraints& full = groups[kFullNgs];
    PositionPhaseResult result;
    if (modified.empty() && full.empty() && !contacts.hasPositionConstraints()) {
        result.solved = true;
        return result;
    }

    // ModifiedNGS keeps the effective mass of the pose the position phase starts from.
    const IndexRange mine = team.share(static_cast<int>(modified.size()));
    for (int k = mine.begin; k < mine.end; ++k) {
        RevoluteConstraint& c = modified[k];
        preparePoint(c.bodies, c.point, positions);
    }
    team.sync();

    while (result.sweeps < iterations) {
        ++result.sweeps;
        // Contacts first: a joint then has the last word on a body both move, and a joint's
        // error is the one users look at (as in Box2D 2.4.1's position loop).
        SweepTally tally;
        forEachBatch(team, schedule.contactBatches, [&](IndexRange range) {
            tally.minSeparation = ContactSolver::minSeparation(
                tally.minSeparation, contacts.solvePositions(range, positions));
        });
        forEachBatch(team, schedule.jointBatches[kModifiedNgs], [&](IndexRange range) {
            bool ok = solveNgsRange<false>(modified, range, positions);
            tally.jointsWithinSlop = tally.jointsWithinSlop && ok;
        });
        forEachBatch(team, schedule.jointBatches[kFullNgs], [&](IndexRange range) {
            bool ok = solveNgsRange<true>(full, range, positions);
            tally.jointsWithinSlop = tally.jointsWithinSlop && ok;
        });
        if (team.size() > 1) {
            std::vector<SweepTally>& round = scratch.tallies[result.sweeps & 1];
            round[team.member()] = tally;
            team.sync();
            tally = SweepTally{};
            for (const SweepTally& t : round) {
                tally.minSeparation =
                    ContactSolver::minSeparation(tally.minSeparation, t.minSeparation);
                tally.jointsWithinSlop = tally.jointsWithinSlop && t.jointsWithinSlop;
            }
        }
        if (ContactSolver::withinTolerance(tally.minSeparation) && tally.jointsWithinSlop) {
            result.solved = true;
            break;
        }
    }
    return result;
}

}  // namespace pivot
