// Body definitions. A body is a rigid frame with mass; shapes attached to it give it that
// mass (see shape.h). Bodies are created by World::createBody and referred to by BodyId.
#pragma once

#include <cstdint>

#include "pivot/math.h"

namespace pivot {

enum class BodyType : std::uint8_t {
    Static,     ///< never moves; infinite mass
    Kinematic,  ///< moves by its velocity only; infinite mass, ignores forces and gravity
    Dynamic,    ///< moved by forces, gravity, joints and contacts
};

/// Everything needed to create a body. Defaults give a static body at the origin.
struct BodyDef {
    BodyType type = BodyType::Static;
    Vec2 position;                 ///< m, world position of the body origin
    float angle = 0.0f;            ///< rad
    Vec2 linearVelocity;           ///< m/s, of the body origin; within +-kMaxSpeed
    float angularVelocity = 0.0f;  ///< rad/s, within +-kMaxAngularSpeed
    /// 1/s. Velocities are scaled by 1/(1 + h*damping) each step; 0 keeps energy.
    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;  ///< multiplies the world gravity for this body; +-kMaxGravityScale
    /// Infinite rotational inertia: the body never turns (angularVelocity must then be 0).
    bool fixedRotation = false;
    /// May sleep once at rest (WorldDef::enableSleep switches sleeping for the whole world).
    bool allowSleep = true;
    bool isAwake = true;  ///< false creates the body asleep until something wakes it
    /// Continuous collision (WorldDef::enableContinuous): a dynamic body that would pass through
    /// static or kinematic geometry within a step is stopped at the moment it touches. false
    /// leaves this body to the discrete step alone (cheaper; fast bodies may then tunnel).
    bool continuous = true;
    /// A bullet is also kept from tunnelling through other dynamic bodies (each bullet costs a
    /// time of impact per nearby dynamic shape per step). Needs `continuous`.
    bool bullet = false;
    std::uint64_t userData = 0;  ///< yours; pivot2d never reads it
};

/// Mass properties of a shape or body, about the centre of mass.
struct MassData {
    float mass = 0.0f;               ///< kg
    Vec2 center;                     ///< m, centre of mass in the body (or shape) frame
    float rotationalInertia = 0.0f;  ///< kg m^2, about the centre of mass
};

}  // namespace pivot
