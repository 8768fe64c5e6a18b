// The contact solver: non-penetration and friction for one island's touching contacts.
//
// Per manifold point, with normal n (A to B), tangent t = n x 1 = (n.y, -n.x), and rA, rB the
// point relative to the centres of mass:
//   vn = (vB + wB x rB - vA - wA x rA) . n       normal relative velocity
//   normal:   K = mA + mB + iA (rA x n)^2 + iB (rB x n)^2; lambda >= 0 accumulated (pushes only)
//   friction: same with t; |lambda_t| <= friction * lambda_n (Coulomb, accumulated clamping)
// Two-point manifolds solve both normal impulses together (a 2x2 linear complementarity
// problem, solved by trying its four cases in turn) when their 2x2 K is well conditioned,
// which is what lets boxes stack; otherwise only the first point is solved for velocity.
//
// Position error (penetration beyond kLinearSlop) is removed one of three ways
// (WorldDef::contactCorrection):
//   Baumgarte: a velocity bias  beta / h * max(0, -(separation + slop))  at the start of step;
//   NGS:       after integration, per point, re-measure the separation from the current
//              transforms and the manifold kept in local frames, and move the bodies by
//              -K^-1 C with C = clamp(beta (separation + slop), -kMaxLinearCorrection, 0);
//   Soft:      a spring (rows.h) with the target min(biasRate max(0, -(separation + slop)),
//              push speed), softened, point by point; after integration, relax sweeps solve
//              the rigid rows without it (restitution's target only).
//
// Soft contacts are built once a step, at the first substep (Box2D v3's way): normal, anchors
// and masses stay the step's, and each later substep re-measures only the separation, from
// the bodies' moves since the start of the step (SolverMotion dp, dq):
//   s = s0 + ((dpB + dqB rB) - (dpA + dqA rA) - (rB - rA)) . n
// exact for rigid motion of the two anchor points (rA = rB + cB - cA at the start, so the
// anchors' gap starts at zero), the normal taken as fixed over the step.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "constraints/contact_tiles.h"
#include "constraints/soft_factors.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "core/index_range.h"
#include "core/slot_pool.h"
#include "model/contact.h"

namespace pivot {

// Above this ratio of a two-point manifold's K entries the block solve is numerically unsafe
// (the two points are nearly the same constraint) and only the first point is kept.
constexpr float kMaxBlockConditionNumber = 1000.0f;

struct ContactVelocityPoint {
    Vec2 rA;
    Vec2 rB;
    // A tiled contact's constraint lives in its tile (contact_tiles.h); this is then only the
    // one-by-one paths' working copy of it.
    float normalImpulse = 0.0f;
    float tangentImpulse = 0.0f;
    float normalMass = 0.0f;
    float tangentMass = 0.0f;
    float velocityBias = 0.0f;    // restitution or Baumgarte target, m/s
    float softTarget = 0.0f;      // soft contacts: the spring's push-out speed, m/s
    float baseSeparation = 0.0f;  // soft contacts: m, s0 - (rB - rA) . n (see above)
};

struct ContactVelocityConstraint {
    ContactVelocityPoint points[2];
    Vec2 normal;
    Mat22 K;           // two-point normal effective mass
    Mat22 normalMass;  // its inverse
    std::int32_t indexA = 0;
    std::int32_t indexB = 0;
    float mA = 0.0f, mB = 0.0f, iA = 0.0f, iB = 0.0f;
    float friction = 0.0f;
    int pointCount = 0;  // 1 when a two-point manifold is too ill-conditioned to block solve
};

// What the end of the step needs of every contact, tiled or not: which contact it is, and how
// fast its points closed at the start of the step (hit events).
struct ContactRecord {
    std::int32_t contactIndex = 0;
    float approachSpeeds[2] = {0.0f, 0.0f};  // m/s, -vn
};

struct ContactPositionConstraint {
    Vec2 localPoints[2];
    Vec2 localNormal;
    Vec2 localPoint;
    Vec2 localCenterA;
    Vec2 localCenterB;
    std::int32_t indexA = 0;
    std::int32_t indexB = 0;
    float mA = 0.0f, mB = 0.0f, iA = 0.0f, iB = 0.0f;
    float radiusA = 0.0f;
    float radiusB = 0.0f;
    ManifoldType type = ManifoldType::Circles;
    int pointCount = 0;
};

/// The contact constraints of one island, rebuilt every step into reused buffers. Contact k
/// is constraint k of the record, velocity and position arrays; each stage works on a range
/// of them, so a team can share it out by colour (island_schedule.h). A tiled contact's
/// velocity and position constraints live only in its tiles (contact_tiles.h; its entries of
/// the two arrays are left unwritten): the velocity constraint's copy was 172 of the about
/// 420 bytes prepare wrote per contact.
class ContactSolver {
public:
    /// Sizes the arrays for `count` contacts, and lays out tiles for the wide sweeps over the
    /// independent ones among `batches` (the batches the sweeps will be given; none without).
    /// On one thread, before prepare. With `polynomialRotations` (a coloured island's contacts),
    /// the NGS sweeps take the bodies' sines and cosines from core/sine_cosine.h instead of
    /// libm, in the wide and the one-by-one sweeps alike.
    void reset(int count, const StepContext& step, const std::vector<Batch>* batches = nullptr,
               bool polynomialRotations = false);
    /// Room for `count` contacts in at most `batches` batches, so that reset does not allocate
    /// up to that many.
    void reserve(std::size_t count, std::size_t batches) {
        records_.reserve(count);
        velocity_.reserve(count);
        tiles_.reserve(count, batches);
        position_.reserve(count);
    }
    /// Builds constraints [range) from the contacts ids[k], whose solver bodies are pairs[k], at
    /// the solver arrays' poses (the start of the step), with the bodies' masses and centres
    /// from `inputs` (by solver slot); writes no velocity. Restitution measures the approach
    /// speed from the bodies' velocities before this step's forces (`inputs`' start).
    /// `rotations`, if given, holds Rot(positions[i].a) for every slot (computed once per body
    /// rather than once per contact). A tile wholly inside the range is built at once
    /// (prepareTile), the rest one contact at a time, to the same bits.
    void prepare(IndexRange range, const std::int32_t* ids, const BodyPair* pairs,
                 const SlotPool<Contact>& pool, const SolverBodyInputs* inputs,
                 const StepContext& step, const SolverPose* positions,
                 const Rot* rotations = nullptr);
    /// Whether constraints are built once a step (soft contacts): later substeps call
    /// updateSeparations instead of prepare, and storeImpulses only at the last.
    bool builtOncePerStep() const { return soft_; }
    /// Soft contacts, at a substep after the first: re-measures each point's separation from
    /// the bodies' motion since the start of the step (indexed by solver slot) and sets its
    /// spring's target from it.
    void updateSeparations(IndexRange range, const SolverMotion* motion);
    /// Applies last step's impulses (scaled by step.dtRatio in prepare) before iterating.
    /// `independent`: as for solveVelocities.
    void warmStart(IndexRange range, SolverVelocity* velocities, bool independent = false);
    /// One velocity sweep over [range). `independent`: no two of these contacts share a solver
    /// slot (one colour of a coloured island), so they are solved several at a time
    /// (contact_solver_wide.cpp), to the same bits.
    void solveVelocities(IndexRange range, SolverVelocity* velocities, bool independent = false);
    /// Writes the accumulated impulses into the contacts' manifolds for the next warm start;
    /// with `approachSpeeds` (once a step: what later substeps measure is what the first left,
    /// not the hit), also each point's approach speed (hit events).
    void storeImpulses(IndexRange range, SlotPool<Contact>& pool, bool approachSpeeds) const;
    /// One NGS sweep over the points of contacts [range). Returns the smallest separation
    /// measured (m, before each correction; NaN if any was NaN); 0 when there are none.
    /// `independent`: as for solveVelocities (several at a time, the same bits).
    float solvePositions(IndexRange range, SolverPose* positions, bool independent = false) const;
    /// Continuous collision's position sweep (world/continuous_solver.h): as solvePositions,
    /// with the given bias, moving only the bodies in solver slots movableA and movableB (the
    /// others are held as if infinitely heavy). Needs NGS constraints (reset with NGS).
    float solveImpactPositions(IndexRange range, SolverPose* positions, std::int32_t movableA,
                               std::int32_t movableB, float bias) const;
    /// m/s, how fast point j of constraint k closed when prepare measured it.
    float approachSpeed(int k, int j) const { return records_[k].approachSpeeds[j]; }
    /// For tests, process-wide: off, independent batches are solved one contact at a time too,
    /// the reference the wide path must match bit for bit.
    static void setWideSolving(bool enabled);
    /// Whether independent batches are solved several at a time (the build has SIMD lanes and
    /// the switch above is on).
    static bool wideSolving();
    /// Whether any contact takes part in the NGS position phase.
    bool hasPositionConstraints() const { return ngs_ && count_ > 0; }
    /// Soft contacts: whether they relax, and one relax sweep over [range) (rigid, no spring).
    bool relaxes() const { return soft_ && count_ > 0; }
    void relax(IndexRange range, SolverVelocity* velocities, bool independent = false);

    /// A sweep's contacts count as solved when no point is deeper than three slops.
    static bool withinTolerance(float minSeparation) {
        return minSeparation >= -3.0f * kLinearSlop;
    }

    /// The smaller separation, a NaN on either side winning (so a blown-up contact is never
    /// taken as solved, however its sweep's contacts are split up and folded).
    static float minSeparation(float a, float b) {
        if (a != a) return a;
        return !(b >= a) ? b : a;
    }

private:
    /// prepare's arguments, as its helpers take them.
    struct PrepareInputs {
        const std::int32_t* ids;
        const BodyPair* pairs;
        const SlotPool<Contact>& pool;
        const SolverBodyInputs* inputs;
        const StepContext& step;
        const SolverPose* positions;
        const Rot* rotations;  // may be null
    };
    /// prepare for contact k alone; a tiled contact's constraint is assembled in `assembled`
    /// (scratch) and written into its lane.
    void prepareOne(int k, const PrepareInputs& in, ContactVelocityConstraint& assembled);
    /// prepare for the whole tile that starts at contact k, its lanes side by side, to the bits
    /// prepareOne would give (contact_prepare_wide.cpp). False, having written nothing, where a
    /// lane needs what only prepareOne does (a block matrix whose products overflow).
    bool prepareTile(int k, const PrepareInputs& in);
    /// Contact k's NGS position constraint.
    void writePositionConstraint(int k, const PrepareInputs& in);
    /// updateSeparations for the tile that starts at contact k.
    void updateTileSeparations(int k, const SolverMotion* motion);
    /// Likewise for the warm start.
    int warmStartWide(IndexRange range, SolverVelocity* velocities) const;
    /// Contact k's velocity constraint for the one-by-one paths: its entry of the velocity
    /// array, or, for a tiled contact (one a range's edge cut from its tile), a copy read from
    /// its tile into `scratch`.
    ContactVelocityConstraint& oneByOne(int k, ContactVelocityConstraint& scratch);
    /// Contact k's NGS position constraint for the one-by-one sweeps: its entry of the position
    /// array, or, for a tiled contact, a copy read from its position tile into `scratch`.
    const ContactPositionConstraint& positionOf(int k, ContactPositionConstraint& scratch) const;
    /// A tiled contact's impulses back into its tile after a one-by-one solve (none untiled).
    void putImpulses(int k, const ContactVelocityConstraint& c);
    /// Solves contacts [range.begin, returned) several at a time (a sweep's work, or with
    /// `relaxing` a relax sweep's); the caller solves the rest one by one.
    int solveWide(IndexRange range, SolverVelocity* velocities, bool relaxing);
    /// Likewise for an NGS sweep in which every body moves, folding the separations it measures
    /// into `smallest`.
    int positionSweepWide(IndexRange range, SolverPose* positions, float bias,
                          float& smallest) const;
    /// One NGS sweep; a body moves if every body may (movableA = kNoSlot) or it is in one of the
    /// two slots.
    /// The separations measured are folded into `smallest` (minSeparation), which it returns.
    float positionSweep(IndexRange range, SolverPose* positions, float bias, std::int32_t movableA,
                        std::int32_t movableB, float smallest = 0.0f) const;

    /// Soft contacts: the spring's push-out speed at a separation of `separation` m.
    float softTarget(float separation) const {
        return std::min(-softness_.biasRate * std::min(0.0f, separation + kLinearSlop), pushSpeed_);
    }

    // Each array holds at least count_ entries (growBuffer: the rest are a bigger island's).
    int count_ = 0;
    std::vector<ContactRecord> records_;
    std::vector<ContactVelocityConstraint> velocity_;  // untiled contacts' (see above)
    ContactTiles tiles_;  // the wide sweeps' constraints (a tiled contact's only copy)
    std::vector<ContactPositionConstraint> position_;  // untiled NGS contacts' (see above)
    bool ngs_ = false;
    bool polynomialRotations_ = false;
    float positionBias_ = 0.0f;
    bool baumgarte_ = false;
    bool soft_ = false;
    SoftFactors softness_;    // soft contacts' spring for this (sub)step
    float pushSpeed_ = 0.0f;  // m/s
};

}  // namespace pivot
