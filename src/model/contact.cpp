#include "model/contact.h"

namespace pivot {

namespace {
// Contacts are made with a segment first, and with a polygon or capsule before a circle (see
// ContactManager::addPair), so these cases are all there is; two segments never meet (both are
// on static or kinematic bodies). To the segment, polygon and circle routines a capsule is a
// rounded polygon of two vertices.
void collide(Manifold& m, const Shape& a, const Transform& xfA, const Shape& b,
             const Transform& xfB) {
    if (isSegmentLike(a.type)) {
        if (b.type == ShapeType::Circle) {
            collideSegmentAndCircle(m, edgeSegmentOf(a), xfA, b.circle, xfB);
        } else if (b.type == ShapeType::Capsule) {
            collideSegmentAndCapsule(m, edgeSegmentOf(a), xfA, b.polygon, xfB);
        } else {
            collideSegmentAndPolygon(m, edgeSegmentOf(a), xfA, b.polygon, xfB);
        }
    } else if (a.type != ShapeType::Circle) {
        if (a.type == ShapeType::Capsule && b.type == ShapeType::Capsule) {
            collideCapsules(m, a.polygon, xfA, b.polygon, xfB);
        } else if (b.type != ShapeType::Circle) {
            // A capsule is a rounded polygon of two vertices to the polygon routine.
            collidePolygons(m, a.polygon, xfA, b.polygon, xfB);
        } else {
            collidePolygonAndCircle(m, a.polygon, xfA, b.circle, xfB);
        }
    } else {
        collideCircles(m, a.circle, xfA, b.circle, xfB);
    }
}
}  // namespace

bool updateContact(Contact& contact, const Shape& shapeA, const Transform& xfA, const Shape& shapeB,
                   const Transform& xfB) {
    const Manifold old = contact.manifold;
    Manifold& m = contact.manifold;
    collide(m, shapeA, xfA, shapeB, xfB);
    for (int i = 0; i < m.pointCount; ++i) {
        ManifoldPoint& p = m.points[i];
        p.normalImpulse = 0.0f;
        p.tangentImpulse = 0.0f;
        p.approachSpeed = 0.0f;
        for (int j = 0; j < old.pointCount; ++j) {
            if (old.points[j].id == p.id) {
                p.normalImpulse = old.points[j].normalImpulse;
                p.tangentImpulse = old.points[j].tangentImpulse;
                p.approachSpeed = old.points[j].approachSpeed;
                break;
            }
        }
    }
    contact.touching = m.pointCount > 0;
    return contact.touching;
}

}  // namespace pivot
