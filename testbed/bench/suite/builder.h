// The benchmark scenes are written once, against this interface, and each engine (pivot2d,
// Box2D 2.4.1, Box2D v3) implements it: what a scene asks for is the same in all of them, and
// where an engine lacks a feature its builder says how it stands in (Box2D 2.4.1 has no
// capsules and no rounded polygons; see box2d_engine.cpp).
//
// Units are SI, angles in radians, everything in world coordinates except shapes, which are in
// their body's frame. Bodies and joints are named by the handle their builder returns.
#pragma once

#include <cstdint>
#include <vector>

#include "pivot/math.h"

namespace pivot::bench {

enum class Motion : std::uint8_t { Static, Kinematic, Dynamic };

struct BodySpec {
    Motion motion = Motion::Dynamic;
    Vec2 position;
    Vec2 velocity;
    float linearDamping = 0.0f;
    bool awake = true;       ///< false: created asleep (when the scene lets bodies sleep)
    bool allowSleep = true;  ///< false: this body never sleeps
};

/// What a shape is made of, and which shapes it touches (each one's category in the other's
/// mask, and no shared negative group).
struct Material {
    float density = 1.0f;
    float friction = 0.6f;
    float restitution = 0.0f;
    std::uint16_t category = 0x0001;
    std::uint16_t mask = 0xFFFF;
    std::int16_t group = 0;
};

/// A revolute joint pinning two bodies at a world point, as they are posed when it is made.
struct PinSpec {
    int bodyA = -1;
    int bodyB = -1;
    Vec2 pivot;                   ///< world point
    float referenceAngle = 0.0f;  ///< angleB - angleA at which the joint angle is zero
    bool limit = false;
    float lower = 0.0f, upper = 0.0f;
    bool motor = false;
    float motorSpeed = 0.0f;  ///< rad/s
    float maxMotorTorque = 0.0f;
};

class Builder {
public:
    virtual ~Builder() = default;

    virtual void setGravity(Vec2 gravity) = 0;
    /// A new body's handle: 0, 1, 2, ... in creation order, never reused.
    virtual int body(const BodySpec& spec) = 0;
    virtual void destroyBody(int body) = 0;  ///< and its shapes and joints

    virtual void circle(int body, Vec2 center, float radius, const Material& material) = 0;
    /// A box of half extents (hx, hy) centred at `center`, turned by `angle`.
    virtual void box(int body, float hx, float hy, Vec2 center, float angle,
                     const Material& material) = 0;
    /// A box of core half extents (hx, hy) at the origin with its corners rounded by `radius`
    /// (it spans hx + radius by hy + radius).
    virtual void roundedBox(int body, float hx, float hy, float radius,
                            const Material& material) = 0;
    /// The convex hull of `points`, rounded by `radius` (0: sharp).
    virtual void polygon(int body, const std::vector<Vec2>& points, float radius,
                         const Material& material) = 0;
    virtual void capsule(int body, Vec2 center1, Vec2 center2, float radius,
                         const Material& material) = 0;
    /// A two-sided segment (static bodies only).
    virtual void segment(int body, Vec2 point1, Vec2 point2, const Material& material) = 0;
    /// A closed chain through `points`, solid on the side its winding puts on its right (the
    /// inside of a clockwise loop).
    virtual void loop(int body, const std::vector<Vec2>& points, const Material& material) = 0;

    /// Its handle: 0, 1, 2, ... in creation order.
    virtual int pin(const PinSpec& spec) = 0;
    /// The joint angle (angleB - angleA - referenceAngle) of a pin made by pin().
    virtual float pinAngle(int joint) = 0;

    /// m: how far apart the cores of two polygons resting on each other settle in this engine.
    /// pivot2d and Box2D 2.4.1 give polygons a collision skin (kPolygonRadius) and let contacts
    /// sink a slop into it; Box2D v3's polygons have none. Stacks are laid this far apart, so
    /// every engine starts them at rest instead of pushing overlapping skins apart.
    virtual float restGap() const = 0;
};

}  // namespace pivot::bench
