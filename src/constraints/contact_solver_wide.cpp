// The contact solver's velocity, relax and NGS position sweeps, four contacts at a time (SSE2,
// the x86-64 baseline), for a batch of independent contacts: one colour of a coloured island
// (island_schedule.h), where no two contacts share a solver slot, so solving them together is
// solving them one after another.
//
// Each lane does exactly the arithmetic of the one-contact code in contact_solver.cpp, operation
// for operation and in the same order (the build never contracts a*b+c into one rounding), and
// where that code branches, every lane computes each branch and keeps the one its contact would
// have taken. So a batch solved here gives the same bits as the same batch solved one contact at
// a time: results do not depend on which path ran, nor on the number of workers.
//
// The maths is contact_solver.h's: per point, vn = (vB + wB x rB - vA - wA x rA) . n, friction
// clamped by friction * normal impulse, the two points of a manifold solved together as a 2x2
// complementarity problem (the first of its four cases that holds), or point by point; and the
// NGS sweep's -K^-1 C per point, from the separation re-measured at the current poses (the
// sines and cosines of those poses stay libm's, lane by lane).
#include "constraints/contact_solver.h"

#include <atomic>

#if defined(__SSE2__)
#include <emmintrin.h>
#define PIVOT_WIDE_CONTACTS 1
#endif

namespace pivot {

#if PIVOT_WIDE_CONTACTS

namespace {

// Four floats, one per contact, with the scalar operators.
struct F4 {
    __m128 v;
    F4() : v(_mm_setzero_ps()) {}
    explicit F4(__m128 m) : v(m) {}
    explicit F4(float s) : v(_mm_set1_ps(s)) {}
};
inline F4 operator+(F4 a, F4 b) {
    return F4(_mm_add_ps(a.v, b.v));
}
inline F4 operator-(F4 a, F4 b) {
    return F4(_mm_sub_ps(a.v, b.v));
}
inline F4 operator*(F4 a, F4 b) {
    return F4(_mm_mul_ps(a.v, b.v));
}
inline F4 operator-(F4 a) {  // flips the sign bit, as scalar negation does
    return F4(_mm_xor_ps(a.v, _mm_set1_ps(-0.0f)));
}
// Lane masks (all ones where true).
inline F4 lessThan(F4 a, F4 b) {
    return F4(_mm_cmplt_ps(a.v, b.v));
}
inline F4 atLeast(F4 a, F4 b) {  // a >= b, false when either is NaN, as the scalar test
    return F4(_mm_cmpge_ps(a.v, b.v));
}
inline F4 both(F4 a, F4 b) {
    return F4(_mm_and_ps(a.v, b.v));
}
inline F4 either(F4 a, F4 b) {
    return F4(_mm_or_ps(a.v, b.v));
}
// mask ? a : b, lane by lane.
inline F4 select(F4 mask, F4 a, F4 b) {
    return F4(_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v)));
}
// std::max(a, b) and std::clamp(x, lo, hi), with their exact choices (ties, signed zeros, NaN).
inline F4 maxOf(F4 a, F4 b) {
    return select(lessThan(a, b), b, a);
}
inline F4 clampOf(F4 x, F4 lo, F4 hi) {
    return select(lessThan(x, lo), lo, select(lessThan(hi, x), hi, x));
}

inline void store(F4 a, float out[4]) {
    _mm_storeu_ps(out, a.v);
}

// One lane of a body's velocity per contact.
struct Velocity4 {
    F4 vx, vy, w;
};

// A point's lanes: its anchors, masses, impulses and targets.
struct Point4 {
    F4 rAx, rAy, rBx, rBy;
    F4 normalMass, tangentMass, normalImpulse, tangentImpulse, velocityBias, softTarget;
};

// The four contacts' constraints, read lane by lane.
struct Contacts4 {
    F4 nx, ny, friction, mA, mB, iA, iB;
    F4 has1, has2;          // masks: the contact has a first, a second point
    F4 kxx, kxy, kyx, kyy;  // K (two points): columns cx = (kxx, kxy), cy = (kyx, kyy)
    F4 mxx, mxy, myx, myy;  // its inverse, likewise
    Point4 p[2];
};

template <typename Get>
F4 gather(ContactVelocityConstraint* const c[4], Get get) {
    return F4(_mm_setr_ps(get(*c[0]), get(*c[1]), get(*c[2]), get(*c[3])));
}

Contacts4 load(ContactVelocityConstraint* const c[4]) {
    using C = const ContactVelocityConstraint&;
    Contacts4 k;
    k.nx = gather(c, [](C x) { return x.normal.x; });
    k.ny = gather(c, [](C x) { return x.normal.y; });
    k.friction = gather(c, [](C x) { return x.friction; });
    k.mA = gather(c, [](C x) { return x.mA; });
    k.mB = gather(c, [](C x) { return x.mB; });
    k.iA = gather(c, [](C x) { return x.iA; });
    k.iB = gather(c, [](C x) { return x.iB; });
    const __m128i counts =
        _mm_setr_epi32(c[0]->pointCount, c[1]->pointCount, c[2]->pointCount, c[3]->pointCount);
    k.has1 = F4(_mm_castsi128_ps(_mm_cmpgt_epi32(counts, _mm_set1_epi32(0))));
    k.has2 = F4(_mm_castsi128_ps(_mm_cmpgt_epi32(counts, _mm_set1_epi32(1))));
    k.kxx = gather(c, [](C x) { return x.K.cx.x; });
    k.kxy = gather(c, [](C x) { return x.K.cx.y; });
    k.kyx = gather(c, [](C x) { return x.K.cy.x; });
    k.kyy = gather(c, [](C x) { return x.K.cy.y; });
    k.mxx = gather(c, [](C x) { return x.normalMass.cx.x; });
    k.mxy = gather(c, [](C x) { return x.normalMass.cx.y; });
    k.myx = gather(c, [](C x) { return x.normalMass.cy.x; });
    k.myy = gather(c, [](C x) { return x.normalMass.cy.y; });
    for (int j = 0; j < 2; ++j) {
        Point4& p = k.p[j];
        p.rAx = gather(c, [j](C x) { return x.points[j].rA.x; });
        p.rAy = gather(c, [j](C x) { return x.points[j].rA.y; });
        p.rBx = gather(c, [j](C x) { return x.points[j].rB.x; });
        p.rBy = gather(c, [j](C x) { return x.points[j].rB.y; });
        p.normalMass = gather(c, [j](C x) { return x.points[j].normalMass; });
        p.tangentMass = gather(c, [j](C x) { return x.points[j].tangentMass; });
        p.normalImpulse = gather(c, [j](C x) { return x.points[j].normalImpulse; });
        p.tangentImpulse = gather(c, [j](C x) { return x.points[j].tangentImpulse; });
        p.velocityBias = gather(c, [j](C x) { return x.points[j].velocityBias; });
        p.softTarget = gather(c, [j](C x) { return x.points[j].softTarget; });
    }
    return k;
}

// Writes back what a sweep changes: the impulses.
void storeImpulses(const Contacts4& k, ContactVelocityConstraint* const c[4]) {
    for (int j = 0; j < 2; ++j) {
        float normal[4], tangent[4];
        store(k.p[j].normalImpulse, normal);
        store(k.p[j].tangentImpulse, tangent);
        for (int lane = 0; lane < 4; ++lane) {
            c[lane]->points[j].normalImpulse = normal[lane];
            c[lane]->points[j].tangentImpulse = tangent[lane];
        }
    }
}

Velocity4 loadVelocities(const SolverVelocity* const v[4]) {
    return {F4(_mm_setr_ps(v[0]->v.x, v[1]->v.x, v[2]->v.x, v[3]->v.x)),
            F4(_mm_setr_ps(v[0]->v.y, v[1]->v.y, v[2]->v.y, v[3]->v.y)),
            F4(_mm_setr_ps(v[0]->w, v[1]->w, v[2]->w, v[3]->w))};
}

void storeVelocities(const Velocity4& in, SolverVelocity* const v[4]) {
    float vx[4], vy[4], w[4];
    store(in.vx, vx);
    store(in.vy, vy);
    store(in.w, w);
    for (int lane = 0; lane < 4; ++lane) {
        v[lane]->v = {vx[lane], vy[lane]};
        v[lane]->w = w[lane];
    }
}

// (vB + wB x rB - vA - wA x rA) . d, as relativeVelocity and dot compute it.
F4 relativeAlong(const Velocity4& A, const Velocity4& B, const Point4& p, F4 dx, F4 dy) {
    const F4 vx = ((B.vx + (-B.w) * p.rBy) - A.vx) - (-A.w) * p.rAy;
    const F4 vy = ((B.vy + B.w * p.rBx) - A.vy) - A.w * p.rAx;
    return vx * dx + vy * dy;
}

// Impulse (Px, Py) at point p, in the lanes of `mask` only.
void apply(Velocity4& A, Velocity4& B, const Contacts4& k, const Point4& p, F4 Px, F4 Py, F4 mask) {
    A.vx = select(mask, A.vx - k.mA * Px, A.vx);
    A.vy = select(mask, A.vy - k.mA * Py, A.vy);
    A.w = select(mask, A.w - k.iA * (p.rAx * Py - p.rAy * Px), A.w);
    B.vx = select(mask, B.vx + k.mB * Px, B.vx);
    B.vy = select(mask, B.vy + k.mB * Py, B.vy);
    B.w = select(mask, B.w + k.iB * (p.rBx * Py - p.rBy * Px), B.w);
}

void solveFriction(Contacts4& k, Velocity4& A, Velocity4& B) {
    const F4 tx = k.ny, ty = -k.nx;  // tangentOf: cross(n, 1)
    for (int j = 0; j < 2; ++j) {
        Point4& p = k.p[j];
        const F4 active = j == 0 ? k.has1 : k.has2;
        const F4 vt = relativeAlong(A, B, p, tx, ty);
        F4 lambda = p.tangentMass * (-vt);
        const F4 maxFriction = k.friction * p.normalImpulse;
        const F4 total = clampOf(p.tangentImpulse + lambda, -maxFriction, maxFriction);
        lambda = total - p.tangentImpulse;
        p.tangentImpulse = select(active, total, p.tangentImpulse);
        apply(A, B, k, p, lambda * tx, lambda * ty, active);
    }
}

// Point by point, in the lanes of `lanes`: rigid towards velocityBias, or (soft) the spring.
template <bool soft>
void solveNormalPoints(Contacts4& k, Velocity4& A, Velocity4& B, F4 lanes,
                       const SoftFactors& softness) {
    for (int j = 0; j < 2; ++j) {
        Point4& p = k.p[j];
        const F4 active = both(lanes, j == 0 ? k.has1 : k.has2);
        const F4 vn = relativeAlong(A, B, p, k.nx, k.ny);
        F4 lambda = soft ? F4(softness.massScale) * ((-p.normalMass) * (vn - p.softTarget)) -
                               F4(softness.impulseScale) * p.normalImpulse
                         : (-p.normalMass) * (vn - p.velocityBias);
        const F4 total = maxOf(p.normalImpulse + lambda, F4(0.0f));
        lambda = total - p.normalImpulse;
        p.normalImpulse = select(active, total, p.normalImpulse);
        apply(A, B, k, p, lambda * k.nx, lambda * k.ny, active);
    }
}

// Both points together, in the lanes of `lanes` (two-point contacts): solveNormalBlock.
void solveNormalBlock(Contacts4& k, Velocity4& A, Velocity4& B, F4 lanes) {
    Point4& p1 = k.p[0];
    Point4& p2 = k.p[1];
    const F4 old1 = p1.normalImpulse, old2 = p2.normalImpulse;
    const F4 vn1 = relativeAlong(A, B, p1, k.nx, k.ny);
    const F4 vn2 = relativeAlong(A, B, p2, k.nx, k.ny);
    F4 bx = vn1 - p1.velocityBias, by = vn2 - p2.velocityBias;
    // b -= K * old
    const F4 kOldX = k.kxx * old1 + k.kyx * old2;
    const F4 kOldY = k.kxy * old1 + k.kyy * old2;
    bx = bx - kOldX;
    by = by - kOldY;
    const F4 zero(0.0f);

    // Both push: x = -(M b).
    const F4 bothX = -(k.mxx * bx + k.myx * by);
    const F4 bothY = -(k.mxy * bx + k.myy * by);
    const F4 bothOk = both(atLeast(bothX, zero), atLeast(bothY, zero));
    // Only the first: x = (-m1 bx, 0), and the second not approaching.
    const F4 firstX = (-p1.normalMass) * bx;
    const F4 firstOk = both(atLeast(firstX, zero), atLeast(k.kxy * firstX + by, zero));
    // Only the second: x = (0, -m2 by).
    const F4 secondY = (-p2.normalMass) * by;
    const F4 secondOk = both(atLeast(secondY, zero), atLeast(k.kyx * secondY + bx, zero));
    // Neither: both separating.
    const F4 noneOk = both(atLeast(bx, zero), atLeast(by, zero));

    F4 x1 = select(bothOk, bothX, select(firstOk, firstX, zero));
    F4 x2 = select(bothOk, bothY, select(firstOk, zero, select(secondOk, secondY, zero)));
    const F4 found = both(lanes, either(either(bothOk, firstOk), either(secondOk, noneOk)));

    const F4 d1 = x1 - old1, d2 = x2 - old2;
    const F4 P1x = d1 * k.nx, P1y = d1 * k.ny;
    const F4 P2x = d2 * k.nx, P2y = d2 * k.ny;
    const F4 Px = P1x + P2x, Py = P1y + P2y;
    A.vx = select(found, A.vx - k.mA * Px, A.vx);
    A.vy = select(found, A.vy - k.mA * Py, A.vy);
    A.w = select(found,
                 A.w - k.iA * ((p1.rAx * P1y - p1.rAy * P1x) + (p2.rAx * P2y - p2.rAy * P2x)), A.w);
    B.vx = select(found, B.vx + k.mB * Px, B.vx);
    B.vy = select(found, B.vy + k.mB * Py, B.vy);
    B.w = select(found,
                 B.w + k.iB * ((p1.rBx * P1y - p1.rBy * P1x) + (p2.rBx * P2y - p2.rBy * P2x)), B.w);
    p1.normalImpulse = select(found, x1, old1);
    p2.normalImpulse = select(found, x2, old2);
}

// One sweep's work on four contacts: friction, then the normal solve each contact would take.
template <bool relaxing>
void solveFour(ContactVelocityConstraint* const c[4], SolverVelocity* velocities, bool soft,
               const SoftFactors& softness) {
    SolverVelocity* bodyA[4];
    SolverVelocity* bodyB[4];
    for (int lane = 0; lane < 4; ++lane) {
        bodyA[lane] = &velocities[c[lane]->indexA];
        bodyB[lane] = &velocities[c[lane]->indexB];
    }
    Contacts4 k = load(c);
    Velocity4 A = loadVelocities(bodyA);
    Velocity4 B = loadVelocities(bodyB);
    solveFriction(k, A, B);
    const F4 all(_mm_castsi128_ps(_mm_set1_epi32(-1)));
    if (relaxing) {
        solveNormalPoints<false>(k, A, B, all, softness);
    } else if (soft) {
        solveNormalPoints<true>(k, A, B, all, softness);
    } else {
        solveNormalBlock(k, A, B, k.has2);
        solveNormalPoints<false>(k, A, B, F4(_mm_andnot_ps(k.has2.v, all.v)), softness);
    }
    storeImpulses(k, c);
    storeVelocities(A, bodyA);
    storeVelocities(B, bodyB);
}

// --- position sweeps (NGS) ---------------------------------------------------------------------

struct Pose4 {
    F4 cx, cy, a;
};

struct Rot4 {
    F4 s, c;
};

// The rotation of each lane's angle, by the scalar Rot (libm's sine and cosine: no wide
// routine rounds as they do).
Rot4 rotations(F4 angles) {
    float a[4], s[4], c[4];
    store(angles, a);
    for (int lane = 0; lane < 4; ++lane) {
        const Rot q(a[lane]);
        s[lane] = q.s;
        c[lane] = q.c;
    }
    return {F4(_mm_loadu_ps(s)), F4(_mm_loadu_ps(c))};
}

struct Vec4 {
    F4 x, y;
};

// rotate(q, v) and transformPoint({p, q}, v).
Vec4 rotate4(const Rot4& q, const Vec4& v) {
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
Vec4 transform4(const Rot4& q, const Vec4& p, const Vec4& v) {
    const Vec4 r = rotate4(q, v);
    return {r.x + p.x, r.y + p.y};
}

template <typename Get>
F4 gatherPosition(const ContactPositionConstraint* const c[4], Get get) {
    return F4(_mm_setr_ps(get(*c[0]), get(*c[1]), get(*c[2]), get(*c[3])));
}

// A lane mask from a per-constraint test.
template <typename Test>
F4 maskOf(const ContactPositionConstraint* const c[4], Test test) {
    return F4(_mm_castsi128_ps(_mm_setr_epi32(test(*c[0]) ? -1 : 0, test(*c[1]) ? -1 : 0,
                                              test(*c[2]) ? -1 : 0, test(*c[3]) ? -1 : 0)));
}

// One NGS sweep over four contacts whose bodies all move (ContactSolver::positionSweep); writes
// each lane's separations, point by point, into separations[point][lane].
void positionFour(const ContactPositionConstraint* const c[4], SolverPose* positions, float bias,
                  float separations[2][4]) {
    using P = const ContactPositionConstraint&;
    SolverPose* poseA[4];
    SolverPose* poseB[4];
    for (int lane = 0; lane < 4; ++lane) {
        poseA[lane] = &positions[c[lane]->indexA];
        poseB[lane] = &positions[c[lane]->indexB];
    }
    Pose4 A{F4(_mm_setr_ps(poseA[0]->c.x, poseA[1]->c.x, poseA[2]->c.x, poseA[3]->c.x)),
            F4(_mm_setr_ps(poseA[0]->c.y, poseA[1]->c.y, poseA[2]->c.y, poseA[3]->c.y)),
            F4(_mm_setr_ps(poseA[0]->a, poseA[1]->a, poseA[2]->a, poseA[3]->a))};
    Pose4 B{F4(_mm_setr_ps(poseB[0]->c.x, poseB[1]->c.x, poseB[2]->c.x, poseB[3]->c.x)),
            F4(_mm_setr_ps(poseB[0]->c.y, poseB[1]->c.y, poseB[2]->c.y, poseB[3]->c.y)),
            F4(_mm_setr_ps(poseB[0]->a, poseB[1]->a, poseB[2]->a, poseB[3]->a))};
    const F4 mA = gatherPosition(c, [](P x) { return x.mA; });
    const F4 mB = gatherPosition(c, [](P x) { return x.mB; });
    const F4 iA = gatherPosition(c, [](P x) { return x.iA; });
    const F4 iB = gatherPosition(c, [](P x) { return x.iB; });
    const F4 radiusA = gatherPosition(c, [](P x) { return x.radiusA; });
    const F4 radiusB = gatherPosition(c, [](P x) { return x.radiusB; });
    const Vec4 centerA{gatherPosition(c, [](P x) { return x.localCenterA.x; }),
                       gatherPosition(c, [](P x) { return x.localCenterA.y; })};
    const Vec4 centerB{gatherPosition(c, [](P x) { return x.localCenterB.x; }),
                       gatherPosition(c, [](P x) { return x.localCenterB.y; })};
    const Vec4 localNormal{gatherPosition(c, [](P x) { return x.localNormal.x; }),
                           gatherPosition(c, [](P x) { return x.localNormal.y; })};
    const Vec4 localPoint{gatherPosition(c, [](P x) { return x.localPoint.x; }),
                          gatherPosition(c, [](P x) { return x.localPoint.y; })};
    // A circles manifold's centre on B (its only point, whichever point is being solved).
    const Vec4 first{gatherPosition(c, [](P x) { return x.localPoints[0].x; }),
                     gatherPosition(c, [](P x) { return x.localPoints[0].y; })};
    const F4 circles = maskOf(c, [](P x) { return x.type == ManifoldType::Circles; });
    const F4 faceA = maskOf(c, [](P x) { return x.type == ManifoldType::FaceA; });
    const F4 zero(0.0f), one(1.0f), half(0.5f);

    for (int j = 0; j < 2; ++j) {
        const F4 active = maskOf(c, [j](P x) { return x.pointCount > j; });
        const Vec4 local{gatherPosition(c, [j](P x) { return x.localPoints[j].x; }),
                         gatherPosition(c, [j](P x) { return x.localPoints[j].y; })};
        // solverTransform of each body: xf.p = c - rotate(q, localCenter).
        const Rot4 qA = rotations(A.a), qB = rotations(B.a);
        const Vec4 turnedA = rotate4(qA, centerA), turnedB = rotate4(qB, centerB);
        const Vec4 pA{A.cx - turnedA.x, A.cy - turnedA.y};
        const Vec4 pB{B.cx - turnedB.x, B.cy - turnedB.y};

        // measure(), each manifold type, then the lane's own.
        // Circles: from centre A to centre B.
        const Vec4 centreA = transform4(qA, pA, localPoint);
        const Vec4 centreB = transform4(qB, pB, first);
        const Vec4 d{centreB.x - centreA.x, centreB.y - centreA.y};
        const F4 len(_mm_sqrt_ps((d.x * d.x + d.y * d.y).v));
        const F4 positive = lessThan(zero, len);
        const F4 inverse(_mm_div_ps(one.v, len.v));
        const Vec4 circleNormal{select(positive, inverse * d.x, one),
                                select(positive, inverse * d.y, zero)};
        const Vec4 circlePoint{half * (centreA.x + centreB.x), half * (centreA.y + centreB.y)};
        const F4 circleSeparation =
            ((d.x * circleNormal.x + d.y * circleNormal.y) - radiusA) - radiusB;
        // FaceA: A's face, B's point.
        const Vec4 normalA = rotate4(qA, localNormal);
        const Vec4 planeA = transform4(qA, pA, localPoint);
        const Vec4 pointOnB = transform4(qB, pB, local);
        const F4 faceASeparation =
            (((pointOnB.x - planeA.x) * normalA.x + (pointOnB.y - planeA.y) * normalA.y) -
             radiusA) -
            radiusB;
        // FaceB: B's face, A's point, the normal turned to point from A to B.
        const Vec4 normalB = rotate4(qB, localNormal);
        const Vec4 planeB = transform4(qB, pB, localPoint);
        const Vec4 pointOnA = transform4(qA, pA, local);
        const F4 faceBSeparation =
            (((pointOnA.x - planeB.x) * normalB.x + (pointOnA.y - planeB.y) * normalB.y) -
             radiusA) -
            radiusB;

        const Vec4 normal{select(circles, circleNormal.x, select(faceA, normalA.x, -normalB.x)),
                          select(circles, circleNormal.y, select(faceA, normalA.y, -normalB.y))};
        const Vec4 point{select(circles, circlePoint.x, select(faceA, pointOnB.x, pointOnA.x)),
                         select(circles, circlePoint.y, select(faceA, pointOnB.y, pointOnA.y))};
        const F4 separation =
            select(circles, circleSeparation, select(faceA, faceASeparation, faceBSeparation));
        store(separation, separations[j]);

        const Vec4 rA{point.x - A.cx, point.y - A.cy};
        const Vec4 rB{point.x - B.cx, point.y - B.cy};
        const F4 C =
            clampOf(F4(bias) * (separation + F4(kLinearSlop)), F4(-kMaxLinearCorrection), zero);
        const F4 rnA = rA.x * normal.y - rA.y * normal.x;
        const F4 rnB = rB.x * normal.y - rB.y * normal.x;
        const F4 K = ((mA + mB) + iA * rnA * rnA) + iB * rnB * rnB;
        const F4 impulse = select(lessThan(zero, K), F4(_mm_div_ps((-C).v, K.v)), zero);
        const F4 Px = impulse * normal.x, Py = impulse * normal.y;
        A.cx = select(active, A.cx - mA * Px, A.cx);
        A.cy = select(active, A.cy - mA * Py, A.cy);
        A.a = select(active, A.a - iA * (rA.x * Py - rA.y * Px), A.a);
        B.cx = select(active, B.cx + mB * Px, B.cx);
        B.cy = select(active, B.cy + mB * Py, B.cy);
        B.a = select(active, B.a + iB * (rB.x * Py - rB.y * Px), B.a);
    }
    float ax[4], ay[4], aa[4], bx[4], by[4], ba[4];
    store(A.cx, ax);
    store(A.cy, ay);
    store(A.a, aa);
    store(B.cx, bx);
    store(B.cy, by);
    store(B.a, ba);
    for (int lane = 0; lane < 4; ++lane) {
        *poseA[lane] = {{ax[lane], ay[lane]}, aa[lane]};
        *poseB[lane] = {{bx[lane], by[lane]}, ba[lane]};
    }
}

}  // namespace

namespace {
std::atomic<bool> wideEnabled{true};
}  // namespace

void ContactSolver::setWideSolving(bool enabled) {
    wideEnabled = enabled;
}

int ContactSolver::solveWide(IndexRange range, SolverVelocity* velocities, bool relaxing) {
    int k = range.begin;
    if (!wideEnabled.load(std::memory_order_relaxed)) return k;
    for (; k + 4 <= range.end; k += 4) {
        ContactVelocityConstraint* const four[4] = {&velocity_[k], &velocity_[k + 1],
                                                    &velocity_[k + 2], &velocity_[k + 3]};
        if (relaxing) {
            solveFour<true>(four, velocities, soft_, softness_);
        } else {
            solveFour<false>(four, velocities, soft_, softness_);
        }
    }
    return k;
}

int ContactSolver::positionSweepWide(IndexRange range, SolverPose* positions, float bias,
                                     float& smallest) const {
    int k = range.begin;
    if (!wideEnabled.load(std::memory_order_relaxed)) return k;
    for (; k + 4 <= range.end; k += 4) {
        const ContactPositionConstraint* const four[4] = {&position_[k], &position_[k + 1],
                                                          &position_[k + 2], &position_[k + 3]};
        float separations[2][4];
        positionFour(four, positions, bias, separations);
        // Folded in the order the one-by-one sweep meets them: contact by contact, point by
        // point (minSeparation's NaN rule makes the order matter).
        for (int lane = 0; lane < 4; ++lane) {
            for (int j = 0; j < four[lane]->pointCount; ++j) {
                smallest = minSeparation(smallest, separations[j][lane]);
            }
        }
    }
    return k;
}

#else

void ContactSolver::setWideSolving(bool) {}

int ContactSolver::positionSweepWide(IndexRange range, SolverPose*, float, float&) const {
    return range.begin;
}

int ContactSolver::solveWide(IndexRange range, SolverVelocity*, bool) {
    return range.begin;  // no wide path on this target: the caller solves every contact
}

#endif

}  // namespace pivot
