// When two moving convex shapes first come within touching distance: the time of impact that
// continuous collision (world/continuous_solver.h) advances bodies to.
//
// Each body moves along a sweep: its centre of mass and angle go linearly from (c0, a0) at the
// sweep's start to (c, a) at its end, parametrised by t in [0, 1]. The search is conservative
// advancement on separating axes: at the current time t1, GJK gives the closest features; they
// define a separating axis (a point pair, or a face of A or of B and a point of the other) whose
// separation s(t) is a function of time alone. The deepest point along that axis is found at
// the end of the interval, t2; if it is still separated the shapes never touch in [t1, t2].
// Otherwise a root of s(t) = target between t1 and t2 (bisection and secant steps in turn, so it
// both brackets and converges) becomes the new t1, and the search repeats with a new axis.
//
// The target is a touching distance of the cores a little inside the shapes' radii,
// max(kLinearSlop, rA + rB - 3 kLinearSlop), reached within +-kLinearSlop / 4: the contact made
// there then has a point a few slops deep for the solver to hold, rather than none.
//
// The iteration, constants and float operations are Box2D 2.4.1's b2TimeOfImpact
// (tests/reference/toi_reference_test.cpp checks them bit for bit).
#pragma once

#include "collision/distance.h"

namespace pivot {

/// A body's motion over (the remaining part of) a step.
struct Sweep {
    Vec2 localCenter;  ///< centre of mass in the body frame
    Vec2 c0, c;        ///< centre of mass at the sweep's start and end (world)
    float a0 = 0.0f, a = 0.0f;
    float alpha0 = 0.0f;  ///< the fraction of the step at which the sweep starts, in [0, 1)

    /// The body frame at `beta` in [0, 1] of the sweep.
    Transform transformAt(float beta) const;
    /// Starts the sweep later, at `alpha` of the step (>= alpha0), where the body is then.
    void advance(float alpha);
    /// a0 within [0, 2 pi) (a shifted by the same whole turns): large angles make the root
    /// finder lose precision.
    void normalizeAngles();
};

enum class ImpactState {
    Failed,      ///< the search gave up; t is how far it got
    Overlapped,  ///< the cores overlap at the start: nothing continuous can do
    Touching,    ///< the shapes reach the target distance at t
    Separated,   ///< they stay apart up to tMax
};

struct ImpactResult {
    ImpactState state = ImpactState::Failed;
    float t = 0.0f;
};

/// The first time in [0, tMax] at which A and B, moving along their sweeps, come within the
/// touching distance.
ImpactResult timeOfImpact(const DistanceProxy& a, const Sweep& sweepA, const DistanceProxy& b,
                          const Sweep& sweepB, float tMax);

}  // namespace pivot
