// Gear joint storage: the geometry of the two joints a gear couples, copied when it is created
// (neither can be destroyed while the gear stands, and their anchors, axes and reference angles
// never change), the ratio and constant, and the accumulated impulse (the alternative of
// Joint::data for a gear joint). gear_constraint.h has the maths.
#pragma once

#include <cmath>
#include <cstdint>

#include "model/body.h"
#include "pivot/math.h"

namespace pivot {

/// One joint of the two a gear couples, as the gear sees it: a base body (the joint's body A)
/// and a moving body (its body B), and the joint's coordinate.
struct GearSide {
    bool prismatic = false;   // else revolute
    std::int32_t joint = -1;  // the joint's pool index
    std::int32_t base = -1;   // the pool index of the joint's body A
    Vec2 localAnchorBase;     // origin-relative, in the base's frame
    Vec2 localAnchorMover;    // origin-relative, in the moving body's frame
    Vec2 localAxis;           // prismatic: unit, in the base's frame
    float referenceAngle = 0.0f;

    /// The joint's coordinate with the bodies where they are: rad (a revolute joint's angle)
    /// or m (a prismatic joint's translation).
    float coordinate(const Body& base, const Body& mover) const {
        if (!prismatic) return mover.angle - base.angle - referenceAngle;
        const Vec2 offset = rotate(mover.xf.q, localAnchorMover) + (mover.xf.p - base.xf.p);
        return dot(inverseRotate(base.xf.q, offset) - localAnchorBase, localAxis);
    }
};

struct GearJoint {
    GearSide side1;  // joint1: its moving body is the gear's body A
    GearSide side2;  // joint2: its moving body is the gear's body B
    float ratio = 1.0f;
    // coordinate1 + ratio coordinate2 when created (World::setGearJointRatio chooses it again,
    // keeping C).
    float constant = 0.0f;

    float impulse = 0.0f;  // accumulated: N m s if joint1 is revolute, N s if prismatic
    Vec2 linearB;          // body B's Jacobian row when last solved (reactions)
    float angularB = 0.0f;

    /// C = coordinate1 + ratio coordinate2 - constant, in joint1's units.
    float error(const Body& a, const Body& b, const Body& c, const Body& d) const {
        return (side1.coordinate(c, a) + ratio * side2.coordinate(d, b)) - constant;
    }
    bool hasFiniteReactions(float invDt) const {
        return std::isfinite(invDt * impulse) && isFinite((invDt * impulse) * linearB) &&
               std::isfinite((invDt * impulse) * angularB);
    }
    void clearImpulses() {
        impulse = 0.0f;
        linearB = Vec2{};  // rows measured in a diverged island or substep may not be finite
        angularB = 0.0f;
    }
};

}  // namespace pivot
