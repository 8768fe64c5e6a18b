#include "world/fast_body_sweeps.h"

#include <algorithm>
#include <cmath>

#include "collision/aabb.h"
#include "collision/time_of_impact.h"
#include "core/buffer.h"

namespace pivot {

namespace {

// A body standing where it is for the whole step.
Sweep standing(const Body& b) {
    Sweep s;
    s.localCenter = b.localCenter;
    s.c0 = s.c = b.center;
    s.a0 = s.a = b.angle;
    return s;
}

// How far any point of the body may be, at some moment of the step, from where it ended: its
// centre's move plus its farthest point's turn.
float reachOf(const Body& b) {
    return length(b.center - b.center0) + std::fabs(b.angle - b.angle0) * b.maxExtent;
}

bool isFast(const Body& b) {
    if (b.type != BodyType::Dynamic || !b.awake || !b.continuous) return false;
    return reachOf(b) > 0.5f * b.minExtent;
}

// The shape's centroid in its body's frame, and a circle of a quarter of its depth there.
DistanceProxy coreCircle(const Shape& shape) {
    DistanceProxy proxy;
    proxy.count = 1;
    proxy.vertices[0] =
        shape.type == ShapeType::Circle ? shape.circle.center : shape.polygon.centroid;
    proxy.radius = 0.25f * shapeExtent(shape, Vec2{}).min;
    return proxy;
}

}  // namespace

float FastBodySweeps::earliestHit(std::int32_t index, const SlotPool<Body>& bodies,
                                  const SlotPool<Shape>& shapes,
                                  ContactManager& contactManager) const {
    const Body& body = bodies[index];
    // The times of impact do not depend on alpha0 (left over from a step under Substeps): the
    // sweep is read between its two ends.
    const Sweep sweep = sweepOf(body);
    // Each shape's box where it ended, grown by the body's reach, holds the shape's whole sweep
    // (cheaper than its box at the start: no sine and cosine, no second box).
    const float reach = reachOf(body);
    const BroadPhase& broadPhase = contactManager.broadPhase();
    float hit = 1.0f;
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        const Shape& shape = shapes[s];
        if (shape.sensor) continue;
        const AABB swept{shape.box.lower - Vec2{reach, reach},
                         shape.box.upper + Vec2{reach, reach}};
        const DistanceProxy proxy = contactProxy(shape);
        auto visit = [&](std::int32_t proxyId) {
            const std::int32_t otherShape = broadPhase.userData(proxyId);
            const Body& other = bodies[shapes[otherShape].body];
            if (other.type != BodyType::Static && (!body.bullet || other.bullet)) return true;
            if (!contactManager.solidShapesMayCollide(s, otherShape)) return true;
            const Sweep otherSweep = standing(other);
            const DistanceProxy otherProxy = contactProxy(shapes[otherShape]);
            ImpactResult impact = timeOfImpact(otherProxy, otherSweep, proxy, sweep, hit);
            if (impact.state == ImpactState::Overlapped ||
                (impact.state == ImpactState::Touching && impact.t == 0.0f)) {
                impact = timeOfImpact(otherProxy, otherSweep, coreCircle(shape), sweep, hit);
            }
            if (impact.state == ImpactState::Touching && impact.t > 0.0f && impact.t < hit) {
                hit = impact.t;
            }
            return true;
        };
        if (body.bullet) {
            broadPhase.query(swept, visit);
        } else {
            broadPhase.queryStaticBodies(swept, visit);
        }
    }
    return hit;
}

int FastBodySweeps::solve(const std::vector<std::int32_t>& solvedBodies, SlotPool<Body>& bodies,
                          const SlotPool<Shape>& shapes, ContactManager& contactManager) {
    reserveBuffer(bullets_, solvedBodies.size());
    bullets_.clear();
    int stopped = 0;
    const auto sweep = [&](std::int32_t index) {
        const float t = earliestHit(index, bodies, shapes, contactManager);
        if (!(t < 1.0f)) return;
        Body& body = bodies[index];
        body.center = flushDenormal((1.0f - t) * body.center0 + t * body.center);
        body.angle = flushDenormal((1.0f - t) * body.angle0 + t * body.angle);
        restartSweep(body);  // what is left of its motion is the next step's
        synchronizeTransform(body);
        contactManager.synchronizeShapes(index, false);  // it starts the next step here
        ++stopped;
    };
    for (std::int32_t index : solvedBodies) {
        if (!isFast(bodies[index])) continue;
        if (bodies[index].bullet) {
            bullets_.push_back(index);
        } else {
            sweep(index);
        }
    }
    for (std::int32_t index : bullets_) sweep(index);
    if (stopped > 0) contactManager.findNewContacts();
    return stopped;
}

}  // namespace pivot
