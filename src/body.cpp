#include "body.h"

#include <cmath>

namespace pivot {

void updateBodyMass(Body& body, const SlotPool<Shape>& shapes) {
    body.mass = 0.0f;
    body.invMass = 0.0f;
    body.inertia = 0.0f;
    body.invInertia = 0.0f;
    body.localCenter = Vec2{};

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
        return;
    }

    // Sum the shapes' mass and their second moments about the body origin.
    float inertiaAboutOrigin = 0.0f;
    Vec2 weightedCenter;
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        const Shape& shape = shapes[s];
        if (shape.density == 0.0f) continue;
        OriginMass m = shapeMassAboutOrigin(shape);
        body.mass += m.mass;
        weightedCenter += m.mass * m.center;
        inertiaAboutOrigin += m.inertia;
    }

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
        for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
            const Shape& shape = shapes[s];
            if (shape.density == 0.0f) continue;
            OriginMass m = shapeMassAboutOrigin(shape);
            Vec2 offset = m.center - body.localCenter;
            direct += m.centroidInertia + m.mass * dot(offset, offset);
        }
        const float tolerance = 1e-4f;  // far above rounding in the reference's own scenes
        bool accurate = shifted > 0.0f && std::fabs(shifted - direct) <= tolerance * direct;
        body.inertia = accurate ? shifted : direct;
        if (body.inertia > 0.0f) {
            body.invInertia = 1.0f / body.inertia;
        } else {
            body.inertia = 0.0f;  // no area to turn: the body does not rotate
        }
    }

    Vec2 oldCenter = body.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.linearVelocity += cross(body.angularVelocity, body.center - oldCenter);
}

}  // namespace pivot
