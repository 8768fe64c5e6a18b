#include "collision/shape_cast.h"

namespace pivot {

namespace {
constexpr int kMaxAdvances = 30;  // the cap only stops round-off from looping
}

std::optional<CastEntry> castShape(const DistanceProxy& mover, const Transform& xf,
                                   Vec2 translation, const DistanceProxy& target,
                                   const Transform& xfTarget, float maxFraction) {
    float t = 0.0f;
    for (int i = 0; i < kMaxAdvances; ++i) {
        const Transform at{xf.p + t * translation, xf.q};
        const DistanceResult d = shapeDistance(mover, at, target, xfTarget, true);
        if (d.overlap && t == 0.0f) {
            CastEntry entry;  // touching at the start: a hit with no direction
            entry.point = d.pointB;
            return entry;
        }
        if (d.overlap || d.distance < kCastTolerance) {
            CastEntry entry;
            entry.fraction = t;
            entry.point = d.pointB;
            const Vec2 gap = d.pointA - d.pointB;
            const float gapLength = length(gap);
            // At a gap within the tolerance its direction is still the normal; the fallback is
            // for an exact touch, where the translation is the best guess.
            entry.normal = gapLength > 0.0f ? (1.0f / gapLength) * gap
                                            : -(1.0f / length(translation)) * translation;
            return entry;
        }
        const Vec2 n = (1.0f / length(d.pointB - d.pointA)) * (d.pointB - d.pointA);
        const float closing = dot(n, translation);
        if (!(closing > 0.0f)) return std::nullopt;  // moving away along the gap
        // Stop a little short of touching, so that the last step lands within the tolerance
        // rather than on the surface.
        t += (d.distance - 0.5f * kCastTolerance) / closing;
        if (t > maxFraction) return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace pivot
