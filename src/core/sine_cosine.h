// A rotation's sine and cosine by pivot2d's own polynomial, written once for a float and for
// SIMD lanes (constraints/lanes.h), so that a lane gives exactly the bits the scalar call
// gives, at any width.
//
// Why not libm: the NGS position sweep of a coloured island re-measures every contact at the
// current poses, four sines and cosines a contact each sweep. Called lane by lane, libm's
// sincosf was 4.5% of large_pyramid's FullNGS step, and each call made the compiler spill the
// sweep's vector registers around it. libm stays wherever Box2D 2.4.1's bits are kept (small
// islands, the reference tests): only coloured islands, which 2.4.1 would solve in another
// order anyway, and substepped worlds, which have no 2.4.1 counterpart (their bodies'
// rotations at each substep, constraints/rotation_lanes.h), use this.
//
// The method is the textbook one: k = round(a * 2/pi), r = a - k pi/2 in three parts
// (Cody-Waite: the first two parts have few enough bits that k times them is exact for
// |k| < 2^13), then minimax polynomials on [-pi/4, pi/4] (Cephes's sinf and cosf coefficients,
// S. L. Moshier) and the quadrant k mod 4 choosing which is which and the signs. Outside
// |a| < kLargestAngle, and for NaN, the caller falls back to libm (coveredAngles).
//
// Accuracy, against double precision over (-kLargestAngle, kLargestAngle): 7.8e-8 at worst
// (about one unit in the last place of a float just below 1; libm's sinf and cosf, 3.3e-8),
// measured over every thousandth of a radian; tests/engine/sine_cosine_test.cpp holds it within
// 2^-23. One difference of sign: the polynomial's sine of -0 is +0, libm's -0.
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

/// Angles (radians) at least this far from zero go to libm (the reduction's exactness ends).
constexpr float kLargestAngle = 8192.0f;

// The scalar forms of the lane operations the template uses (lanes.h has the SIMD ones).
namespace sine_cosine_ops {
inline bool lessThan(float a, float b) {
    return a < b;
}
inline bool atLeast(float a, float b) {
    return a >= b;
}
inline bool both(bool a, bool b) {
    return a && b;
}
inline bool either(bool a, bool b) {
    return a || b;
}
inline float select(bool mask, float a, float b) {
    return mask ? a : b;
}
}  // namespace sine_cosine_ops

// Always inlined: called out of line, the eight-lane form cost the NGS sweep its registers
// around each call, as libm's did.
#if defined(__GNUC__) || defined(__clang__)
#define PIVOT_SINE_COSINE_INLINE inline __attribute__((always_inline))
#else
#define PIVOT_SINE_COSINE_INLINE inline
#endif

/// s = sin(a), c = cos(a) for |a| < kLargestAngle. F is float or a lanes type; each step is one
/// IEEE-rounded operation (the build never fuses a*b+c), so every width gives the same bits.
template <typename F>
PIVOT_SINE_COSINE_INLINE void polynomialSineCosine(F a, F& s, F& c) {
    using namespace sine_cosine_ops;
    // Adding and taking away 1.5 * 2^23 rounds a float below 2^22 to an integer (to even).
    const F magic(12582912.0f);
    const auto roundToInteger = [&](F x) { return (x + magic) - magic; };
    const F k = roundToInteger(a * F(0.636619772367581343f));  // 2/pi
    const F r = ((a - k * F(1.5703125f)) - k * F(4.837512969970703125e-4f)) -
                k * F(7.54978995489188216e-8f);
    const F z = r * r;
    const F sine =
        ((F(-1.9515295891e-4f) * z + F(8.3321608736e-3f)) * z - F(1.6666654611e-1f)) * z * r + r;
    const F cosine = (((F(2.443315711809948e-5f) * z - F(1.388731625493765e-3f)) * z +
                       F(4.166664568298827e-2f)) *
                          z * z -
                      F(0.5f) * z) +
                     F(1.0f);
    // The quadrant q = k mod 4 (in 0..3, also for negative k), from floor(k / 4).
    const F quarter = k * F(0.25f);
    const F near = roundToInteger(quarter);
    const F below = select(lessThan(quarter, near), near - F(1.0f), near);
    const F q = k - F(4.0f) * below;
    const auto odd = either(both(atLeast(q, F(0.5f)), lessThan(q, F(1.5f))), atLeast(q, F(2.5f)));
    const auto sineNegative = atLeast(q, F(1.5f));                                // q = 2, 3
    const auto cosineNegative = both(atLeast(q, F(0.5f)), lessThan(q, F(2.5f)));  // q = 1, 2
    const F sineOfR = select(odd, cosine, sine);
    const F cosineOfR = select(odd, sine, cosine);
    s = select(sineNegative, -sineOfR, sineOfR);
    c = select(cosineNegative, -cosineOfR, cosineOfR);
}

/// Whether the polynomial covers a (lane by lane for lanes): |a| < kLargestAngle, not NaN.
template <typename F>
auto coveredAngles(F a) {
    using namespace sine_cosine_ops;
    return both(lessThan(a, F(kLargestAngle)), lessThan(F(-kLargestAngle), a));
}

/// The scalar call: the polynomial where it holds, libm elsewhere.
inline void sineCosine(float a, float& s, float& c) {
    if (!coveredAngles(a)) {
        s = std::sin(a);
        c = std::cos(a);
        return;
    }
    polynomialSineCosine(a, s, c);
}

/// A body's rotation as an NGS contact sweep takes it: libm's Rot(a), or with `polynomial` (a
/// coloured island's contacts) sineCosine's. The one-by-one and the wide sweeps both call this.
inline Rot rotationOf(float a, bool polynomial) {
    if (!polynomial) return Rot(a);
    Rot q;
    sineCosine(a, q.s, q.c);
    return q;
}

}  // namespace pivot
