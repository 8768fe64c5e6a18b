// Revolute joint storage: what persists between steps. The per-step solver state lives in
// PointConstraint (point_constraint.h), built afresh for each island each step.
#pragma once

#include <cstdint>

#include "body_edge.h"
#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

struct RevoluteJoint {
    BodyEdge edges[2];  // edges[0].body is body A, edges[1].body is body B
    Vec2 localAnchorA;   // origin-relative, in body A's frame
    Vec2 localAnchorB;
    float referenceAngle = 0.0f;
    PositionSolver solver = PositionSolver::FullNGS;
    bool hasBiasOverride = false;
    float biasOverride = 0.0f;
    bool collideConnected = false;
    std::uint64_t userData = 0;
    Vec2 impulse;  // accumulated point impulse of the last step solved, N s (warm starting)
    float impulseInvDt = 0.0f;  // 1/dt of that step: impulse * impulseInvDt is the force

    std::int32_t bodyA() const { return edges[0].body; }
    std::int32_t bodyB() const { return edges[1].body; }
    float biasFactor() const { return hasBiasOverride ? biasOverride : defaultBiasFactor(solver); }
};

}  // namespace pivot
