#include "model/body.h"

#include <algorithm>
#include <cmath>

namespace pivot {

namespace {

// Calls f(shape) for each shape the body would have after `change`, in list order (a shape
// being attached first, as it becomes the head of the list): the order the mass sums are formed
// in, so that a change checked beforehand gives the bits the change itself will.
template <typename F>
void forEachShapeAfter(const Body& body, const SlotPool<Shape>& shapes, const MassChange& change,
                       F&& f) {
    if (change.added) f(*change.added);
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        if (s == change.removed) continue;
        if (s == change.reweighed) {
            Shape reweighed = shapes[s];
            reweighed.density = change.density;
            f(reweighed);
        } else {
            f(shapes[s]);
        }
    }
}

}  // namespace

void updateBodyMass(Body& body, const SlotPool<Shape>& shapes) {
    body = bodyAfterMassChange(body, shapes, MassChange{body.type});
    restartSweep(body);
}

Body bodyAfterMassChange(const Body& before, const SlotPool<Shape>& shapes,
                         const MassChange& change) {
    Body body = before;
    body.type = change.type;
    body.mass = 0.0f;
    body.invMass = 0.0f;
    body.inertia = 0.0f;
    body.invInertia = 0.0f;
    body.localCenter = Vec2{};
    body.minExtent = 0.0f;
    body.maxExtent = 0.0f;

    if (body.type != BodyType::Dynamic) {
        // Without mass the centre is the origin. When it moves there (a dynamic body made
        // kinematic), a kinematic body's velocity follows the origin, so its motion does not
        // jump. A static body has no velocity to adjust, and must not get one from a centre
        // that a diverged solver left non-finite.
        Vec2 oldCenter = body.center;
        body.center = body.xf.p;
        if (body.type == BodyType::Kinematic && body.center != oldCenter) {
            body.linearVelocity += cross(body.angularVelocity, body.center - oldCenter);
        }
        return body;
    }

    // Sum the shapes' mass and their second moments about the body origin.
    float inertiaAboutOrigin = 0.0f;
    Vec2 weightedCenter;
    forEachShapeAfter(before, shapes, change, [&](const Shape& shape) {
        if (shape.density == 0.0f) return;
        OriginMass m = shapeMassAboutOrigin(shape);
        body.mass += m.mass;
        weightedCenter += m.mass * m.center;
        inertiaAboutOrigin += m.inertia;
    });

    if (body.mass > 0.0f) {
        body.invMass = 1.0f / body.mass;
        body.localCenter = body.invMass * weightedCenter;
    } else {
        // A dynamic body without shapes moves as a unit point mass, so forces and joints still
        // act on it sensibly (createShape rejects a zero-density shape on a dynamic body).
        body.mass = 1.0f;
        body.invMass = 1.0f;
    }

    if (inertiaAboutOrigin > 0.0f && !body.fixedRotation) {
        // The reference's way: shift the second moment about the origin to the centre of mass.
        // Kept for its bits (docs/reference-agreement.md), but when the shapes sit far from the
        // origin the two terms are huge and nearly equal, and their difference is rounding noise
        // (a circle 1e5 m out got a zero or negative inertia, and the body went NaN). The sum
        // of each shape's own inertia and its offset from the centre of mass has no such
        // cancellation; it replaces the reference's value when the two disagree.
        float shifted = inertiaAboutOrigin - body.mass * dot(body.localCenter, body.localCenter);
        float direct = 0.0f;
        forEachShapeAfter(before, shapes, change, [&](const Shape& shape) {
            if (shape.density == 0.0f) return;
            OriginMass m = shapeMassAboutOrigin(shape);
            Vec2 offset = m.center - body.localCenter;
            direct += m.centroidInertia + m.mass * dot(offset, offset);
        });
        const float tolerance = 1e-4f;  // far above rounding in the reference's own scenes
        bool accurate = shifted > 0.0f && std::fabs(shifted - direct) <= tolerance * direct;
        body.inertia = accurate ? shifted : direct;
        if (body.inertia > 0.0f) {
            body.invInertia = 1.0f / body.inertia;
        } else {
            body.inertia = 0.0f;  // no area to turn: the body does not rotate
        }
    }

    bool first = true;
    forEachShapeAfter(before, shapes, change, [&](const Shape& shape) {
        const ShapeExtent extent = shapeExtent(shape, body.localCenter);
        body.minExtent = first ? extent.min : std::min(body.minExtent, extent.min);
        body.maxExtent = std::max(body.maxExtent, extent.max);
        first = false;
    });

    Vec2 oldCenter = body.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.linearVelocity += cross(body.angularVelocity, body.center - oldCenter);
    return body;
}

bool holdAtWorldEdge(Body& body) {
    const Vec2 origin = body.xf.p;
    const Vec2 held{std::fmin(std::fmax(origin.x, -kMaxCoordinate), kMaxCoordinate),
                    std::fmin(std::fmax(origin.y, -kMaxCoordinate), kMaxCoordinate)};
    if (held.x == origin.x && held.y == origin.y) return false;
    // The origin is set exactly on the edge and the centre follows it, so that reading the
    // position back gives a value the API accepts.
    body.xf.p = held;
    body.center = flushDenormal(held + rotate(body.xf.q, body.localCenter));
    Vec2& v = body.linearVelocity;
    if ((held.x < origin.x && v.x > 0.0f) || (held.x > origin.x && v.x < 0.0f)) v.x = 0.0f;
    if ((held.y < origin.y && v.y > 0.0f) || (held.y > origin.y && v.y < 0.0f)) v.y = 0.0f;
    body.heldAtEdge = true;
    body.edgeReached = origin;
    return true;
}

}  // namespace pivot
