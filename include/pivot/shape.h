// Collision shapes and their mass. A shape belongs to one body; its density, spread over its
// area, gives the body its mass, centre of mass and rotational inertia.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "pivot/body.h"
#include "pivot/constants.h"
#include "pivot/math.h"

namespace pivot {

enum class ShapeType : std::uint8_t { Circle, Polygon, Segment, ChainSegment, Capsule };

/// A solid disc.
struct Circle {
    Vec2 center;          ///< m, in the body frame
    float radius = 0.5f;  ///< m, in [kLinearSlop, kMaxCoordinate]
};

/// A solid capsule: every point within `radius` of the segment from center1 to center2 (a
/// rectangle with a half disc at each end); for limbs, characters, rounded rods. Centres within
/// kMaxCoordinate and at least kLinearSlop apart (closer, make it a Circle), radius in
/// [kLinearSlop, kMaxCoordinate]. It collides with its radius plus the polygons' thin skin
/// (kPolygonRadius), like a rounded polygon.
struct Capsule {
    Vec2 center1;
    Vec2 center2;
    float radius = 0.25f;
};

/// A solid convex polygon of 3 to kMaxPolygonVertices vertices in the body frame, in either
/// winding. World::createShape checks it (convex, edges at least kLinearSlop long, no
/// collinear vertices, coordinates within kMaxCoordinate) and stores it counter-clockwise.
struct Polygon {
    std::array<Vec2, kMaxPolygonVertices> vertices{};
    int count = 0;
    /// m, in [0, kMaxCoordinate]: a rounded polygon, every point within `radius` of the
    /// polygon above (its corners become arcs, its edges move out by `radius`). Its mass
    /// includes the rounding. It collides with the same thin skin beyond (kPolygonRadius) as
    /// any polygon.
    float radius = 0.0f;

    /// An axis-aligned box of the given half extents (m, in (0, kMaxCoordinate]), centred on the
    /// body origin. Other arguments throw pivot::Error.
    static Polygon box(float halfWidth, float halfHeight);
    /// A box of the given half extents, centred at `center` and turned by `angle` (rad).
    static Polygon box(float halfWidth, float halfHeight, Vec2 center, float angle);
    /// A box whose corners are rounded by `radius`: its core has the half extents less the
    /// radius, so the whole shape spans the given half extents (each must exceed the radius by
    /// at least kLinearSlop / 2).
    static Polygon roundedBox(float halfWidth, float halfHeight, float radius);
    /// A polygon from its vertices. More than kMaxPolygonVertices throws pivot::Error.
    static Polygon fromPoints(std::initializer_list<Vec2> points);
    /// The convex hull of a cloud of points (any number, any order), counter-clockwise, made
    /// valid for World::createShape: points closer than kLinearSlop are merged and points on
    /// (or within a tenth of the slop of) the line between their neighbours are dropped. Throws
    /// pivot::Error for a point that is not finite or outside kMaxCoordinate, for fewer than 3
    /// points, for a cloud with no area (all on one line, or all within the slop of each other)
    /// and for a hull of more than kMaxPolygonVertices corners (simplify the cloud first).
    static Polygon convexHull(const Vec2* points, int count);
    static Polygon convexHull(std::initializer_list<Vec2> points);
};

/// A line segment between two points in the body frame, solid from both sides (a wall, a
/// floor, a ramp), with the same thin collision skin as a polygon (kPolygonRadius). It has no
/// area and so no mass: it belongs on a static or kinematic body (World::createShape refuses a
/// dynamic one, and World::setBodyType refuses to make its body dynamic). Its points are within
/// kMaxCoordinate and at least kLinearSlop apart. Segments do not collide with each other.
struct Segment {
    Vec2 point1;
    Vec2 point2;
};

/// A one-sided segment with its neighbours: what a chain is made of (World::createChain), and
/// what World::createShape makes on its own. It is solid only on its right looking from
/// segment.point1 to segment.point2: a shape whose centre is behind it passes through. The
/// ghosts are the chain's points before point1 and after point2; they are not part of the
/// shape, but a body sliding across a join of two segments does not catch on the corner
/// because each segment knows its neighbour's direction. Otherwise as a Segment: no mass, on a
/// static or kinematic body, not colliding with other segments. Each point within
/// kMaxCoordinate, each at least kLinearSlop from the next (ghost1, point1, point2, ghost2).
struct ChainSegment {
    Vec2 ghost1;
    Segment segment;
    Vec2 ghost2;
};

/// A polyline of one-sided segments, for terrain (World::createChain). Each segment is solid on
/// its right looking along the chain: list a floor's points from right to left, a closed loop
/// counter-clockwise to keep bodies outside it, clockwise to keep them inside.
struct Chain {
    std::vector<Vec2> points;
    /// A closed loop joins the last point to the first: n points make n segments (n >= 3). An
    /// open chain's first and last points are ghosts only, the directions its ends continue in
    /// (a body slides off an end as off a join): n points make n - 3 segments (n >= 4).
    bool loop = false;
};

/// Which shapes may touch. Two shapes collide when each one's category is in the other's mask,
/// unless they share a non-zero group: then a positive group always collides and a negative
/// group never does.
struct Filter {
    std::uint16_t categoryBits = 0x0001;
    std::uint16_t maskBits = 0xFFFF;
    std::int16_t groupIndex = 0;
};

/// Everything a shape needs besides its geometry.
struct ShapeDef {
    /// kg/m^2: 0, or in [kMinDensity, kMaxDensity]. Every shape of a dynamic body has a density
    /// > 0 (createShape, setShapeDensity and setBodyType refuse to break that).
    float density = 1.0f;
    /// Coulomb coefficient, in [0, kMaxFriction]. A contact uses sqrt(frictionA * frictionB).
    float friction = 0.6f;
    /// Bounce, in [0, 1]. A contact uses max(restitutionA, restitutionB), and bounces only when
    /// it closes faster than WorldDef::restitutionThreshold.
    float restitution = 0.0f;
    Filter filter;
    std::uint64_t userData = 0;
    /// A sensor detects overlaps and never pushes: it reports World::sensorBeginEvents and
    /// sensorEndEvents for the shapes it overlaps (on any body type, as long as one of the two
    /// bodies is not static; filtering applies; two sensors do not detect each other), and
    /// takes no part in contacts, islands or continuous collision. Its density still counts in
    /// its body's mass.
    bool isSensor = false;
    /// Report World::contactHitEvents for this shape's contacts: touching begun or kept with an
    /// approach faster than WorldDef::hitEventThreshold (a crash sound, damage). Off by default:
    /// most shapes need none.
    bool enableHitEvents = false;
    /// Ask World::setPreSolveCallback's callback about this shape's touching contacts before
    /// each step solves them (a one-way platform sets it). Off by default.
    bool enablePreSolve = false;
};

/// Mass properties of a circle of the given density (kg/m^2). A circle or density that
/// World::createShape would refuse throws pivot::Error.
MassData computeMass(const Circle& circle, float density);
/// Mass properties of a capsule of the given density (kg/m^2). A capsule or density that
/// World::createShape would refuse throws pivot::Error.
MassData computeMass(const Capsule& capsule, float density);
/// Mass properties of a convex polygon (either winding) of the given density (kg/m^2). A
/// polygon or density that World::createShape would refuse throws pivot::Error.
MassData computeMass(const Polygon& polygon, float density);

}  // namespace pivot
