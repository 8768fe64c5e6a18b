// The two bodies a joint constraint acts on, as the solver sees them.
#pragma once

#include <cstdint>

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

}  // namespace pivot
