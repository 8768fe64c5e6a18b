#include "solver/position_solver.h"

#include <algorithm>

#include "pivot/constants.h"

namespace pivot {

namespace {

RevoluteConstraints& groupOf(ConstraintGroups& groups, PositionSolver solver) {
    return groups[static_cast<int>(solver)];
}

// Baumgarte: the joint's errors at the start of the step, fed back as velocities.
void prepareBaumgarteBias(RevoluteConstraints& group, const SolverPosition* positions,
                          float invDt) {
    for (RevoluteConstraint& c : group) {
        const SolverPosition& A = positions[c.bodies.indexA];
        const SolverPosition& B = positions[c.bodies.indexB];
        Vec2 C = B.c + c.point.rB - A.c - c.point.rA;  // rA, rB were set for this pose
        c.point.bias = (c.biasFactor * invDt) * C;
        prepareLimitBaumgarteBias(c.angle, c.biasFactor, invDt);
    }
}

template <bool withBias>
void solveVelocityGroup(RevoluteConstraints& group, SolverVelocity* velocities) {
    for (RevoluteConstraint& c : group) {
        solveRevoluteVelocity(c, velocities, withBias ? c.point.bias : Vec2{});
    }
}

// PseudoVelocity: the velocity solve again, on velocities that only move positions. The
// velocity phase's impulses are stored by now, so its accumulators and bias fields are free to
// hold the pass's own (which start at zero: no warm start).
void solvePseudoVelocityPass(RevoluteConstraints& group, SolverPosition* positions,
                             std::vector<SolverVelocity>& pseudo, int iterations, float h) {
    if (group.empty()) return;
    std::fill(pseudo.begin(), pseudo.end(), SolverVelocity{});

    const float invH = 1.0f / h;
    for (RevoluteConstraint& c : group) {
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
    for (int it = 0; it < iterations; ++it) {
        for (RevoluteConstraint& c : group) {
            solveAngleVelocity<false>(c.bodies, c.angle, pseudo.data());
            solvePointVelocity(c.bodies, c.point, pseudo.data(), c.point.bias);
        }
    }
    // Bodies no pseudo-velocity joint touches have zero pseudo velocity: adding it is a no-op.
    for (std::size_t i = 0; i < pseudo.size(); ++i) {
        positions[i].c += h * pseudo[i].v;
        positions[i].a += h * pseudo[i].w;
    }
}

// NGS: one sweep of position-level solves. Returns whether every joint was within slop.
template <bool rebuildMass>
bool solveNgsSweep(const RevoluteConstraints& group, SolverPosition* positions) {
    bool withinSlop = true;
    for (const RevoluteConstraint& c : group) {
        // Evaluated for every joint: each solve moves the bodies, whatever the others report.
        bool ok = solveRevolutePosition<rebuildMass>(c, positions);
        withinSlop = withinSlop && ok;
    }
    return withinSlop;
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

    RevoluteConstraints& modified = groupOf(groups, PositionSolver::ModifiedNGS);
    RevoluteConstraints& full = groupOf(groups, PositionSolver::FullNGS);
    PositionPhaseResult result;
    if (modified.empty() && full.empty() && !contacts.hasPositionConstraints()) {
        result.solved = true;
        return result;
    }

    // ModifiedNGS keeps the effective mass of the pose the position phase starts from.
    for (RevoluteConstraint& c : modified) preparePoint(c.bodies, c.point, positions);

    while (result.sweeps < iterations) {
        ++result.sweeps;
        // Contacts first: a joint then has the last word on a body both move, and a joint's
        // error is the one users look at (as in Box2D 2.4.1's position loop).
        float minSeparation = contacts.solvePositions(positions);
        bool modifiedOk = solveNgsSweep<false>(modified, positions);
        bool fullOk = solveNgsSweep<true>(full, positions);
        if (ContactSolver::withinTolerance(minSeparation) && modifiedOk && fullOk) {
            result.solved = true;
            break;
        }
    }
    return result;
}

}  // namespace pivot
