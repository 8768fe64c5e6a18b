#include "body.h"

namespace pivot {

void updateBodyMass(Body& body, const SlotPool<Shape>& shapes) {
    body.mass = 0.0f;
    body.invMass = 0.0f;
    body.inertia = 0.0f;
    body.invInertia = 0.0f;
    body.localCenter = Vec2{};

    if (body.type != BodyType::Dynamic) {
        // Without mass the centre is the origin. When it moves there (a dynamic body made
        // kinematic), the velocity follows the origin, so the body's motion does not jump.
        Vec2 oldCenter = body.center;
        body.center = body.xf.p;
        if (body.center != oldCenter) {
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
        body.inertia = inertiaAboutOrigin - body.mass * dot(body.localCenter, body.localCenter);
        body.invInertia = 1.0f / body.inertia;
    }

    Vec2 oldCenter = body.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.linearVelocity += cross(body.angularVelocity, body.center - oldCenter);
}

}  // namespace pivot
