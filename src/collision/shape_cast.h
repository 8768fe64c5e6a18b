// Where a shape moving in a straight line (no turning) first touches another: conservative
// advancement on the GJK distance. At fraction t of the translation d the shapes are a distance
// s(t) apart, with n the unit direction from the mover's closest point to the target's; the
// mover closes that gap at most at dot(n, d) per unit of t, so it can advance by
// s / dot(n, d) without passing through, and does, until the gap is under kCastTolerance (a hit)
// or it would move away or past the end (no hit). Without turning each advance is safe and the
// gap shrinks geometrically near a face, so a few iterations reach the tolerance.
#pragma once

#include <optional>

#include "collision/distance.h"

namespace pivot {

/// How close a cast shape comes before it counts as touching (m).
constexpr float kCastTolerance = 0.25f * kLinearSlop;

struct CastEntry {
    float fraction = 0.0f;  ///< of the translation, where the gap first falls under the tolerance
    Vec2 point;             ///< the target's closest point then (world)
    Vec2 normal;            ///< the target's outward normal there (towards the mover); zero if
                            ///< the shapes overlap at the start
};

std::optional<CastEntry> castShape(const DistanceProxy& mover, const Transform& xf,
                                   Vec2 translation, const DistanceProxy& target,
                                   const Transform& xfTarget, float maxFraction);

}  // namespace pivot
