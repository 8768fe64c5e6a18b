// The two bodies a joint constraint acts on, as the solver sees them.
#pragma once

#include <cstdint>

#include "constraints/solver_body.h"

namespace pivot {

struct ConstraintBodies {
    std::int32_t indexA = 0;  // solver indices
    std::int32_t indexB = 0;
    float mA = 0.0f, mB = 0.0f;  // inverse masses
    float iA = 0.0f, iB = 0.0f;  // inverse rotational inertias

    /// No rotation possible about the joint (both bodies static, kinematic or fixed-rotation):
    /// the angle part has nothing to act on.
    bool fixedRotation() const { return iA + iB == 0.0f; }
};

/// The constraint's view of bodies a and b, in solver slots slots[0] and slots[1] (their
/// inputs are the solver's copy, read in slot order, where the bodies are scattered in their pool).
inline ConstraintBodies constraintBodies(const JointSlots& slots, const SolverBodyInputs& a,
                                         const SolverBodyInputs& b) {
    ConstraintBodies bodies;
    bodies.indexA = slots[0];
    bodies.indexB = slots[1];
    bodies.mA = a.invMass;
    bodies.mB = b.invMass;
    bodies.iA = a.invInertia;
    bodies.iB = b.invInertia;
    return bodies;
}

}  // namespace pivot
