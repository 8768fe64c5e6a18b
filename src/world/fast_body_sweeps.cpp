#include "world/fast_body_sweeps.h"

#include <algorithm>
#include <cmath>

#include "collision/aabb.h"
#include "collision/time_of_impact.h"
#include "core/buffer.h"
#include "core/prefetch.h"
#include "pivot/constants.h"

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

// The shape's centroid in its body's frame (a capsule's is its core's middle).
Vec2 centroidOf(const Shape& shape) {
    return shape.type == ShapeType::Circle ? shape.circle.center : shape.polygon.centroid;
}

// The point a fraction t of the way from a to b, never outside [a, b]: rounded, (1 - t) a + t b
// can land an ulp beyond both ends, which for a body at the edge of the input limits (an angle
// of 1e10 rad, a coordinate of kMaxCoordinate) is beyond what the API accepts.
float between(float a, float b, float t) {
    const float point = flushDenormal((1.0f - t) * a + t * b);
    return std::fmin(std::fmax(point, std::fmin(a, b)), std::fmax(a, b));
}

// A circle of a quarter of the shape's depth around its centroid.
DistanceProxy coreCircle(const Shape& shape) {
    DistanceProxy proxy;
    proxy.count = 1;
    proxy.vertices[0] = centroidOf(shape);
    proxy.radius = 0.25f * shapeExtent(shape, Vec2{}).min;
    return proxy;
}

// Whether a chain segment lets a fast shape's sweep by without a time of impact, as Box2D v3
// lets it: when the shape's centroid starts behind the segment's line (a one-sided segment
// stops nothing from behind), or comes towards the line by less than a quarter of the body's
// thinnest part (the contacts of the next step hold that much, and a body sliding fast along a
// chain is not stopped at every join it brushes). `from` and `to` are the centroid at the
// sweep's two ends.
bool chainLetsBy(const Shape& segment, const Transform& xf, Vec2 from, Vec2 to, float minExtent) {
    const Vec2 p1 = transformPoint(xf, segment.polygon.vertices[0]);
    const Vec2 p2 = transformPoint(xf, segment.polygon.vertices[1]);
    const float segmentLength = length(p2 - p1);
    if (!(segmentLength > kLinearSlop)) return false;
    const Vec2 along = (1.0f / segmentLength) * (p2 - p1);
    // Distances in front of the line, along its normal (the right of p1 -> p2).
    const float before = cross(from - p1, along);
    const float after = cross(to - p1, along);
    return before < 0.0f || before - after < 0.25f * minExtent;
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
    // The body's pose at the sweep's start, for chains only (one sine and cosine).
    bool startKnown = false;
    Transform start;
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
            if (shapes[otherShape].type == ShapeType::ChainSegment) {
                if (!startKnown) {
                    start.q = Rot(body.angle0);
                    start.p = body.center0 - rotate(start.q, body.localCenter);
                    startKnown = true;
                }
                const Vec2 centroid = centroidOf(shape);
                if (chainLetsBy(shapes[otherShape], other.xf, transformPoint(start, centroid),
                                transformPoint(body.xf, centroid), body.minExtent)) {
                    return true;
                }
            }
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
    reserveBuffer(heldAtEdge_, solvedBodies.size());
    bullets_.clear();
    heldAtEdge_.clear();
    int stopped = 0;
    const auto sweep = [&](std::int32_t index) {
        const float t = earliestHit(index, bodies, shapes, contactManager);
        if (!(t < 1.0f)) return;
        Body& body = bodies[index];
        body.center = {between(body.center0.x, body.center.x, t),
                       between(body.center0.y, body.center.y, t)};
        body.angle = between(body.angle0, body.angle, t);
        restartSweep(body);  // what is left of its motion is the next step's
        synchronizeTransform(body);
        if (holdAtWorldEdge(body)) heldAtEdge_.push_back(index);
        contactManager.synchronizeShapes(index, false);  // it starts the next step here
        ++stopped;
    };
    // The bodies are scattered over their pool, a miss each: each is asked for a few ahead.
    constexpr std::size_t kBodiesAhead = 8;
    for (std::size_t i = 0; i < solvedBodies.size(); ++i) {
        if (i + kBodiesAhead < solvedBodies.size()) {
            prefetch(&bodies[solvedBodies[i + kBodiesAhead]], sizeof(Body));
        }
        const std::int32_t index = solvedBodies[i];
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
