#include "constraints/contact_solver.h"

#include <algorithm>
#include <cmath>

#include "core/buffer.h"
#include "core/prefetch.h"
#include "core/sine_cosine.h"
#include "pivot/constants.h"

namespace pivot {

namespace {

// The body frame of a solver pose, q being Rot(p.a).
Transform solverTransform(const SolverPose& p, Rot q, Vec2 localCenter) {
    Transform xf;
    xf.q = q;
    xf.p = p.c - rotate(xf.q, localCenter);
    return xf;
}

Vec2 tangentOf(Vec2 normal) {
    return cross(normal, 1.0f);
}

Vec2 relativeVelocity(const SolverVelocity& A, const SolverVelocity& B, Vec2 rA, Vec2 rB) {
    return B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
}

void applyImpulse(SolverVelocity& A, SolverVelocity& B, const ContactVelocityConstraint& c,
                  const ContactVelocityPoint& p, Vec2 P) {
    A.v -= c.mA * P;
    A.w -= c.iA * cross(p.rA, P);
    B.v += c.mB * P;
    B.w += c.iB * cross(p.rB, P);
}

float effectiveMass(const ContactVelocityConstraint& c, Vec2 rA, Vec2 rB, Vec2 direction) {
    float rnA = cross(rA, direction);
    float rnB = cross(rB, direction);
    float k = c.mA + c.mB + c.iA * rnA * rnA + c.iB * rnB * rnB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

void solveFriction(ContactVelocityConstraint& c, SolverVelocity& A, SolverVelocity& B) {
    Vec2 tangent = tangentOf(c.normal);
    for (int j = 0; j < c.pointCount; ++j) {
        ContactVelocityPoint& p = c.points[j];
        float vt = dot(relativeVelocity(A, B, p.rA, p.rB), tangent);
        float lambda = p.tangentMass * (-vt);
        float maxFriction = c.friction * p.normalImpulse;
        float total = std::clamp(p.tangentImpulse + lambda, -maxFriction, maxFriction);
        lambda = total - p.tangentImpulse;
        p.tangentImpulse = total;
        applyImpulse(A, B, c, p, lambda * tangent);
    }
}

void solveNormalPointByPoint(ContactVelocityConstraint& c, SolverVelocity& A, SolverVelocity& B) {
    for (int j = 0; j < c.pointCount; ++j) {
        ContactVelocityPoint& p = c.points[j];
        float vn = dot(relativeVelocity(A, B, p.rA, p.rB), c.normal);
        float lambda = -p.normalMass * (vn - p.velocityBias);
        float total = std::max(p.normalImpulse + lambda, 0.0f);
        lambda = total - p.normalImpulse;
        p.normalImpulse = total;
        applyImpulse(A, B, c, p, lambda * c.normal);
    }
}

// Soft contacts (rows.h): with `biased`, each point's penetration is a spring pushing apart at
// up to its soft target, softened; without (the relax sweeps), the rigid row with restitution.
template <bool biased>
void solveNormalSoft(ContactVelocityConstraint& c, SolverVelocity& A, SolverVelocity& B,
                     const SoftFactors& soft) {
    for (int j = 0; j < c.pointCount; ++j) {
        ContactVelocityPoint& p = c.points[j];
        float vn = dot(relativeVelocity(A, B, p.rA, p.rB), c.normal);
        float lambda = biased ? soft.massScale * (-p.normalMass * (vn - p.softTarget)) -
                                    soft.impulseScale * p.normalImpulse
                              : -p.normalMass * (vn - p.velocityBias);
        float total = std::max(p.normalImpulse + lambda, 0.0f);
        lambda = total - p.normalImpulse;
        p.normalImpulse = total;
        applyImpulse(A, B, c, p, lambda * c.normal);
    }
}

// The two normal impulses x of a two-point manifold together: find x >= 0 with
// vn = K x + b' >= 0 and x_i vn_i = 0, where b' = vn_now - bias - K x_old. Of the four cases
// (both points pushing; only the first; only the second; neither) the first consistent one is
// taken. If none is (round-off on a degenerate manifold), the impulses are left unchanged.
void solveNormalBlock(ContactVelocityConstraint& c, SolverVelocity& A, SolverVelocity& B) {
    ContactVelocityPoint& p1 = c.points[0];
    ContactVelocityPoint& p2 = c.points[1];
    Vec2 old{p1.normalImpulse, p2.normalImpulse};
    float vn1 = dot(relativeVelocity(A, B, p1.rA, p1.rB), c.normal);
    float vn2 = dot(relativeVelocity(A, B, p2.rA, p2.rB), c.normal);
    Vec2 b{vn1 - p1.velocityBias, vn2 - p2.velocityBias};
    b -= c.K * old;

    Vec2 x;
    bool found = false;
    // Both points push: vn = 0.
    x = -(c.normalMass * b);
    if (x.x >= 0.0f && x.y >= 0.0f) {
        found = true;
    }
    // Only the first pushes: vn1 = 0, x2 = 0, and the second must not be approaching.
    if (!found) {
        x = {-p1.normalMass * b.x, 0.0f};
        float v2 = c.K.cx.y * x.x + b.y;
        found = x.x >= 0.0f && v2 >= 0.0f;
    }
    // Only the second pushes.
    if (!found) {
        x = {0.0f, -p2.normalMass * b.y};
        float v1 = c.K.cy.x * x.y + b.x;
        found = x.y >= 0.0f && v1 >= 0.0f;
    }
    // Neither pushes: both points separating.
    if (!found) {
        x = {0.0f, 0.0f};
        found = b.x >= 0.0f && b.y >= 0.0f;
    }
    if (!found) return;

    Vec2 d = x - old;
    Vec2 P1 = d.x * c.normal;
    Vec2 P2 = d.y * c.normal;
    A.v -= c.mA * (P1 + P2);
    A.w -= c.iA * (cross(p1.rA, P1) + cross(p2.rA, P2));
    B.v += c.mB * (P1 + P2);
    B.w += c.iB * (cross(p1.rB, P1) + cross(p2.rB, P2));
    p1.normalImpulse = x.x;
    p2.normalImpulse = x.y;
}

// A manifold point re-measured at the current transforms: world normal, point, separation.
struct MeasuredPoint {
    Vec2 normal;
    Vec2 point;
    float separation;
};

MeasuredPoint measure(const ContactPositionConstraint& pc, const Transform& xfA,
                      const Transform& xfB, int index) {
    MeasuredPoint m;
    switch (pc.type) {
        case ManifoldType::Circles: {
            Vec2 pointA = transformPoint(xfA, pc.localPoint);
            Vec2 pointB = transformPoint(xfB, pc.localPoints[0]);
            Vec2 d = pointB - pointA;
            float len = length(d);
            m.normal = len > 0.0f ? (1.0f / len) * d : Vec2{1.0f, 0.0f};
            m.point = 0.5f * (pointA + pointB);
            m.separation = dot(d, m.normal) - pc.radiusA - pc.radiusB;
            break;
        }
        case ManifoldType::FaceA: {
            m.normal = rotate(xfA.q, pc.localNormal);
            Vec2 planePoint = transformPoint(xfA, pc.localPoint);
            m.point = transformPoint(xfB, pc.localPoints[index]);
            m.separation = dot(m.point - planePoint, m.normal) - pc.radiusA - pc.radiusB;
            break;
        }
        case ManifoldType::FaceB: {
            m.normal = rotate(xfB.q, pc.localNormal);
            Vec2 planePoint = transformPoint(xfB, pc.localPoint);
            m.point = transformPoint(xfA, pc.localPoints[index]);
            m.separation = dot(m.point - planePoint, m.normal) - pc.radiusA - pc.radiusB;
            m.normal = -m.normal;  // keep it pointing from A to B
            break;
        }
    }
    return m;
}

// Contacts come to prepare in colour order, scattered over the pool: the contact this far ahead
// is fetched, so the misses overlap instead of following one another.
constexpr int kContactsAhead = 16;

void prefetchContact(const Contact& contact) {
    prefetch(&contact, sizeof(Contact));
}

// Constraint c's fields into lane `lane` of its tile (all of both points: a one-point
// contact's second is zeros, which the wide sweeps read and leave unused).
void writeTile(ContactTile& tile, int lane, const ContactVelocityConstraint& c) {
    using T = ContactTile;
    tile.lanes(T::kNormalX)[lane] = c.normal.x;
    tile.lanes(T::kNormalY)[lane] = c.normal.y;
    tile.lanes(T::kFriction)[lane] = c.friction;
    tile.lanes(T::kMassA)[lane] = c.mA;
    tile.lanes(T::kMassB)[lane] = c.mB;
    tile.lanes(T::kInertiaA)[lane] = c.iA;
    tile.lanes(T::kInertiaB)[lane] = c.iB;
    tile.lanes(T::kKxx)[lane] = c.K.cx.x;
    tile.lanes(T::kKxy)[lane] = c.K.cx.y;
    tile.lanes(T::kKyx)[lane] = c.K.cy.x;
    tile.lanes(T::kKyy)[lane] = c.K.cy.y;
    tile.lanes(T::kMxx)[lane] = c.normalMass.cx.x;
    tile.lanes(T::kMxy)[lane] = c.normalMass.cx.y;
    tile.lanes(T::kMyx)[lane] = c.normalMass.cy.x;
    tile.lanes(T::kMyy)[lane] = c.normalMass.cy.y;
    for (int j = 0; j < 2; ++j) {
        const ContactVelocityPoint& p = c.points[j];
        tile.lanes(j, T::kAnchorAx)[lane] = p.rA.x;
        tile.lanes(j, T::kAnchorAy)[lane] = p.rA.y;
        tile.lanes(j, T::kAnchorBx)[lane] = p.rB.x;
        tile.lanes(j, T::kAnchorBy)[lane] = p.rB.y;
        tile.lanes(j, T::kNormalMass)[lane] = p.normalMass;
        tile.lanes(j, T::kTangentMass)[lane] = p.tangentMass;
        tile.lanes(j, T::kNormalImpulse)[lane] = p.normalImpulse;
        tile.lanes(j, T::kTangentImpulse)[lane] = p.tangentImpulse;
        tile.lanes(j, T::kVelocityBias)[lane] = p.velocityBias;
        tile.lanes(j, T::kSoftTarget)[lane] = p.softTarget;
        tile.lanes(j, T::kBaseSeparation)[lane] = p.baseSeparation;
    }
    tile.indexA[lane] = c.indexA;
    tile.indexB[lane] = c.indexB;
    tile.pointCount[lane] = c.pointCount;
    if (lane == 0) {  // the empty lanes' bodies (contact_tiles.h)
        for (int empty = tile.contactCount; empty < kContactLanes; ++empty) {
            tile.indexA[empty] = c.indexA;
            tile.indexB[empty] = c.indexB;
        }
    }
}

// A tiled contact's position constraint into its lane of the position tile
// (contact_tiles.h), which the wide NGS sweeps read instead of the constraint.
// `contacts`: the lanes in use.
void writePositionTile(PositionTile& tile, int lane, int contacts,
                       const ContactPositionConstraint& pc) {
    using T = PositionTile;
    tile.lanes(T::kMassA)[lane] = pc.mA;
    tile.lanes(T::kMassB)[lane] = pc.mB;
    tile.lanes(T::kInertiaA)[lane] = pc.iA;
    tile.lanes(T::kInertiaB)[lane] = pc.iB;
    tile.lanes(T::kRadiusA)[lane] = pc.radiusA;
    tile.lanes(T::kRadiusB)[lane] = pc.radiusB;
    tile.lanes(T::kCenterAx)[lane] = pc.localCenterA.x;
    tile.lanes(T::kCenterAy)[lane] = pc.localCenterA.y;
    tile.lanes(T::kCenterBx)[lane] = pc.localCenterB.x;
    tile.lanes(T::kCenterBy)[lane] = pc.localCenterB.y;
    tile.lanes(T::kNormalX)[lane] = pc.localNormal.x;
    tile.lanes(T::kNormalY)[lane] = pc.localNormal.y;
    tile.lanes(T::kPointX)[lane] = pc.localPoint.x;
    tile.lanes(T::kPointY)[lane] = pc.localPoint.y;
    for (int j = 0; j < 2; ++j) {
        // An unused point's coordinates are never read by a sweep's result, but are kept
        // finite.
        const Vec2 p = j < pc.pointCount ? pc.localPoints[j] : Vec2{};
        tile.pointX(j)[lane] = p.x;
        tile.pointY(j)[lane] = p.y;
    }
    tile.indexA[lane] = pc.indexA;
    tile.indexB[lane] = pc.indexB;
    tile.pointCount[lane] = pc.pointCount;
    tile.type[lane] = static_cast<std::int32_t>(pc.type);
    if (lane == 0) {  // the empty lanes' bodies (contact_tiles.h)
        for (int empty = contacts; empty < kContactLanes; ++empty) {
            tile.indexA[empty] = pc.indexA;
            tile.indexB[empty] = pc.indexB;
        }
    }
}

// The inverse of writePositionTile.
void readPositionTile(const PositionTile& tile, int lane, ContactPositionConstraint& pc) {
    using T = PositionTile;
    pc.mA = tile.lanes(T::kMassA)[lane];
    pc.mB = tile.lanes(T::kMassB)[lane];
    pc.iA = tile.lanes(T::kInertiaA)[lane];
    pc.iB = tile.lanes(T::kInertiaB)[lane];
    pc.radiusA = tile.lanes(T::kRadiusA)[lane];
    pc.radiusB = tile.lanes(T::kRadiusB)[lane];
    pc.localCenterA = {tile.lanes(T::kCenterAx)[lane], tile.lanes(T::kCenterAy)[lane]};
    pc.localCenterB = {tile.lanes(T::kCenterBx)[lane], tile.lanes(T::kCenterBy)[lane]};
    pc.localNormal = {tile.lanes(T::kNormalX)[lane], tile.lanes(T::kNormalY)[lane]};
    pc.localPoint = {tile.lanes(T::kPointX)[lane], tile.lanes(T::kPointY)[lane]};
    for (int j = 0; j < 2; ++j) pc.localPoints[j] = {tile.pointX(j)[lane], tile.pointY(j)[lane]};
    pc.indexA = tile.indexA[lane];
    pc.indexB = tile.indexB[lane];
    pc.pointCount = tile.pointCount[lane];
    pc.type = static_cast<ManifoldType>(tile.type[lane]);
}

// The inverse of writeTile.
void readTile(const ContactTile& tile, int lane, ContactVelocityConstraint& c) {
    using T = ContactTile;
    c.normal = {tile.lanes(T::kNormalX)[lane], tile.lanes(T::kNormalY)[lane]};
    c.friction = tile.lanes(T::kFriction)[lane];
    c.mA = tile.lanes(T::kMassA)[lane];
    c.mB = tile.lanes(T::kMassB)[lane];
    c.iA = tile.lanes(T::kInertiaA)[lane];
    c.iB = tile.lanes(T::kInertiaB)[lane];
    c.K.cx = {tile.lanes(T::kKxx)[lane], tile.lanes(T::kKxy)[lane]};
    c.K.cy = {tile.lanes(T::kKyx)[lane], tile.lanes(T::kKyy)[lane]};
    c.normalMass.cx = {tile.lanes(T::kMxx)[lane], tile.lanes(T::kMxy)[lane]};
    c.normalMass.cy = {tile.lanes(T::kMyx)[lane], tile.lanes(T::kMyy)[lane]};
    for (int j = 0; j < 2; ++j) {
        ContactVelocityPoint& p = c.points[j];
        p.rA = {tile.lanes(j, T::kAnchorAx)[lane], tile.lanes(j, T::kAnchorAy)[lane]};
        p.rB = {tile.lanes(j, T::kAnchorBx)[lane], tile.lanes(j, T::kAnchorBy)[lane]};
        p.normalMass = tile.lanes(j, T::kNormalMass)[lane];
        p.tangentMass = tile.lanes(j, T::kTangentMass)[lane];
        p.normalImpulse = tile.lanes(j, T::kNormalImpulse)[lane];
        p.tangentImpulse = tile.lanes(j, T::kTangentImpulse)[lane];
        p.velocityBias = tile.lanes(j, T::kVelocityBias)[lane];
        p.softTarget = tile.lanes(j, T::kSoftTarget)[lane];
        p.baseSeparation = tile.lanes(j, T::kBaseSeparation)[lane];
    }
    c.indexA = tile.indexA[lane];
    c.indexB = tile.indexB[lane];
    c.pointCount = tile.pointCount[lane];
}

}  // namespace

const ContactPositionConstraint& ContactSolver::positionOf(
    int k, ContactPositionConstraint& scratch) const {
    const int slot = tiles_.slot(k);
    if (slot < 0) return position_[k];
    readPositionTile(tiles_.positionTileOf(slot), slot % kContactLanes, scratch);
    return scratch;
}

ContactVelocityConstraint& ContactSolver::oneByOne(int k, ContactVelocityConstraint& scratch) {
    const int slot = tiles_.slot(k);
    if (slot < 0) return velocity_[k];
    readTile(tiles_.tileOf(slot), slot % kContactLanes, scratch);
    return scratch;
}

void ContactSolver::putImpulses(int k, const ContactVelocityConstraint& c) {
    const int slot = tiles_.slot(k);
    if (slot < 0) return;
    ContactTile& tile = tiles_.tileOf(slot);
    const int lane = slot % kContactLanes;
    for (int j = 0; j < 2; ++j) {
        tile.lanes(j, ContactTile::kNormalImpulse)[lane] = c.points[j].normalImpulse;
        tile.lanes(j, ContactTile::kTangentImpulse)[lane] = c.points[j].tangentImpulse;
    }
}

void ContactSolver::reset(int count, const StepContext& step, const std::vector<Batch>* batches,
                          bool polynomialRotations) {
    positionBias_ = step.contactBiasFactor;
    polynomialRotations_ = polynomialRotations;
    baumgarte_ = step.contactCorrection == ContactCorrection::Baumgarte;
    soft_ = step.contactCorrection == ContactCorrection::Soft;
    if (soft_) {
        const float hertz = std::min(step.contactHertz, kMaxSoftHertzShare * step.invDt);
        softness_ = SoftFactors::of(hertz, step.contactDampingRatio, step.dt);
        pushSpeed_ = step.contactPushSpeed;
    }
    ngs_ = step.contactCorrection == ContactCorrection::NGS;
    count_ = count;
    // prepare writes every entry it uses (records for every contact, the untiled contacts'
    // velocity constraints and, under NGS, position constraints, the tiled ones' tiles):
    // nothing is cleared.
    const std::size_t size = static_cast<std::size_t>(count);
    growBuffer(records_, size);
    growBuffer(velocity_, size);
    tiles_.layOut(count, batches, wideSolving(), ngs_);
    if (ngs_) growBuffer(position_, size);
}

void ContactSolver::prepare(IndexRange range, const std::int32_t* ids, const BodyPair* pairs,
                            const SlotPool<Contact>& pool, const SolverBodyInputs* inputs,
                            const StepContext& step, const SolverPose* positions,
                            const Rot* rotations) {
    const PrepareInputs in{ids, pairs, pool, inputs, step, positions, rotations};
    // prepareOne's scratch for a tiled contact, out of the loop.
    ContactVelocityConstraint assembled;
    for (int k = range.begin; k < range.end;) {
        // A whole tile at once where the range holds one (contact_prepare_wide.cpp).
        if (tiles_.isTileStart(k) && k + tiles_.tileAt(k).contactCount <= range.end &&
            prepareTile(k, in)) {
            k += tiles_.tileAt(k).contactCount;
            continue;
        }
        if (k + kContactsAhead < range.end) prefetchContact(pool[ids[k + kContactsAhead]]);
        prepareOne(k, in, assembled);
        ++k;
    }
}

void ContactSolver::writePositionConstraint(int k, const PrepareInputs& in) {
    const Contact& contact = in.pool[in.ids[k]];
    const Manifold& manifold = contact.manifold;
    const SolverBodyInputs& bodyA = in.inputs[in.pairs[k][0]];
    const SolverBodyInputs& bodyB = in.inputs[in.pairs[k][1]];
    // A tiled contact's constraint is assembled here and lives only in its position tile.
    const int slot = tiles_.slot(k);
    ContactPositionConstraint assembled;
    ContactPositionConstraint& pc = slot >= 0 ? assembled : position_[k];
    pc.indexA = in.pairs[k][0];
    pc.indexB = in.pairs[k][1];
    pc.mA = bodyA.invMass;
    pc.mB = bodyB.invMass;
    pc.iA = bodyA.invInertia;
    pc.iB = bodyB.invInertia;
    pc.localCenterA = bodyA.localCenter;
    pc.localCenterB = bodyB.localCenter;
    pc.localNormal = manifold.localNormal;
    pc.localPoint = manifold.localPoint;
    pc.type = manifold.type;
    pc.pointCount = manifold.pointCount;
    pc.radiusA = contact.radiusA;
    pc.radiusB = contact.radiusB;
    for (int j = 0; j < manifold.pointCount; ++j) {
        pc.localPoints[j] = manifold.points[j].localPoint;
    }
    if (slot >= 0) {
        writePositionTile(tiles_.positionTileOf(slot), slot % kContactLanes,
                          tiles_.tileOf(slot).contactCount, pc);
    }
}

void ContactSolver::prepareOne(int k, const PrepareInputs& in,
                               ContactVelocityConstraint& assembled) {
    const BodyPair* pairs = in.pairs;
    const StepContext& step = in.step;
    const SolverPose* positions = in.positions;
    const Rot* rotations = in.rotations;
    const std::int32_t contactIndex = in.ids[k];
    const Contact& contact = in.pool[contactIndex];
    const Manifold& manifold = contact.manifold;
    const SolverBodyInputs& bodyA = in.inputs[pairs[k][0]];
    const SolverBodyInputs& bodyB = in.inputs[pairs[k][1]];

    // A tiled contact's constraint is assembled in `assembled` and written field by field into
    // its tile; an untiled one's is built in place (a copy of one assembled here would read
    // back, in wide loads, fields just written narrow, which stalls each store-to-load
    // forward). Every field is written for every contact, so nothing is cleared first
    // (clearing a constraint cost as much as a tenth of this loop).
    const int slot = tiles_.slot(k);
    ContactVelocityConstraint& c = slot >= 0 ? assembled : velocity_[k];
    c.indexA = pairs[k][0];
    c.indexB = pairs[k][1];
    c.mA = bodyA.invMass;
    c.mB = bodyB.invMass;
    c.iA = bodyA.invInertia;
    c.iB = bodyB.invInertia;
    c.friction = contact.friction;
    c.pointCount = manifold.pointCount;
    c.K = Mat22{};
    c.normalMass = Mat22{};
    ContactRecord& record = records_[k];
    record = ContactRecord{contactIndex, {0.0f, 0.0f}};

    if (ngs_) writePositionConstraint(k, in);  // only NGS contacts keep one

    const SolverPose& posA = positions[c.indexA];
    const SolverPose& posB = positions[c.indexB];
    const SolverVelocity& startA = bodyA.start;
    const SolverVelocity& startB = bodyB.start;
    const Rot qA = rotations ? rotations[c.indexA] : Rot(posA.a);
    const Rot qB = rotations ? rotations[c.indexB] : Rot(posB.a);
    WorldManifold wm = computeWorldManifold(
        manifold, solverTransform(posA, qA, bodyA.localCenter), contact.radiusA,
        solverTransform(posB, qB, bodyB.localCenter), contact.radiusB);
    c.normal = wm.normal;
    const Vec2 tangent = tangentOf(c.normal);

    for (int j = 0; j < 2; ++j) {
        ContactVelocityPoint& p = c.points[j];
        if (j >= manifold.pointCount) {
            p = ContactVelocityPoint{};  // the tile's lanes read it (writeTile)
            continue;
        }
        const ManifoldPoint& mp = manifold.points[j];
        p.normalImpulse = step.warmStarting ? step.dtRatio * mp.normalImpulse : 0.0f;
        p.tangentImpulse = step.warmStarting ? step.dtRatio * mp.tangentImpulse : 0.0f;
        p.rA = wm.points[j] - posA.c;
        p.rB = wm.points[j] - posB.c;
        p.normalMass = effectiveMass(c, p.rA, p.rB, c.normal);
        p.tangentMass = effectiveMass(c, p.rA, p.rB, tangent);

        // Bounce only off fast approaches, so resting contacts stay inelastic. The approach
        // speed is the one the bodies collided with, at the start of the step: this step's
        // gravity acts after the bounce. (Measuring after it would return the ball about
        // one step's travel higher than it fell, v * h, 5% for a 2 m drop at 60 Hz.)
        float vRel = dot(c.normal, relativeVelocity(startA, startB, p.rA, p.rB));
        record.approachSpeeds[j] = -vRel;
        p.velocityBias = vRel < -step.restitutionThreshold ? -contact.restitution * vRel : 0.0f;
        p.softTarget = 0.0f;
        p.baseSeparation = 0.0f;
        if (baumgarte_) {
            float push = -step.contactBiasFactor * step.invDt *
                         std::min(0.0f, wm.separations[j] + kLinearSlop);
            p.velocityBias = std::max(p.velocityBias, push);
        } else if (soft_) {
            p.softTarget = softTarget(wm.separations[j]);
            p.baseSeparation = wm.separations[j] - dot(p.rB - p.rA, c.normal);
        }
    }

    // Soft contacts solve their points one by one, as Box2D v3 does.
    if (c.pointCount == 2 && !soft_) {
        const ContactVelocityPoint& p1 = c.points[0];
        const ContactVelocityPoint& p2 = c.points[1];
        float rn1A = cross(p1.rA, c.normal), rn1B = cross(p1.rB, c.normal);
        float rn2A = cross(p2.rA, c.normal), rn2B = cross(p2.rB, c.normal);
        float k11 = c.mA + c.mB + c.iA * rn1A * rn1A + c.iB * rn1B * rn1B;
        float k22 = c.mA + c.mB + c.iA * rn2A * rn2A + c.iB * rn2B * rn2B;
        float k12 = c.mA + c.mB + c.iA * rn1A * rn2A + c.iB * rn1B * rn2B;
        if (k11 * k11 < kMaxBlockConditionNumber * (k11 * k22 - k12 * k12)) {
            c.K = {{k11, k12}, {k12, k22}};
            c.normalMass = c.K.inverse();
        } else {
            c.pointCount = 1;
        }
    }
    if (slot >= 0) writeTile(tiles_.tileOf(slot), slot % kContactLanes, c);
}

void ContactSolver::updateSeparations(IndexRange range, const SolverMotion* motion) {
    ContactVelocityConstraint scratch;  // out of the loop: clearing it is not free
    for (int k = range.begin; k < range.end;) {
        // A whole tile at once where the range holds one (its contacts' softTarget is then
        // the tile's only: they are solved from there).
        if (tiles_.isTileStart(k) && k + tiles_.tileAt(k).contactCount <= range.end) {
            updateTileSeparations(k, motion);
            k += tiles_.tileAt(k).contactCount;
            continue;
        }
        ContactVelocityConstraint& c = oneByOne(k, scratch);
        const SolverMotion& A = motion[c.indexA];
        const SolverMotion& B = motion[c.indexB];
        for (int j = 0; j < c.pointCount; ++j) {
            ContactVelocityPoint& p = c.points[j];
            const Vec2 gap = (B.dp - A.dp) + (rotate(B.dq, p.rB) - rotate(A.dq, p.rA));
            p.softTarget = softTarget(dot(gap, c.normal) + p.baseSeparation);
        }
        const int slot = tiles_.slot(k);
        if (slot >= 0) {  // a tile cut by the range's edge
            ContactTile& tile = tiles_.tileOf(slot);
            for (int j = 0; j < 2; ++j) {
                tile.lanes(j, ContactTile::kSoftTarget)[slot % kContactLanes] =
                    c.points[j].softTarget;
            }
        }
        ++k;
    }
}

void ContactSolver::warmStart(IndexRange range, SolverVelocity* velocities, bool independent) {
    const int first = independent ? warmStartWide(range, velocities) : range.begin;
    ContactVelocityConstraint scratch;
    for (int k = first; k < range.end; ++k) {
        const ContactVelocityConstraint& c = oneByOne(k, scratch);
        SolverVelocity& A = velocities[c.indexA];
        SolverVelocity& B = velocities[c.indexB];
        Vec2 tangent = tangentOf(c.normal);
        for (int j = 0; j < c.pointCount; ++j) {
            const ContactVelocityPoint& p = c.points[j];
            applyImpulse(A, B, c, p, p.normalImpulse * c.normal + p.tangentImpulse * tangent);
        }
    }
}

void ContactSolver::solveVelocities(IndexRange range, SolverVelocity* velocities,
                                    bool independent) {
    const int first = independent ? solveWide(range, velocities, false) : range.begin;
    ContactVelocityConstraint scratch;
    for (int k = first; k < range.end; ++k) {
        ContactVelocityConstraint& c = oneByOne(k, scratch);
        SolverVelocity& A = velocities[c.indexA];
        SolverVelocity& B = velocities[c.indexB];
        // Friction first: its bound depends on the normal impulse, and penetration matters
        // more than sliding, so the normal solve gets the last word.
        solveFriction(c, A, B);
        if (soft_) {
            solveNormalSoft<true>(c, A, B, softness_);
        } else if (c.pointCount == 2) {
            solveNormalBlock(c, A, B);
        } else {
            solveNormalPointByPoint(c, A, B);
        }
        putImpulses(k, c);
    }
}

void ContactSolver::relax(IndexRange range, SolverVelocity* velocities, bool independent) {
    const int first = independent ? solveWide(range, velocities, true) : range.begin;
    ContactVelocityConstraint scratch;
    for (int k = first; k < range.end; ++k) {
        ContactVelocityConstraint& c = oneByOne(k, scratch);
        SolverVelocity& A = velocities[c.indexA];
        SolverVelocity& B = velocities[c.indexB];
        solveFriction(c, A, B);
        solveNormalSoft<false>(c, A, B, softness_);
        putImpulses(k, c);
    }
}

void ContactSolver::storeImpulses(IndexRange range, SlotPool<Contact>& pool,
                                  bool approachSpeeds) const {
    for (int k = range.begin; k < range.end; ++k) {
        // The manifolds are scattered over the pool like the contacts prepare reads.
        if (k + kContactsAhead < range.end) {
            prefetch(&pool[records_[k + kContactsAhead].contactIndex].manifold, sizeof(Manifold));
        }
        const ContactRecord& record = records_[k];
        Manifold& m = pool[record.contactIndex].manifold;
        if (approachSpeeds) {
            for (int j = 0; j < m.pointCount; ++j) {
                m.points[j].approachSpeed = record.approachSpeeds[j];
            }
        }
        const int slot = tiles_.slot(k);
        const ContactTile* tile = slot >= 0 ? &tiles_.tileOf(slot) : nullptr;
        const int lane = slot % kContactLanes;
        const ContactVelocityConstraint* c = tile ? nullptr : &velocity_[k];
        const int pointCount = tile ? tile->pointCount[lane] : c->pointCount;
        for (int j = 0; j < pointCount; ++j) {
            // A non-finite impulse is not carried into the next step's warm start.
            const float normal = tile ? tile->lanes(j, ContactTile::kNormalImpulse)[lane]
                                      : c->points[j].normalImpulse;
            const float tangent = tile ? tile->lanes(j, ContactTile::kTangentImpulse)[lane]
                                       : c->points[j].tangentImpulse;
            const bool finite = std::isfinite(normal) && std::isfinite(tangent);
            m.points[j].normalImpulse = finite ? normal : 0.0f;
            m.points[j].tangentImpulse = finite ? tangent : 0.0f;
        }
    }
}

float ContactSolver::solvePositions(IndexRange range, SolverPose* positions,
                                    bool independent) const {
    if (!independent || !ngs_) {
        return positionSweep(range, positions, positionBias_, kNoSlot, kNoSlot);
    }
    // One fold of the separations, as the one-by-one sweep makes it: the wide part's, then on.
    float smallest = 0.0f;
    const int first = positionSweepWide(range, positions, positionBias_, smallest);
    return positionSweep({first, range.end}, positions, positionBias_, kNoSlot, kNoSlot, smallest);
}

float ContactSolver::solveImpactPositions(IndexRange range, SolverPose* positions,
                                          std::int32_t movableA, std::int32_t movableB,
                                          float bias) const {
    return positionSweep(range, positions, bias, movableA, movableB);
}

float ContactSolver::positionSweep(IndexRange range, SolverPose* positions, float bias,
                                   std::int32_t movableA, std::int32_t movableB,
                                   float smallest) const {
    if (!ngs_) return smallest;
    auto moves = [&](std::int32_t slot) {
        return movableA == kNoSlot || slot == movableA || slot == movableB;
    };
    ContactPositionConstraint scratch;  // positionOf's, out of the loop
    for (int k = range.begin; k < range.end; ++k) {
        const ContactPositionConstraint& pc = positionOf(k, scratch);
        SolverPose& A = positions[pc.indexA];
        SolverPose& B = positions[pc.indexB];
        const bool movesA = moves(pc.indexA);
        const bool movesB = moves(pc.indexB);
        const float mA = movesA ? pc.mA : 0.0f;
        const float iA = movesA ? pc.iA : 0.0f;
        const float mB = movesB ? pc.mB : 0.0f;
        const float iB = movesB ? pc.iB : 0.0f;
        for (int j = 0; j < pc.pointCount; ++j) {
            MeasuredPoint m = measure(
                pc, solverTransform(A, rotationOf(A.a, polynomialRotations_), pc.localCenterA),
                solverTransform(B, rotationOf(B.a, polynomialRotations_), pc.localCenterB), j);
            Vec2 rA = m.point - A.c;
            Vec2 rB = m.point - B.c;
            smallest = minSeparation(smallest, m.separation);
            // Only penetration beyond the slop is corrected, a fraction at a time and never by
            // more than kMaxLinearCorrection in one solve.
            float C = std::clamp(bias * (m.separation + kLinearSlop), -kMaxLinearCorrection, 0.0f);
            float rnA = cross(rA, m.normal);
            float rnB = cross(rB, m.normal);
            float K = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
            float impulse = K > 0.0f ? -C / K : 0.0f;
            Vec2 P = impulse * m.normal;
            A.c -= mA * P;
            A.a -= iA * cross(rA, P);
            B.c += mB * P;
            B.a += iB * cross(rB, P);
        }
    }
    return smallest;
}

}  // namespace pivot
