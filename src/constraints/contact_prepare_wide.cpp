// Contact constraints built a tile at a time (ContactSolver::prepareTile): the set-up of
// ContactSolver::prepareOne, for the kContactLanes contacts of a tile side by side in SIMD lanes
// (lanes.h), written straight into the tile's fields.
//
// Per contact, at the poses of the start of the step (contact_solver.h has the maths):
//   the world manifold (computeWorldManifold: circles, face of A or face of B, chosen per lane
//   by mask), each point's anchors rA = p - cA and rB = p - cB, its normal and tangent masses
//   1 / (mA + mB + iA (r x d)^2 + iB (r x d)^2), the approach speed and restitution's target,
//   Baumgarte's push or the soft spring's target and base separation, and for a rigid two-point
//   contact the 2x2 block K, its inverse, or the fall-back to one point.
// Each lane does prepareOne's arithmetic operation for operation and in its order (lanes.h
// rounds each operation as the scalar one does), and where prepareOne branches every lane
// computes both sides and keeps its own: the tile holds the same bits either way
// (WideContacts tests). Gathering the inputs and the records stay scalar.
//
// Measured on large_pyramid (soft step, one thread): the set-up one contact at a time, with
// its world manifolds, was about 17% of the step's samples, three times Box2D v3's; a tile at
// a time, about 9% (docs/performance.md).
#include <cstring>

#include "constraints/contact_solver.h"
#include "constraints/lanes.h"
#include "core/prefetch.h"
#include "pivot/constants.h"

namespace pivot {

#if PIVOT_LANES_4

namespace {

using namespace lanes;
#if PIVOT_LANES_8
using F = F8;
#else
using F = F4;
#endif
static_assert(F::kWidth == kContactLanes, "a tile is built in one go");
constexpr int W = F::kWidth;

struct V2 {
    F x, y;
};

V2 operator+(V2 a, V2 b) {
    return {a.x + b.x, a.y + b.y};
}
V2 operator-(V2 a, V2 b) {
    return {a.x - b.x, a.y - b.y};
}
V2 operator*(F s, V2 v) {
    return {s * v.x, s * v.y};
}
F dotL(V2 a, V2 b) {
    return a.x * b.x + a.y * b.y;
}
F crossL(V2 a, V2 b) {
    return a.x * b.y - a.y * b.x;
}
V2 selectL(F mask, V2 a, V2 b) {
    return {select(mask, a.x, b.x), select(mask, a.y, b.y)};
}

// A rotation, and a frame, one per lane.
struct RotL {
    F s, c;
};
struct FrameL {
    V2 p;
    RotL q;
};
V2 rotateL(RotL q, V2 v) {
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
V2 transformL(const FrameL& xf, V2 v) {
    return rotateL(xf.q, v) + xf.p;
}

// What prepareOne reads of a tile's contacts and their bodies, gathered lane by lane.
struct Gathered {
    // The contacts.
    float friction[W], restitution[W], radiusA[W], radiusB[W];
    std::int32_t pointCount[W], circles[W], faceA[W];    // circles, faceA: 1 or 0
    float normalX[W], normalY[W], pointX[W], pointY[W];  // manifold.localNormal, localPoint
    float localX[2][W], localY[2][W];                    // points[j].localPoint
    float normalImpulse[2][W], tangentImpulse[2][W];     // last step's
    // The bodies, A then B.
    struct Body {
        float invMass[W], invInertia[W], centerX[W], centerY[W];  // centerX, Y: localCenter
        float vx[W], vy[W], w[W];                                 // start velocity
        float cx[W], cy[W], s[W], c[W];                           // pose and its rotation
    } body[2];
};

F loadL(const float (&a)[W]) {
    return F::load(a);
}

// mA + mB + iA (rA x d)^2 + iB (rB x d)^2 inverted, 0 where not positive: effectiveMass.
F effectiveMassL(F mA, F mB, F iA, F iB, V2 rA, V2 rB, V2 d) {
    const F rnA = crossL(rA, d);
    const F rnB = crossL(rB, d);
    const F k = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
    return select(lessThan(F(0.0f), k), F(1.0f) / k, F(0.0f));
}

// Lanes where x is finite (x - x is NaN for infinities and NaN).
F finiteL(F x) {
    return lessThan(x - x, F(1.0f));
}

// A face manifold's points where `mask` holds, computeWorldManifold's FaceA (onA) or FaceB:
// the reference face's normal n and plane point, the incident points local[j] in the other
// body's frame; each point is the midpoint between the two surfaces, its separation measured
// along n from the reference surface. The sums keep computeWorldManifold's order (A's first).
template <bool onA>
void facePoints(F mask, V2 n, V2 planePoint, const FrameL& incident, const V2 local[2],
                F radiusReference, F radiusIncident, V2 points[2], F separations[2]) {
    const F half(0.5f);
    for (int j = 0; j < 2; ++j) {
        const V2 p = transformL(incident, local[j]);
        const V2 reference = p + (radiusReference - dotL(p - planePoint, n)) * n;
        const V2 incidentSurface = p - radiusIncident * n;
        const V2 sum = onA ? reference + incidentSurface : incidentSurface + reference;
        points[j] = selectL(mask, half * sum, points[j]);
        separations[j] = select(mask, dotL(incidentSurface - reference, n), separations[j]);
    }
}

// writePositionConstraint for every lane of the tile of contacts k on (`count` of them) at
// once, from what prepareTile gathered, into its position tile (contact_tiles.h). An empty lane
// keeps lane 0's contact, which it repeats, without its points. (The solver slots are taken
// from `pairs`, not copied from the velocity tile: a wide load of slots just written there one
// by one would stall on the stores.)
void writePositionTile(PositionTile& t, const Gathered& g, int count, const BodyPair* pairs,
                       int k) {
    using T = PositionTile;
    auto copy = [&t](T::Field f, const float(&from)[W]) {
        std::memcpy(t.lanes(f), from, sizeof(from));
    };
    copy(T::kMassA, g.body[0].invMass);
    copy(T::kMassB, g.body[1].invMass);
    copy(T::kInertiaA, g.body[0].invInertia);
    copy(T::kInertiaB, g.body[1].invInertia);
    copy(T::kRadiusA, g.radiusA);
    copy(T::kRadiusB, g.radiusB);
    copy(T::kCenterAx, g.body[0].centerX);
    copy(T::kCenterAy, g.body[0].centerY);
    copy(T::kCenterBx, g.body[1].centerX);
    copy(T::kCenterBy, g.body[1].centerY);
    copy(T::kNormalX, g.normalX);
    copy(T::kNormalY, g.normalY);
    copy(T::kPointX, g.pointX);
    copy(T::kPointY, g.pointY);
    for (int j = 0; j < 2; ++j) {
        // A missing point's coordinates (whatever the manifold last held) as zeros.
        const F has = F::above(g.pointCount, j);
        store(t.pointX(j), select(has, loadL(g.localX[j]), F(0.0f)));
        store(t.pointY(j), select(has, loadL(g.localY[j]), F(0.0f)));
    }
    for (int lane = 0; lane < W; ++lane) {
        const BodyPair& pair = pairs[k + (lane < count ? lane : 0)];
        t.indexA[lane] = pair[0];
        t.indexB[lane] = pair[1];
        t.pointCount[lane] = lane < count ? g.pointCount[lane] : 0;
        const ManifoldType type = g.circles[lane] ? ManifoldType::Circles
                                  : g.faceA[lane] ? ManifoldType::FaceA
                                                  : ManifoldType::FaceB;
        t.type[lane] = static_cast<std::int32_t>(type);
    }
}

}  // namespace

bool ContactSolver::prepareTile(int k, const PrepareInputs& in) {
    ContactTile& tile = tiles_.tileAt(k);
    const int count = tile.contactCount;
    const StepContext& step = in.step;

    // Gather, lane by lane; empty lanes repeat lane 0 (their results are not kept).
    Gathered g;
    for (int lane = 0; lane < W; ++lane) {
        const int at = k + (lane < count ? lane : 0);
        if (lane < count && at + W < count_) prefetch(&in.pool[in.ids[at + W]], sizeof(Contact));
        const Contact& contact = in.pool[in.ids[at]];
        const Manifold& m = contact.manifold;
        if (m.pointCount == 0) return false;  // not touching: computeWorldManifold's own case
        g.friction[lane] = contact.friction;
        g.restitution[lane] = contact.restitution;
        g.radiusA[lane] = contact.radiusA;
        g.radiusB[lane] = contact.radiusB;
        g.pointCount[lane] = m.pointCount;
        g.circles[lane] = m.type == ManifoldType::Circles;
        g.faceA[lane] = m.type == ManifoldType::FaceA;
        g.normalX[lane] = m.localNormal.x;
        g.normalY[lane] = m.localNormal.y;
        g.pointX[lane] = m.localPoint.x;
        g.pointY[lane] = m.localPoint.y;
        for (int j = 0; j < 2; ++j) {
            g.localX[j][lane] = m.points[j].localPoint.x;
            g.localY[j][lane] = m.points[j].localPoint.y;
            g.normalImpulse[j][lane] = m.points[j].normalImpulse;
            g.tangentImpulse[j][lane] = m.points[j].tangentImpulse;
        }
        for (int side = 0; side < 2; ++side) {
            const std::int32_t slot = in.pairs[at][side];
            const SolverBodyInputs& body = in.inputs[slot];
            const SolverPose& pose = in.positions[slot];
            const Rot q = in.rotations ? in.rotations[slot] : Rot(pose.a);
            Gathered::Body& b = g.body[side];
            b.invMass[lane] = body.invMass;
            b.invInertia[lane] = body.invInertia;
            b.centerX[lane] = body.localCenter.x;
            b.centerY[lane] = body.localCenter.y;
            b.vx[lane] = body.start.v.x;
            b.vy[lane] = body.start.v.y;
            b.w[lane] = body.start.w;
            b.cx[lane] = pose.c.x;
            b.cy[lane] = pose.c.y;
            b.s[lane] = q.s;
            b.c[lane] = q.c;
        }
    }

    const F zero(0.0f);
    const Gathered::Body& ga = g.body[0];
    const Gathered::Body& gb = g.body[1];
    const F mA = loadL(ga.invMass), mB = loadL(gb.invMass);
    const F iA = loadL(ga.invInertia), iB = loadL(gb.invInertia);
    const V2 cA{loadL(ga.cx), loadL(ga.cy)}, cB{loadL(gb.cx), loadL(gb.cy)};
    // solverTransform: p = c - rotate(q, localCenter)
    FrameL xfA{{}, {loadL(ga.s), loadL(ga.c)}};
    FrameL xfB{{}, {loadL(gb.s), loadL(gb.c)}};
    xfA.p = cA - rotateL(xfA.q, {loadL(ga.centerX), loadL(ga.centerY)});
    xfB.p = cB - rotateL(xfB.q, {loadL(gb.centerX), loadL(gb.centerY)});
    const F radiusA = loadL(g.radiusA), radiusB = loadL(g.radiusB);
    const V2 localNormal{loadL(g.normalX), loadL(g.normalY)};
    const V2 localPoint{loadL(g.pointX), loadL(g.pointY)};
    const V2 local[2] = {{loadL(g.localX[0]), loadL(g.localY[0])},
                         {loadL(g.localX[1]), loadL(g.localY[1])}};
    const F circles = F::above(g.circles, 0), faceA = F::above(g.faceA, 0);
    const F has[2] = {F::above(g.pointCount, 0), F::above(g.pointCount, 1)};
    const F half(0.5f);

    // The world manifold: computeWorldManifold, each kind where any lane has it.
    V2 normal{zero, zero};
    V2 points[2] = {{zero, zero}, {zero, zero}};
    F separations[2] = {zero, zero};
    if (any(circles)) {
        const V2 centerA = transformL(xfA, localPoint);
        const V2 centerB = transformL(xfB, local[0]);
        const V2 d = centerA - centerB;
        const F apart = lessThan(F(kDirectionEpsilon * kDirectionEpsilon), dotL(d, d));
        // normalizedOrUnchanged(centerB - centerA)
        const V2 v = centerB - centerA;
        const F length = squareRoot(dotL(v, v));
        const F inv = F(1.0f) / length;
        const V2 unit = selectL(lessThan(length, F(kDirectionEpsilon)), v, {v.x * inv, v.y * inv});
        const V2 n = selectL(apart, unit, {F(1.0f), zero});
        const V2 surfaceA = centerA + radiusA * n;
        const V2 surfaceB = centerB - radiusB * n;
        normal = selectL(circles, n, normal);
        points[0] = selectL(circles, half * (surfaceA + surfaceB), points[0]);
        separations[0] = select(circles, dotL(surfaceB - surfaceA, n), separations[0]);
    }
    if (any(faceA)) {
        const V2 n = rotateL(xfA.q, localNormal);
        facePoints<true>(faceA, n, transformL(xfA, localPoint), xfB, local, radiusA, radiusB,
                         points, separations);
        normal = selectL(faceA, n, normal);
    }
    const F faceB = butNot(butNot(F::allLanes(), circles), faceA);
    if (any(faceB)) {
        const V2 normalB = rotateL(xfB.q, localNormal);
        facePoints<false>(faceB, normalB, transformL(xfB, localPoint), xfA, local, radiusB, radiusA,
                          points, separations);
        normal = selectL(faceB, {-normalB.x, -normalB.y}, normal);
    }

    using T = ContactTile;
    store(tile.lanes(T::kNormalX), normal.x);
    store(tile.lanes(T::kNormalY), normal.y);
    store(tile.lanes(T::kFriction), loadL(g.friction));
    store(tile.lanes(T::kMassA), mA);
    store(tile.lanes(T::kMassB), mB);
    store(tile.lanes(T::kInertiaA), iA);
    store(tile.lanes(T::kInertiaB), iB);

    // The points: prepareOne's loop over j.
    const V2 tangent{normal.y, -normal.x};  // tangentOf
    const V2 vA{loadL(ga.vx), loadL(ga.vy)}, vB{loadL(gb.vx), loadL(gb.vy)};
    const F wA = loadL(ga.w), wB = loadL(gb.w);
    const F restitution = loadL(g.restitution);
    V2 rA[2], rB[2];
    float approach[2][W];
    for (int j = 0; j < 2; ++j) {
        const F active = has[j];
        const F dtRatio(step.dtRatio);
        const F normalImpulse = step.warmStarting ? dtRatio * loadL(g.normalImpulse[j]) : zero;
        const F tangentImpulse = step.warmStarting ? dtRatio * loadL(g.tangentImpulse[j]) : zero;
        rA[j] = points[j] - cA;
        rB[j] = points[j] - cB;
        const F normalMass = effectiveMassL(mA, mB, iA, iB, rA[j], rB[j], normal);
        const F tangentMass = effectiveMassL(mA, mB, iA, iB, rA[j], rB[j], tangent);
        // relativeVelocity(startA, startB, rA, rB), then its dot with the normal
        const V2 relative{((vB.x + (-wB) * rB[j].y) - vA.x) - (-wA) * rA[j].y,
                          ((vB.y + wB * rB[j].x) - vA.y) - wA * rA[j].x};
        const F vRel = dotL(normal, relative);
        store(approach[j], -vRel);
        F velocityBias =
            select(lessThan(vRel, F(-step.restitutionThreshold)), (-restitution) * vRel, zero);
        F softTarget = zero, baseSeparation = zero;
        const F shifted = separations[j] + F(kLinearSlop);
        const F deeper = select(lessThan(shifted, zero), shifted, zero);  // min(0, s + slop)
        if (baumgarte_) {
            const F push = F(-step.contactBiasFactor) * F(step.invDt) * deeper;
            velocityBias = select(lessThan(velocityBias, push), push, velocityBias);
        } else if (soft_) {
            const F speed = F(-softness_.biasRate) * deeper;
            const F pushSpeed(pushSpeed_);
            softTarget = select(lessThan(pushSpeed, speed), pushSpeed, speed);
            baseSeparation = separations[j] - dotL(rB[j] - rA[j], normal);
        }
        // A missing point's fields are zeros (prepareOne's ContactVelocityPoint{}).
        auto put = [&](T::PointField f, F value) {
            store(tile.lanes(j, f), select(active, value, zero));
        };
        put(T::kAnchorAx, rA[j].x);
        put(T::kAnchorAy, rA[j].y);
        put(T::kAnchorBx, rB[j].x);
        put(T::kAnchorBy, rB[j].y);
        put(T::kNormalMass, normalMass);
        put(T::kTangentMass, tangentMass);
        put(T::kNormalImpulse, normalImpulse);
        put(T::kTangentImpulse, tangentImpulse);
        put(T::kVelocityBias, velocityBias);
        put(T::kSoftTarget, softTarget);
        put(T::kBaseSeparation, baseSeparation);
    }

    // Rigid two-point contacts: the block K and its inverse where well conditioned, else one
    // point (prepareOne's test, and Mat22::inverse).
    F K[4] = {zero, zero, zero, zero}, M[4] = {zero, zero, zero, zero};
    F keepTwo = zero;
    if (!soft_ && any(has[1])) {
        const F rn1A = crossL(rA[0], normal), rn1B = crossL(rB[0], normal);
        const F rn2A = crossL(rA[1], normal), rn2B = crossL(rB[1], normal);
        const F k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        const F k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        const F k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
        keepTwo = both(has[1],
                       lessThan(k11 * k11, F(kMaxBlockConditionNumber) * (k11 * k22 - k12 * k12)));
        const F p = k11 * k22, q = k12 * k12;
        // Mat22::cramer rescales a matrix whose products overflow: left to prepareOne.
        if (any(butNot(keepTwo, both(finiteL(p), finiteL(q))))) return false;
        const F det = p - q;
        const F invDet =
            select(either(lessThan(det, zero), lessThan(zero, det)), F(1.0f) / det, det);
        K[0] = select(keepTwo, k11, zero);
        K[1] = select(keepTwo, k12, zero);
        K[2] = K[1];
        K[3] = select(keepTwo, k22, zero);
        M[0] = select(keepTwo, invDet * k22, zero);
        M[1] = select(keepTwo, (-invDet) * k12, zero);
        M[2] = M[1];
        M[3] = select(keepTwo, invDet * k11, zero);
    }
    store(tile.lanes(T::kKxx), K[0]);
    store(tile.lanes(T::kKxy), K[1]);
    store(tile.lanes(T::kKyx), K[2]);
    store(tile.lanes(T::kKyy), K[3]);
    store(tile.lanes(T::kMxx), M[0]);
    store(tile.lanes(T::kMxy), M[1]);
    store(tile.lanes(T::kMyx), M[2]);
    store(tile.lanes(T::kMyy), M[3]);

    // Per lane: bodies, point counts, records; empty lanes cleared
    // again (contact_tiles.h: no points, zeros, lane 0's bodies).
    float keepMask[W];
    store(keepMask, keepTwo);
    std::int32_t twoKept[W];  // all ones or zero
    std::memcpy(twoKept, keepMask, sizeof(twoKept));
    for (int lane = 0; lane < W; ++lane) {
        if (lane >= count) {
            for (auto& field : tile.values) field[lane] = 0.0f;
            tile.pointCount[lane] = 0;
            tile.indexA[lane] = in.pairs[k][0];
            tile.indexB[lane] = in.pairs[k][1];
            continue;
        }
        const int at = k + lane;
        tile.indexA[lane] = in.pairs[at][0];
        tile.indexB[lane] = in.pairs[at][1];
        const bool fallsBack = !soft_ && g.pointCount[lane] == 2 && twoKept[lane] == 0;
        tile.pointCount[lane] = fallsBack ? 1 : g.pointCount[lane];
        ContactRecord& record = records_[at];
        record.contactIndex = in.ids[at];
        for (int j = 0; j < 2; ++j) {
            record.approachSpeeds[j] = j < g.pointCount[lane] ? approach[j][lane] : 0.0f;
        }
    }
    if (ngs_) writePositionTile(tiles_.positionTileOf(tiles_.slot(k)), g, count, in.pairs, k);
    return true;
}

#else  // no SIMD lanes: no tiles

bool ContactSolver::prepareTile(int, const PrepareInputs&) {
    return false;
}

#endif

}  // namespace pivot
