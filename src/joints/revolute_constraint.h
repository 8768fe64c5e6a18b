// The revolute joint as the solver sees it for one step: its two bodies, the point part and the
// angle part (motor and limits). Built from the joint each step (island_solver.cpp) into the
// group of its PositionSolver.
#pragma once

#include <cstdint>

#include "constraints/angle_part.h"
#include "constraints/constraint_bodies.h"
#include "constraints/point_part.h"

namespace pivot {

struct RevoluteConstraint {
    ConstraintBodies bodies;
    PointPart point;
    AnglePart angle;
    float biasFactor = 0.0f;
    std::int32_t jointIndex = 0;  // where the impulses are stored back
};

/// Applies the accumulated impulses (already scaled for this step) to the velocities.
inline void warmStart(const RevoluteConstraint& c, SolverVelocity* velocities) {
    const ConstraintBodies& b = c.bodies;
    SolverVelocity& A = velocities[b.indexA];
    SolverVelocity& B = velocities[b.indexB];
    Vec2 P = c.point.impulse;
    float axial = c.angle.axialImpulse();
    A.v -= b.mA * P;
    A.w -= b.iA * (cross(c.point.rA, P) + axial);
    B.v += b.mB * P;
    B.w += b.iB * (cross(c.point.rB, P) + axial);
}

/// One velocity solve: motor, limits, then the pin (it gets the last word: a joint that comes
/// apart is worse than one that turns a little too far).
inline void solveRevoluteVelocity(RevoluteConstraint& c, SolverVelocity* velocities,
                                  Vec2 pointBias) {
    solveAngleVelocity(c.bodies, c.angle, velocities);
    c.point.impulse += solvePointVelocity(c.bodies, c.point, velocities, pointBias);
}

/// One NGS solve: the limit, then the pin. Returns whether both ended the solve within slop as
/// measured before their corrections (|C| <= kLinearSlop, limit error <= kAngularSlop).
template <bool rebuildMass>
inline bool solveRevolutePosition(const RevoluteConstraint& c, SolverPose* positions) {
    float angularError = solveLimitPosition(c.bodies, c.angle, positions, c.biasFactor);
    float linearError = solvePointPosition<rebuildMass>(c.bodies, c.point, positions, c.biasFactor);
    return linearError <= kLinearSlop && angularError <= kAngularSlop;
}

}  // namespace pivot
