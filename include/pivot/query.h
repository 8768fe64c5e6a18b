// Asking the world what is where: ray casts, box, point and shape overlap queries and shape
// casts, on one shape or on every shape of a World (World::castRay, castRayClosest, queryAABB,
// queryPoint, queryShape, castShape, castShapeClosest). The world's queries walk the broad
// phase's tree, so each costs about log(shapes) plus what it finds, and none allocates.
#pragma once

#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>

#include "pivot/id.h"
#include "pivot/math.h"
#include "pivot/shape.h"

namespace pivot {

/// Which shapes a query sees: a shape is seen when its Filter::categoryBits share a bit with
/// maskBits and its Filter::maskBits share one with categoryBits (the rule two shapes use to
/// decide whether they collide, with the query as the other shape; groups play no part). The
/// default sees every shape.
struct QueryFilter {
    std::uint16_t categoryBits = 0xFFFF;
    std::uint16_t maskBits = 0xFFFF;
};

/// Where a ray first enters a shape (or a cast shape first touches one: World::castShape). A ray
/// from origin through origin + translation; a ray that starts inside a shape does not hit it
/// (it never enters).
struct RayHit {
    ShapeId shape;          ///< the shape hit (null from the single-shape rayCast functions)
    Vec2 point;             ///< m, in world coordinates
    Vec2 normal;            ///< the shape's outward unit normal at `point`
    float fraction = 0.0f;  ///< point = origin + fraction * translation, in [0, 1]
};

/// The functions on one shape take its transform `xf` as World's queries do: a position within
/// kMaxCoordinate and a unit rotation (within kMaxRotationError; build it with Rot(angle)), or
/// they throw pivot::Error.
///
/// A ray against one circle at transform `xf`. No hit when the ray misses, starts inside, or
/// has a zero translation.
std::optional<RayHit> rayCast(const Circle& circle, const Transform& xf, Vec2 origin,
                              Vec2 translation);
/// A ray against one convex polygon (checked as World::createShape checks it: a polygon it
/// would refuse throws pivot::Error) at transform `xf`. The polygon's thin collision skin
/// (kPolygonRadius) is not part of it here, as in every query.
std::optional<RayHit> rayCast(const Polygon& polygon, const Transform& xf, Vec2 origin,
                              Vec2 translation);

/// A ray against one segment at transform `xf` (checked as World::createShape checks it); the
/// normal faces the side the ray comes from. A ray along the segment's line does not hit it.
std::optional<RayHit> rayCast(const Segment& segment, const Transform& xf, Vec2 origin,
                              Vec2 translation);
/// A ray against one capsule (checked as World::createShape checks it).
std::optional<RayHit> rayCast(const Capsule& capsule, const Transform& xf, Vec2 origin,
                              Vec2 translation);
/// A ray against one chain segment (checked as World::createShape checks it): only from its
/// solid side, the right of point1 -> point2; a ray from behind passes through.
std::optional<RayHit> rayCast(const ChainSegment& segment, const Transform& xf, Vec2 origin,
                              Vec2 translation);

/// Whether a point (world coordinates) lies inside, or on the boundary of, a shape at `xf`. (A
/// segment has no inside: World::queryPoint never reports one.)
bool testPoint(const Circle& circle, const Transform& xf, Vec2 point);
bool testPoint(const Polygon& polygon, const Transform& xf, Vec2 point);
bool testPoint(const Capsule& capsule, const Transform& xf, Vec2 point);

/// A non-owning reference to a callable, so a query can take a lambda without allocating
/// (std::function may). It must not outlive the callable it refers to: pass it straight on.
template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
public:
    template <typename F,
              typename = std::enable_if_t<!std::is_same_v<std::decay_t<F>, FunctionRef> &&
                                          std::is_invocable_r_v<R, F&, Args...>>>
    FunctionRef(F&& f)  // NOLINT: implicit, so a lambda can be passed where one is expected
        : object_(const_cast<void*>(static_cast<const void*>(&f))),
          call_([](void* object, Args... args) -> R {
              return (*static_cast<std::remove_reference_t<F>*>(object))(
                  std::forward<Args>(args)...);
          }) {}

    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

private:
    void* object_;
    R (*call_)(void*, Args...);
};

/// What a ray cast's callback returns for each hit, which decides how the cast goes on:
///  - a negative value: ignore this shape, as if the ray had missed it;
///  - 0 (or NaN): stop the cast here;
///  - a value in (0, 1]: go on, but only as far as that fraction of the translation (returning
///    hit.fraction keeps only closer hits coming; returning 1 reports every shape on the ray).
/// Hits come in the tree's order, not by distance.
using RayCallback = FunctionRef<float(const RayHit&)>;
/// A box or point query's callback: called once per shape found; return false to stop.
using ShapeCallback = FunctionRef<bool(ShapeId)>;

}  // namespace pivot
