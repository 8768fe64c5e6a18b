#include "solver/position_solver.h"

#include <algorithm>

#include "pivot/constants.h"

namespace pivot {

namespace {

PointConstraints& groupOf(ConstraintGroups& groups, PositionSolver solver) {
    return groups[static_cast<int>(solver)];
}

// Baumgarte: the joint's error at the start of the step, fed back as a velocity.
void prepareBaumgarteBias(PointConstraints& group, const SolverPosition* positions, float invDt) {
    for (PointConstraint& pc : group) {
        const SolverPosition& A = positions[pc.indexA];
        const SolverPosition& B = positions[pc.indexB];
        Vec2 C = B.c + pc.rB - A.c - pc.rA;  // rA, rB were set for this pose by preparePoint
        pc.bias = (pc.biasFactor * invDt) * C;
    }
}

template <bool withBias>
void solveVelocityGroup(PointConstraints& group, SolverVelocity* velocities) {
    for (PointConstraint& pc : group) {
        pc.impulse += solvePointVelocity(pc, velocities, withBias ? pc.bias : Vec2{});
    }
}

// PseudoVelocity: the velocity solve again, on velocities that only move positions.
void solvePseudoVelocityPass(PointConstraints& group, SolverPosition* positions,
                             std::vector<SolverVelocity>& pseudo, int iterations, float h) {
    if (group.empty()) return;
    std::fill(pseudo.begin(), pseudo.end(), SolverVelocity{});

    const float invH = 1.0f / h;
    for (PointConstraint& pc : group) {
        Vec2 C = preparePoint(pc, positions);
        pc.bias = (pc.biasFactor * invH) * C;
    }
    for (int it = 0; it < iterations; ++it) {
        for (const PointConstraint& pc : group) solvePointVelocity(pc, pseudo.data(), pc.bias);
    }
    // Bodies no pseudo-velocity joint touches have zero pseudo velocity: adding it is a no-op.
    for (std::size_t i = 0; i < pseudo.size(); ++i) {
        positions[i].c += h * pseudo[i].v;
        positions[i].a += h * pseudo[i].w;
    }
}

// NGS: one sweep of position-level solves. Returns the largest error before correction.
template <bool rebuildMass>
float solveNgsSweep(const PointConstraints& group, SolverPosition* positions) {
    float maxError = 0.0f;
    for (const PointConstraint& pc : group) {
        float error = solvePointPosition<rebuildMass>(pc, positions);
        // Written so a NaN error wins and can never pass for "within slop".
        if (!(error <= maxError)) maxError = error;
    }
    return maxError;
}

}  // namespace

void prepareVelocityBias(ConstraintGroups& groups, const SolverPosition* positions, float invDt) {
    prepareBaumgarteBias(groupOf(groups, PositionSolver::Baumgarte), positions, invDt);
}

void solveVelocitySweep(ConstraintGroups& groups, SolverVelocity* velocities) {
    solveVelocityGroup<true>(groupOf(groups, PositionSolver::Baumgarte), velocities);
    solveVelocityGroup<false>(groupOf(groups, PositionSolver::PseudoVelocity), velocities);
    solveVelocityGroup<false>(groupOf(groups, PositionSolver::ModifiedNGS), velocities);
    solveVelocityGroup<false>(groupOf(groups, PositionSolver::FullNGS), velocities);
}

PositionPhaseResult solvePositionPhase(ConstraintGroups& groups, const ContactSolver& contacts,
                                       SolverPosition* positions,
                                       std::vector<SolverVelocity>& pseudo, int iterations,
                                       float h) {
    solvePseudoVelocityPass(groupOf(groups, PositionSolver::PseudoVelocity), positions, pseudo,
                            iterations, h);

    PointConstraints& modified = groupOf(groups, PositionSolver::ModifiedNGS);
    PointConstraints& full = groupOf(groups, PositionSolver::FullNGS);
    PositionPhaseResult result;
    if (modified.empty() && full.empty() && !contacts.hasPositionConstraints()) {
        result.solved = true;
        return result;
    }

    // ModifiedNGS keeps the effective mass of the pose the position phase starts from.
    for (PointConstraint& pc : modified) preparePoint(pc, positions);

    while (result.sweeps < iterations) {
        ++result.sweeps;
        // Contacts first: a joint then has the last word on a body both move, and a joint's
        // error is the one users look at (as in Box2D 2.4.1's position loop).
        float minSeparation = contacts.solvePositions(positions);
        float error = solveNgsSweep<false>(modified, positions);
        float fullError = solveNgsSweep<true>(full, positions);
        if (!(fullError <= error)) error = fullError;
        if (ContactSolver::withinTolerance(minSeparation) && error <= kLinearSlop) {
            result.solved = true;
            break;
        }
    }
    return result;
}

}  // namespace pivot
