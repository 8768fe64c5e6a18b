// The contact solver's velocity, relax and NGS position sweeps, several contacts at a time in
// SIMD lanes (lanes.h: four with SSE2, the x86-64 baseline; eight with the PIVOT_AVX2
// build), for a batch of independent contacts: one colour of a coloured island
// (island_schedule.h), where no two contacts share a solver slot, so solving them together is
// solving them one after another.
//
// Each lane does exactly the arithmetic of the one-contact code in contact_solver.cpp, operation
// for operation and in the same order, and where that code branches, every lane computes each
// branch and keeps the one its contact would have taken (a branch no lane takes is skipped). So
// a batch solved here gives the same bits as the same batch solved one contact at a time, at
// either width: results do not depend on which path ran, nor on the number of workers.
//
// The velocity sweeps read the constraints from their tiles (contact_tiles.h), and the NGS
// sweeps from the position tiles beside them, written once per build, with one load per field;
// only the bodies' velocities and poses are gathered and scattered.
//
// The maths is contact_solver.h's: per point, vn = (vB + wB x rB - vA - wA x rA) . n, friction
// clamped by friction * normal impulse, the two points of a manifold solved together as a 2x2
// complementarity problem (the first of its four cases that holds), or point by point; and the
// NGS sweep's -K^-1 C per point, from the separation re-measured at the current poses (the
// sines and cosines of those poses from core/sine_cosine.h's polynomial in a coloured island,
// else libm's, lane by lane).
#include <atomic>

#include "constraints/contact_solver.h"
#include "constraints/lanes.h"
#include "core/sine_cosine.h"

namespace pivot {

#if PIVOT_LANES_4

namespace {

using namespace lanes;

// A body's velocity, one lane per contact.
template <typename F>
struct Velocities {
    F vx, vy, w;
};

template <typename F>
Velocities<F> loadVelocities(const SolverVelocity* velocities, const std::int32_t* index) {
    const float* rows[F::kWidth];
    for (int lane = 0; lane < F::kWidth; ++lane) rows[lane] = &velocities[index[lane]].v.x;
    Velocities<F> out;
    loadColumns(rows, out.vx, out.vy, out.w);
    return out;
}

// Lanes [0, count) only: an empty lane's copy of lane 0's body must not overwrite lane 0's.
template <typename F>
void storeVelocities(const Velocities<F>& in, SolverVelocity* velocities, const std::int32_t* index,
                     int count) {
    float* rows[F::kWidth];
    for (int lane = 0; lane < F::kWidth; ++lane) rows[lane] = &velocities[index[lane]].v.x;
    storeColumns(rows, in.vx, in.vy, in.w, count);
}

// Inlined into the tile loops, so that the two bodies' velocities stay in registers across a
// tile's constraints.
#if defined(__GNUC__) || defined(__clang__)
#define PIVOT_LANES_INLINE inline __attribute__((always_inline))
#else
#define PIVOT_LANES_INLINE inline
#endif

// A tile's constraints, each field loaded where it is used and impulses stored as they change.
// (A copy of the whole tile, 37 vectors, does not fit in the 16 vector registers: it went to
// the stack and back, and the copy alone was about 6% of a large_pyramid soft step.)
// `Tile` is ContactTile, or const ContactTile for the sweeps that only read it.
template <typename F, typename Tile>
struct TileLanes {
    using T = ContactTile;
    Tile& tile;
    F has1, has2;  // masks: the contact has a first, a second point

    explicit TileLanes(Tile& t)
        : tile(t), has1(F::above(t.pointCount, 0)), has2(F::above(t.pointCount, 1)) {}
    F get(T::Field f) const { return F::load(tile.lanes(f)); }
    F get(int point, T::PointField f) const { return F::load(tile.lanes(point, f)); }
    void put(int point, T::PointField f, F value) const { store(tile.lanes(point, f), value); }
    F has(int point) const { return point == 0 ? has1 : has2; }
};

// (vB + wB x rB - vA - wA x rA) . d at point j, as relativeVelocity and dot compute it.
template <typename F, typename Tile>
PIVOT_LANES_INLINE F relativeAlong(const Velocities<F>& A, const Velocities<F>& B,
                                   const TileLanes<F, Tile>& k, int j, F dx, F dy) {
    using T = ContactTile;
    const F vx =
        ((B.vx + (-B.w) * k.get(j, T::kAnchorBy)) - A.vx) - (-A.w) * k.get(j, T::kAnchorAy);
    const F vy = ((B.vy + B.w * k.get(j, T::kAnchorBx)) - A.vy) - A.w * k.get(j, T::kAnchorAx);
    return vx * dx + vy * dy;
}

// Impulse (Px, Py) at point j, in the lanes of `mask` only.
template <typename F, typename Tile>
PIVOT_LANES_INLINE void apply(Velocities<F>& A, Velocities<F>& B, const TileLanes<F, Tile>& k,
                              int j, F Px, F Py, F mask) {
    using T = ContactTile;
    const F mA = k.get(T::kMassA), iA = k.get(T::kInertiaA);
    const F mB = k.get(T::kMassB), iB = k.get(T::kInertiaB);
    const F rAx = k.get(j, T::kAnchorAx), rAy = k.get(j, T::kAnchorAy);
    const F rBx = k.get(j, T::kAnchorBx), rBy = k.get(j, T::kAnchorBy);
    A.vx = select(mask, A.vx - mA * Px, A.vx);
    A.vy = select(mask, A.vy - mA * Py, A.vy);
    A.w = select(mask, A.w - iA * (rAx * Py - rAy * Px), A.w);
    B.vx = select(mask, B.vx + mB * Px, B.vx);
    B.vy = select(mask, B.vy + mB * Py, B.vy);
    B.w = select(mask, B.w + iB * (rBx * Py - rBy * Px), B.w);
}

template <typename F>
PIVOT_LANES_INLINE void solveFriction(const TileLanes<F, ContactTile>& k, Velocities<F>& A,
                                      Velocities<F>& B) {
    using T = ContactTile;
    const F tx = k.get(T::kNormalY), ty = -k.get(T::kNormalX);  // tangentOf: cross(n, 1)
    for (int j = 0; j < 2; ++j) {
        const F active = k.has(j);
        if (!any(active)) continue;
        const F vt = relativeAlong(A, B, k, j, tx, ty);
        F lambda = k.get(j, T::kTangentMass) * (-vt);
        const F maxFriction = k.get(T::kFriction) * k.get(j, T::kNormalImpulse);
        const F old = k.get(j, T::kTangentImpulse);
        const F total = clampOf(old + lambda, -maxFriction, maxFriction);
        lambda = total - old;
        k.put(j, T::kTangentImpulse, select(active, total, old));
        apply(A, B, k, j, lambda * tx, lambda * ty, active);
    }
}

// Point by point, in the lanes of `lanes`: rigid towards velocityBias, or (soft) the spring.
template <bool soft, typename F>
PIVOT_LANES_INLINE void solveNormalPoints(const TileLanes<F, ContactTile>& k, Velocities<F>& A,
                                          Velocities<F>& B, F lanes, const SoftFactors& softness) {
    using T = ContactTile;
    const F nx = k.get(T::kNormalX), ny = k.get(T::kNormalY);
    for (int j = 0; j < 2; ++j) {
        const F active = both(lanes, k.has(j));
        if (!any(active)) continue;
        const F vn = relativeAlong(A, B, k, j, nx, ny);
        const F old = k.get(j, T::kNormalImpulse);
        const F normalMass = k.get(j, T::kNormalMass);
        F lambda = soft
                       ? F(softness.massScale) * ((-normalMass) * (vn - k.get(j, T::kSoftTarget))) -
                             F(softness.impulseScale) * old
                       : (-normalMass) * (vn - k.get(j, T::kVelocityBias));
        const F total = maxOf(old + lambda, F(0.0f));
        lambda = total - old;
        k.put(j, T::kNormalImpulse, select(active, total, old));
        apply(A, B, k, j, lambda * nx, lambda * ny, active);
    }
}

// Both points together, in the lanes of `lanes` (two-point contacts): solveNormalBlock.
template <typename F>
PIVOT_LANES_INLINE void solveNormalBlock(const TileLanes<F, ContactTile>& k, Velocities<F>& A,
                                         Velocities<F>& B, F lanes) {
    using T = ContactTile;
    const F nx = k.get(T::kNormalX), ny = k.get(T::kNormalY);
    const F old1 = k.get(0, T::kNormalImpulse), old2 = k.get(1, T::kNormalImpulse);
    const F vn1 = relativeAlong(A, B, k, 0, nx, ny);
    const F vn2 = relativeAlong(A, B, k, 1, nx, ny);
    F bx = vn1 - k.get(0, T::kVelocityBias), by = vn2 - k.get(1, T::kVelocityBias);
    // b -= K * old
    const F kxx = k.get(T::kKxx), kxy = k.get(T::kKxy), kyx = k.get(T::kKyx), kyy = k.get(T::kKyy);
    const F kOldX = kxx * old1 + kyx * old2;
    const F kOldY = kxy * old1 + kyy * old2;
    bx = bx - kOldX;
    by = by - kOldY;
    const F zero(0.0f);

    // Both push: x = -(M b).
    const F bothX = -(k.get(T::kMxx) * bx + k.get(T::kMyx) * by);
    const F bothY = -(k.get(T::kMxy) * bx + k.get(T::kMyy) * by);
    const F bothOk = both(atLeast(bothX, zero), atLeast(bothY, zero));
    // Only the first: x = (-m1 bx, 0), and the second not approaching.
    const F firstX = (-k.get(0, T::kNormalMass)) * bx;
    const F firstOk = both(atLeast(firstX, zero), atLeast(kxy * firstX + by, zero));
    // Only the second: x = (0, -m2 by).
    const F secondY = (-k.get(1, T::kNormalMass)) * by;
    const F secondOk = both(atLeast(secondY, zero), atLeast(kyx * secondY + bx, zero));
    // Neither: both separating.
    const F noneOk = both(atLeast(bx, zero), atLeast(by, zero));

    F x1 = select(bothOk, bothX, select(firstOk, firstX, zero));
    F x2 = select(bothOk, bothY, select(firstOk, zero, select(secondOk, secondY, zero)));
    const F found = both(lanes, either(either(bothOk, firstOk), either(secondOk, noneOk)));

    const F d1 = x1 - old1, d2 = x2 - old2;
    const F P1x = d1 * nx, P1y = d1 * ny;
    const F P2x = d2 * nx, P2y = d2 * ny;
    const F Px = P1x + P2x, Py = P1y + P2y;
    const F mA = k.get(T::kMassA), iA = k.get(T::kInertiaA);
    const F mB = k.get(T::kMassB), iB = k.get(T::kInertiaB);
    A.vx = select(found, A.vx - mA * Px, A.vx);
    A.vy = select(found, A.vy - mA * Py, A.vy);
    A.w = select(found,
                 A.w - iA * ((k.get(0, T::kAnchorAx) * P1y - k.get(0, T::kAnchorAy) * P1x) +
                             (k.get(1, T::kAnchorAx) * P2y - k.get(1, T::kAnchorAy) * P2x)),
                 A.w);
    B.vx = select(found, B.vx + mB * Px, B.vx);
    B.vy = select(found, B.vy + mB * Py, B.vy);
    B.w = select(found,
                 B.w + iB * ((k.get(0, T::kAnchorBx) * P1y - k.get(0, T::kAnchorBy) * P1x) +
                             (k.get(1, T::kAnchorBx) * P2y - k.get(1, T::kAnchorBy) * P2x)),
                 B.w);
    k.put(0, T::kNormalImpulse, select(found, x1, old1));
    k.put(1, T::kNormalImpulse, select(found, x2, old2));
}

// One sweep's work on a tile's contacts: friction, then the normal solve each contact would
// take.
template <bool relaxing, typename F>
void solveTile(ContactTile& tile, SolverVelocity* velocities, bool soft,
               const SoftFactors& softness) {
    static_assert(F::kWidth == kContactLanes, "a tile is solved in one go");
    const std::int32_t* indexA = tile.indexA;
    const std::int32_t* indexB = tile.indexB;
    const TileLanes<F, ContactTile> c(tile);
    Velocities<F> A = loadVelocities<F>(velocities, indexA);
    Velocities<F> B = loadVelocities<F>(velocities, indexB);
    solveFriction(c, A, B);
    const F all = F::allLanes();
    if (relaxing) {
        solveNormalPoints<false>(c, A, B, all, softness);
    } else if (soft) {
        solveNormalPoints<true>(c, A, B, all, softness);
    } else {
        if (any(c.has2)) solveNormalBlock(c, A, B, c.has2);
        solveNormalPoints<false>(c, A, B, butNot(all, c.has2), softness);
    }
    // No two lanes share a solver slot (a colour's contacts each have their own copy of a body
    // that never moves), so the order of these writes does not matter.
    storeVelocities(A, velocities, indexA, tile.contactCount);
    storeVelocities(B, velocities, indexB, tile.contactCount);
}

// Last step's impulses applied to a tile's contacts (ContactSolver::warmStart).
template <typename F>
void warmStartTile(const ContactTile& tile, SolverVelocity* velocities) {
    using T = ContactTile;
    const TileLanes<F, const ContactTile> c(tile);
    Velocities<F> A = loadVelocities<F>(velocities, tile.indexA);
    Velocities<F> B = loadVelocities<F>(velocities, tile.indexB);
    const F nx = c.get(T::kNormalX), ny = c.get(T::kNormalY);
    const F tx = ny, ty = -nx;
    for (int j = 0; j < 2; ++j) {
        const F active = c.has(j);
        if (!any(active)) continue;
        const F normalImpulse = c.get(j, T::kNormalImpulse);
        const F tangentImpulse = c.get(j, T::kTangentImpulse);
        const F Px = normalImpulse * nx + tangentImpulse * tx;
        const F Py = normalImpulse * ny + tangentImpulse * ty;
        apply(A, B, c, j, Px, Py, active);
    }
    storeVelocities(A, velocities, tile.indexA, tile.contactCount);
    storeVelocities(B, velocities, tile.indexB, tile.contactCount);
}

// Soft contacts at a later substep: each point's separation re-measured from the bodies'
// motion since the step began, and its spring's target from it (ContactSolver::
// updateSeparations and softTarget, operation for operation).
template <typename F>
void updateTile(ContactTile& t, const SolverMotion* motion, float biasRate, float pushSpeed) {
    using T = ContactTile;
    // Each lane's motion of A and of B: dp.x, dp.y, dq.s, dq.c.
    const float* rowsA[F::kWidth];
    const float* rowsB[F::kWidth];
    for (int i = 0; i < F::kWidth; ++i) {
        rowsA[i] = &motion[t.indexA[i]].dp.x;
        rowsB[i] = &motion[t.indexB[i]].dp.x;
    }
    F dpAx, dpAy, sA, cA, dpBx, dpBy, sB, cB;
    loadColumns(rowsA, dpAx, dpAy, sA, cA);
    loadColumns(rowsB, dpBx, dpBy, sB, cB);
    const F nx = F::load(t.lanes(T::kNormalX)), ny = F::load(t.lanes(T::kNormalY));
    const F zero(0.0f), slop(kLinearSlop), rate(-biasRate), push(pushSpeed);
    for (int j = 0; j < 2; ++j) {
        const F active = F::above(t.pointCount, j);
        if (!any(active)) break;
        const F rAx = F::load(t.lanes(j, T::kAnchorAx)), rAy = F::load(t.lanes(j, T::kAnchorAy));
        const F rBx = F::load(t.lanes(j, T::kAnchorBx)), rBy = F::load(t.lanes(j, T::kAnchorBy));
        // (B.dp - A.dp) + (rotate(B.dq, rB) - rotate(A.dq, rA))
        const F gapX = (dpBx - dpAx) + ((cB * rBx - sB * rBy) - (cA * rAx - sA * rAy));
        const F gapY = (dpBy - dpAy) + ((sB * rBx + cB * rBy) - (sA * rAx + cA * rAy));
        const F separation = (gapX * nx + gapY * ny) + F::load(t.lanes(j, T::kBaseSeparation));
        // min(-biasRate * min(0, separation + slop), pushSpeed), std::min's choices
        const F shifted = separation + slop;
        const F inner = select(lessThan(shifted, zero), shifted, zero);
        const F speed = rate * inner;
        const F target = select(lessThan(push, speed), push, speed);
        float* out = t.lanes(j, T::kSoftTarget);
        store(out, select(active, target, F::load(out)));
    }
}

// --- position sweeps (NGS) ---------------------------------------------------------------------

template <typename F>
struct PoseLanes {
    F cx, cy, a;
};

template <typename F>
struct RotLanes {
    F s, c;
};

template <typename F>
struct VecLanes {
    F x, y;
};

// The rotation of each lane's angle, one lane at a time, as the one-by-one sweep computes it
// (rotationOf).
template <typename F>
RotLanes<F> rotationsLaneByLane(F angles, bool polynomial) {
    constexpr int W = F::kWidth;
    float a[W], s[W], c[W];
    store(a, angles);
    for (int lane = 0; lane < W; ++lane) {
        const Rot one = rotationOf(a[lane], polynomial);
        s[lane] = one.s;
        c[lane] = one.c;
    }
    return {F::load(s), F::load(c)};
}

// The rotation of each lane's angle: the polynomial of core/sine_cosine.h (a coloured
// island's, ContactSolver::reset), all lanes at once where it covers them all, inlined so
// that the sweep keeps its registers; otherwise lane by lane.
template <typename F>
PIVOT_LANES_INLINE RotLanes<F> rotations(F angles, bool polynomial) {
    if (polynomial && all(coveredAngles(angles))) {
        RotLanes<F> q;
        polynomialSineCosine(angles, q.s, q.c);
        return q;
    }
    return rotationsLaneByLane(angles, polynomial);
}

// rotate(q, v) and transformPoint({p, q}, v).
template <typename F>
VecLanes<F> rotateLanes(const RotLanes<F>& q, const VecLanes<F>& v) {
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
template <typename F>
VecLanes<F> transformLanes(const RotLanes<F>& q, const VecLanes<F>& p, const VecLanes<F>& v) {
    const VecLanes<F> r = rotateLanes(q, v);
    return {r.x + p.x, r.y + p.y};
}

template <typename F>
PoseLanes<F> loadPoses(SolverPose* const pose[]) {
    const float* rows[F::kWidth];
    for (int lane = 0; lane < F::kWidth; ++lane) rows[lane] = &pose[lane]->c.x;
    PoseLanes<F> out;
    loadColumns(rows, out.cx, out.cy, out.a);
    return out;
}

// Lanes [0, count) only, as storeVelocities.
template <typename F>
void storePoses(const PoseLanes<F>& in, SolverPose* const pose[], int count) {
    float* rows[F::kWidth];
    for (int lane = 0; lane < F::kWidth; ++lane) rows[lane] = &pose[lane]->c.x;
    storeColumns(rows, in.cx, in.cy, in.a, count);
}

// One NGS sweep over a position tile's `contacts` contacts (ContactSolver::positionSweep,
// every body moving); writes each lane's separations, point by point, into
// separations[point][lane].
template <typename F>
void positionTile(const PositionTile& t, int contacts, SolverPose* positions, float bias,
                  bool polynomial, float separations[2][F::kWidth]) {
    constexpr int W = F::kWidth;
    using T = PositionTile;
    SolverPose* poseA[W];
    SolverPose* poseB[W];
    for (int lane = 0; lane < W; ++lane) {
        poseA[lane] = &positions[t.indexA[lane]];
        poseB[lane] = &positions[t.indexB[lane]];
    }
    auto field = [&t](T::Field f) { return F::load(t.lanes(f)); };
    PoseLanes<F> A = loadPoses<F>(poseA);
    PoseLanes<F> B = loadPoses<F>(poseB);
    const F circles = F::equal(t.type, static_cast<std::int32_t>(ManifoldType::Circles));
    const F faceA = F::equal(t.type, static_cast<std::int32_t>(ManifoldType::FaceA));
    const F faceB = F::equal(t.type, static_cast<std::int32_t>(ManifoldType::FaceB));
    const bool anyCircles = any(circles), anyFaceA = any(faceA), anyFaceB = any(faceB);
    const F zero(0.0f), one(1.0f), half(0.5f);

    for (int j = 0; j < 2; ++j) {
        const F active = F::above(t.pointCount, j);
        if (!any(active)) break;  // no lane has a second point
        // solverTransform of each body: xf.p = c - rotate(q, localCenter).
        const RotLanes<F> qA = rotations(A.a, polynomial), qB = rotations(B.a, polynomial);
        const VecLanes<F> turnedA = rotateLanes(qA, {field(T::kCenterAx), field(T::kCenterAy)});
        const VecLanes<F> turnedB = rotateLanes(qB, {field(T::kCenterBx), field(T::kCenterBy)});
        const VecLanes<F> pA{A.cx - turnedA.x, A.cy - turnedA.y};
        const VecLanes<F> pB{B.cx - turnedB.x, B.cy - turnedB.y};
        const VecLanes<F> localPoint{field(T::kPointX), field(T::kPointY)};

        // measure(), for each manifold type some lane has; each lane then keeps its own.
        VecLanes<F> normal{zero, zero}, point{zero, zero};
        F separation = zero;
        if (anyCircles) {  // from centre A to centre B, B's centre its only point (point 0)
            const VecLanes<F> centreA = transformLanes(qA, pA, localPoint);
            const VecLanes<F> centreB =
                transformLanes(qB, pB, {F::load(t.pointX(0)), F::load(t.pointY(0))});
            const VecLanes<F> d{centreB.x - centreA.x, centreB.y - centreA.y};
            const F len = squareRoot(d.x * d.x + d.y * d.y);
            const F positive = lessThan(zero, len);
            const F inverse = one / len;
            normal = {select(positive, inverse * d.x, one), select(positive, inverse * d.y, zero)};
            point = {half * (centreA.x + centreB.x), half * (centreA.y + centreB.y)};
            separation =
                ((d.x * normal.x + d.y * normal.y) - field(T::kRadiusA)) - field(T::kRadiusB);
        }
        if (anyFaceA || anyFaceB) {
            // One body's face and the other's point: A's face and B's point (FaceA), or the
            // other way round with the normal turned to point from A to B (FaceB). The lanes
            // pick their face's body first, so one measure serves both types, each lane's
            // the same operations on the same values as its own type's.
            const RotLanes<F> qFace{select(faceB, qB.s, qA.s), select(faceB, qB.c, qA.c)};
            const RotLanes<F> qPoint{select(faceB, qA.s, qB.s), select(faceB, qA.c, qB.c)};
            const VecLanes<F> pFace{select(faceB, pB.x, pA.x), select(faceB, pB.y, pA.y)};
            const VecLanes<F> pPoint{select(faceB, pA.x, pB.x), select(faceB, pA.y, pB.y)};
            const VecLanes<F> faceNormal =
                rotateLanes(qFace, {field(T::kNormalX), field(T::kNormalY)});
            const VecLanes<F> plane = transformLanes(qFace, pFace, localPoint);
            const VecLanes<F> onPoint =
                transformLanes(qPoint, pPoint, {F::load(t.pointX(j)), F::load(t.pointY(j))});
            const F s =
                (((onPoint.x - plane.x) * faceNormal.x + (onPoint.y - plane.y) * faceNormal.y) -
                 field(T::kRadiusA)) -
                field(T::kRadiusB);
            const F face = either(faceA, faceB);
            const VecLanes<F> turned{select(faceB, -faceNormal.x, faceNormal.x),
                                     select(faceB, -faceNormal.y, faceNormal.y)};
            normal = {select(face, turned.x, normal.x), select(face, turned.y, normal.y)};
            point = {select(face, onPoint.x, point.x), select(face, onPoint.y, point.y)};
            separation = select(face, s, separation);
        }
        store(separations[j], separation);

        const VecLanes<F> rA{point.x - A.cx, point.y - A.cy};
        const VecLanes<F> rB{point.x - B.cx, point.y - B.cy};
        const F C =
            clampOf(F(bias) * (separation + F(kLinearSlop)), F(-kMaxLinearCorrection), zero);
        const F rnA = rA.x * normal.y - rA.y * normal.x;
        const F rnB = rB.x * normal.y - rB.y * normal.x;
        const F mA = field(T::kMassA), mB = field(T::kMassB);
        const F iA = field(T::kInertiaA), iB = field(T::kInertiaB);
        const F K = ((mA + mB) + iA * rnA * rnA) + iB * rnB * rnB;
        const F impulse = select(lessThan(zero, K), (-C) / K, zero);
        const F Px = impulse * normal.x, Py = impulse * normal.y;
        A.cx = select(active, A.cx - mA * Px, A.cx);
        A.cy = select(active, A.cy - mA * Py, A.cy);
        A.a = select(active, A.a - iA * (rA.x * Py - rA.y * Px), A.a);
        B.cx = select(active, B.cx + mB * Px, B.cx);
        B.cy = select(active, B.cy + mB * Py, B.cy);
        B.a = select(active, B.a + iB * (rB.x * Py - rB.y * Px), B.a);
    }
    storePoses(A, poseA, contacts);
    storePoses(B, poseB, contacts);
}

#if PIVOT_LANES_8
using ContactLanesF = F8;
#else
using ContactLanesF = F4;
#endif

}  // namespace

namespace {
std::atomic<bool> wideEnabled{true};
}  // namespace

void ContactSolver::setWideSolving(bool enabled) {
    wideEnabled = enabled;
}

bool ContactSolver::wideSolving() {
    return wideEnabled.load(std::memory_order_relaxed);
}

int ContactSolver::solveWide(IndexRange range, SolverVelocity* velocities, bool relaxing) {
    // The tiles laid out at reset: from the range's start (a block of an independent batch)
    // while they last.
    int k = range.begin;
    for (; k < range.end && tiles_.isTileStart(k); k += tiles_.tileAt(k).contactCount) {
        ContactTile& tile = tiles_.tileAt(k);
        if (k + tile.contactCount > range.end) break;  // cut by the range's edge
        if (relaxing) {
            solveTile<true, ContactLanesF>(tile, velocities, soft_, softness_);
        } else {
            solveTile<false, ContactLanesF>(tile, velocities, soft_, softness_);
        }
    }
    return k;
}

void ContactSolver::updateTileSeparations(int k, const SolverMotion* motion) {
    updateTile<ContactLanesF>(tiles_.tileAt(k), motion, softness_.biasRate, pushSpeed_);
}

int ContactSolver::warmStartWide(IndexRange range, SolverVelocity* velocities) const {
    int k = range.begin;
    for (; k < range.end && tiles_.isTileStart(k); k += tiles_.tileAt(k).contactCount) {
        const ContactTile& tile = tiles_.tileAt(k);
        if (k + tile.contactCount > range.end) break;  // cut by the range's edge
        warmStartTile<ContactLanesF>(tile, velocities);
    }
    return k;
}

int ContactSolver::positionSweepWide(IndexRange range, SolverPose* positions, float bias,
                                     float& smallest) const {
    int k = range.begin;
    if (!tiles_.hasPositions()) return k;
    // The tiles laid out at reset, as solveWide takes them.
    for (; k < range.end && tiles_.isTileStart(k); k += tiles_.tileAt(k).contactCount) {
        const int contacts = tiles_.tileAt(k).contactCount;
        if (k + contacts > range.end) break;  // cut by the range's edge
        const PositionTile& tile = tiles_.positionTileOf(tiles_.slot(k));
        float separations[2][kContactLanes];
        positionTile<ContactLanesF>(tile, contacts, positions, bias, polynomialRotations_,
                                    separations);
        // Folded in the order the one-by-one sweep meets them: contact by contact, point by
        // point (minSeparation's NaN rule makes the order matter).
        for (int lane = 0; lane < contacts; ++lane) {
            for (int j = 0; j < tile.pointCount[lane]; ++j) {
                smallest = ContactSolver::minSeparation(smallest, separations[j][lane]);
            }
        }
    }
    return k;
}

#else

void ContactSolver::setWideSolving(bool) {}

bool ContactSolver::wideSolving() {
    return false;
}

int ContactSolver::positionSweepWide(IndexRange range, SolverPose*, float, float&) const {
    return range.begin;
}

int ContactSolver::warmStartWide(IndexRange range, SolverVelocity*) const {
    return range.begin;
}

void ContactSolver::updateTileSeparations(int, const SolverMotion*) {}  // no tiles here

int ContactSolver::solveWide(IndexRange range, SolverVelocity*, bool) {
    return range.begin;  // no wide path on this target: the caller solves every contact
}

#endif  // PIVOT_LANES_4

}  // namespace pivot
