// Debug drawing: World::debugDraw describes the world to an interface the game implements with
// its own renderer (pivot::DebugDraw), with options to choose what is drawn. The testbed's SVG
// figures and its HTML replay draw through it (testbed/report, testbed/replay).
#pragma once

#include "pivot/id.h"
#include "pivot/joint.h"
#include "pivot/math.h"

namespace pivot {

/// A colour, each channel in [0, 1].
struct DebugColor {
    float r = 1.0f;
    float g = 1.0f;
    float b = 1.0f;
    friend bool operator==(DebugColor x, DebugColor y) {
        return x.r == y.r && x.g == y.g && x.b == y.b;
    }
    friend bool operator!=(DebugColor x, DebugColor y) { return !(x == y); }
};

/// The colours World::debugDraw uses, by what a shape's body is doing or what is drawn.
namespace debug_colors {
constexpr DebugColor kStatic{0.55f, 0.58f, 0.62f};
constexpr DebugColor kKinematic{0.45f, 0.55f, 0.95f};
constexpr DebugColor kDynamic{0.95f, 0.75f, 0.45f};
constexpr DebugColor kSleeping{0.62f, 0.62f, 0.55f};
constexpr DebugColor kSensor{0.35f, 0.85f, 0.45f};
constexpr DebugColor kJoint{0.30f, 0.75f, 0.80f};
constexpr DebugColor kSeparatedJoint{0.90f, 0.20f, 0.20f};  ///< anchors over 1 mm apart
constexpr DebugColor kLetGoJoint{0.55f, 0.40f, 0.40f};
constexpr DebugColor kAABB{0.80f, 0.40f, 0.80f};
constexpr DebugColor kContactPoint{0.95f, 0.25f, 0.20f};
constexpr DebugColor kContactNormal{0.90f, 0.90f, 0.30f};
constexpr DebugColor kCenterOfMass{0.20f, 0.20f, 0.20f};
}  // namespace debug_colors

/// What World::debugDraw draws.
struct DebugDrawOptions {
    bool shapes = true;           ///< every shape, coloured by its body's state (debug_colors)
    bool joints = true;           ///< every joint (mouse joints aside) with its anchors
    bool aabbs = false;           ///< each shape's broad-phase box (World::shapeAABB)
    bool contactPoints = false;   ///< each touching contact's points
    bool contactNormals = false;  ///< and its normal, as a segment of normalLength at each point
    bool centersOfMass = false;   ///< each non-static body's centre of mass and axes
    float normalLength = 0.3f;    ///< m
};

/// Implemented by the game. Coordinates are world coordinates in metres, y up, unless a call
/// says otherwise. The three calls with a default body are conveniences that draw with the
/// primitives; override them to draw those things your way.
class DebugDraw {
public:
    virtual ~DebugDraw() = default;

    /// A closed outline (a box, say).
    virtual void drawPolygon(const Vec2* vertices, int count, DebugColor color) = 0;
    /// A filled convex polygon, counter-clockwise, rounded by `radius` (0: sharp corners).
    virtual void drawSolidPolygon(const Vec2* vertices, int count, float radius,
                                  DebugColor color) = 0;
    /// A filled disc; `axis` is a unit vector that turns with the body, to show rotation.
    virtual void drawSolidCircle(Vec2 center, float radius, Vec2 axis, DebugColor color) = 0;
    /// A filled capsule: every point within `radius` of the segment from center1 to center2.
    virtual void drawSolidCapsule(Vec2 center1, Vec2 center2, float radius, DebugColor color) = 0;
    virtual void drawSegment(Vec2 p1, Vec2 p2, DebugColor color) = 0;
    /// A dot of `size` pixels.
    virtual void drawPoint(Vec2 p, float size, DebugColor color) = 0;

    /// A frame: its x axis red, its y axis green, `axisLength` m long.
    virtual void drawTransform(const Transform& xf, float axisLength);
    /// A joint: `anchorA` and `anchorB` are its anchors on body A and body B (World::jointAnchorA,
    /// jointAnchorB); `separation` is World::jointSeparation; `color` says whether it holds
    /// (debug_colors::kJoint), has come apart by over 1 mm (kSeparatedJoint) or is let go
    /// (kLetGoJoint). By default: a segment between the anchors and a dot on each.
    virtual void drawJoint(JointId joint, JointType type, Vec2 anchorA, Vec2 anchorB,
                           float separation, DebugColor color);
};

}  // namespace pivot
