// The fuzz driver's random numbers: a seeded generator whose sequence is the same on every
// platform and standard library (std::uniform_*_distribution is not), so a seed reproduces a
// run anywhere, and the values it draws for API arguments, each marked with whether the API
// must refuse it.
#pragma once

#include <cstdint>
#include <limits>

#include "pivot/pivot.h"

namespace pivot::fuzz {

/// SplitMix64: tiny, fast, and every 64-bit seed gives a good stream.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n).
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    /// Uniform in [lo, hi].
    int between(int lo, int hi) { return lo + below(hi - lo + 1); }
    /// Uniform in [0, 1).
    float unit() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
    bool chance(float p) { return unit() < p; }

private:
    std::uint64_t state_;
};

/// A generated argument and whether the API must refuse it.
template <typename T>
struct Arg {
    T value;
    bool bad = false;
};

/// Values for each kind of argument. `hostile` is the chance that a value is one the API must
/// refuse; otherwise it is valid, and with `extremes` now and then at the edge of its range.
class Values {
public:
    Values(Random& random, float hostile, bool extremes)
        : r_(random), hostile_(hostile), extremes_(extremes) {}

    /// Not a number the API accepts anywhere.
    float garbage() {
        constexpr float kInf = std::numeric_limits<float>::infinity();
        const float choices[] = {std::numeric_limits<float>::quiet_NaN(),
                                 kInf,
                                 -kInf,
                                 std::numeric_limits<float>::max(),
                                 -std::numeric_limits<float>::max(),
                                 1e20f,
                                 -1e30f,
                                 std::numeric_limits<float>::denorm_min(),
                                 -1e-39f};  // denormals
        return choices[r_.below(9)];
    }

    /// A little past a limit (by a thousandth), where an off-by-one in a check would show.
    static float pastLimit(float limit) { return limit * 1.001f; }

    /// A signed quantity bounded by `limit` (named in constants.h), usually of the given
    /// typical size; now and then exactly at the limit, or (hostile) just past it.
    Arg<float> bounded(float typical, float limit) {
        if (r_.chance(hostile_)) {
            if (r_.chance(0.4f)) return {garbage(), true};
            const float past = r_.chance(0.5f) ? pastLimit(limit) : 3.0f * limit;
            return {r_.chance(0.5f) ? past : -past, true};
        }
        if (edge(0.01f)) return {r_.chance(0.5f) ? limit : -limit};
        if (r_.chance(0.05f)) return {0.0f};
        return {r_.uniform(-typical, typical)};
    }
    Arg<Vec2> bounded2(float typical, float limit) {
        Arg<float> x = bounded(typical, limit);
        Arg<float> y = bounded(typical, limit);
        return {{x.value, y.value}, x.bad || y.bad};
    }
    Arg<Vec2> speed2(float typical) { return bounded2(typical, kMaxSpeed); }
    Arg<float> angularSpeed(float typical) { return bounded(typical, kMaxAngularSpeed); }
    Arg<Vec2> gravity() { return bounded2(20.0f, kMaxGravity); }
    Arg<float> gravityScale() { return bounded(2.0f, kMaxGravityScale); }

    /// In [0, limit].
    Arg<float> nonNegativeUpTo(float typical, float limit) {
        if (r_.chance(hostile_)) {
            if (r_.chance(0.4f)) return {garbage(), true};
            return {r_.chance(0.5f) ? pastLimit(limit) : -r_.uniform(0.001f, typical) - 1e-3f,
                    true};
        }
        if (r_.chance(0.1f)) return {0.0f};
        if (edge(0.01f)) return {limit};
        return {r_.uniform(0.0f, typical)};
    }

    /// A position or point, m.
    Arg<Vec2> coordinate(float span = 20.0f) {
        if (r_.chance(hostile_)) {
            Vec2 v{r_.uniform(-span, span), r_.uniform(-span, span)};
            const float past = r_.chance(0.5f) ? pastLimit(kMaxCoordinate) : 2.0f * kMaxCoordinate;
            float bad = r_.chance(0.5f) ? garbage() : (r_.chance(0.5f) ? past : -past);
            (r_.chance(0.5f) ? v.x : v.y) = bad;
            return {v, true};
        }
        if (edge(0.02f)) {
            return {{r_.chance(0.5f) ? kMaxCoordinate : -kMaxCoordinate, r_.uniform(-span, span)}};
        }
        return {{r_.uniform(-span, span), r_.uniform(-span, span)}};
    }

    /// A signed quantity bounded by kMaxMagnitude (force, torque, angle, ...), usually of the
    /// given typical size.
    Arg<float> magnitude(float typical) { return bounded(typical, kMaxMagnitude); }
    Arg<Vec2> magnitude2(float typical) {
        Arg<float> x = magnitude(typical);
        Arg<float> y = magnitude(typical);
        return {{x.value, y.value}, x.bad || y.bad};
    }

    /// >= 0 and <= kMaxMagnitude.
    Arg<float> nonNegative(float typical) {
        if (r_.chance(hostile_)) {
            return {r_.chance(0.5f) ? garbage() : -r_.uniform(0.001f, typical) - 1e-3f, true};
        }
        if (r_.chance(0.1f)) return {0.0f};
        if (edge(0.01f)) return {kMaxMagnitude};
        return {r_.uniform(0.0f, typical)};
    }

    /// > 0 and <= kMaxMagnitude.
    Arg<float> positive(float typical) {
        if (r_.chance(hostile_)) {
            return {r_.chance(0.4f) ? garbage() : (r_.chance(0.5f) ? 0.0f : -typical), true};
        }
        if (edge(0.01f)) return {kMaxMagnitude};
        return {r_.uniform(0.01f, 1.0f) * typical};
    }

    /// In [0, 1].
    Arg<float> fraction() {
        if (r_.chance(hostile_)) {
            return {r_.chance(0.4f) ? garbage() : (r_.chance(0.5f) ? 1.5f : -0.25f), true};
        }
        if (r_.chance(0.1f)) return {r_.chance(0.5f) ? 0.0f : 1.0f};
        return {r_.unit()};
    }

    /// A density; zero is valid only where `zeroAllowed`.
    Arg<float> density(bool zeroAllowed) {
        if (r_.chance(hostile_)) {
            const float choices[] = {-1.0f, 1e-30f, 2.0f * kMaxDensity, 0.5f * kMinDensity,
                                     std::numeric_limits<float>::denorm_min()};
            return {r_.chance(0.3f) ? garbage() : choices[r_.below(5)], true};
        }
        if (zeroAllowed && r_.chance(0.15f)) return {0.0f};
        if (edge(0.02f)) return {r_.chance(0.5f) ? kMinDensity : kMaxDensity};
        return {r_.uniform(0.1f, 10.0f)};
    }

    /// A circle radius, m.
    Arg<float> radius() {
        if (r_.chance(hostile_)) {
            const float choices[] = {0.0f, -0.5f, 1e-20f, 0.5f * kLinearSlop,
                                     2.0f * kMaxCoordinate};
            return {r_.chance(0.3f) ? garbage() : choices[r_.below(5)], true};
        }
        if (edge(0.02f)) return {r_.chance(0.5f) ? kLinearSlop : kMaxCoordinate};
        return {r_.uniform(0.05f, 2.0f)};
    }

    /// Whether to draw a value at the edge of its range (chance p, when extremes are on).
    bool edge(float p) { return extremes_ && r_.chance(p); }

private:
    Random& r_;
    float hostile_;
    bool extremes_;
};

}  // namespace pivot::fuzz
