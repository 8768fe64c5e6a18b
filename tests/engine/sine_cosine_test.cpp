// core/sine_cosine.h: the polynomial sine and cosine the NGS sweeps of coloured islands and the
// substepped worlds' rotations (constraints/rotation_lanes.h) use.
// It must be as accurate as a float allows over the angles it covers, hand every other angle
// (large, infinite, NaN) to libm, and give the same bits at every width: one float, four SSE2
// lanes, eight AVX2 lanes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "constraints/lanes.h"
#include "constraints/rotation_lanes.h"
#include "core/sine_cosine.h"

using namespace pivot;

namespace {

std::uint32_t bitsOf(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// Angles over the covered range: a dense sweep near zero, every quadrant boundary up to a few
// turns, and a spread out to the limit (a deterministic walk, no seed to vary).
std::vector<float> testAngles() {
    std::vector<float> angles;
    for (int i = -20000; i <= 20000; ++i) angles.push_back(static_cast<float>(i) * 1.0e-3f);
    const double halfPi = 1.5707963267948966;
    for (int k = -64; k <= 64; ++k) {
        const float boundary = static_cast<float>(k * halfPi);
        float below = boundary, above = boundary;
        for (int step = 0; step < 4; ++step) {
            below = std::nextafter(below, -1.0e9f);
            above = std::nextafter(above, 1.0e9f);
            angles.push_back(below);
            angles.push_back(above);
        }
        angles.push_back(boundary);
    }
    std::uint32_t state = 12345u;
    for (int i = 0; i < 200000; ++i) {
        state = state * 1664525u + 1013904223u;
        const float unit = static_cast<float>(state >> 8) / 16777216.0f;  // [0, 1)
        angles.push_back((2.0f * unit - 1.0f) * kLargestAngle);
    }
    angles.push_back(0.0f);
    angles.push_back(-0.0f);
    angles.push_back(std::nextafter(kLargestAngle, 0.0f));
    angles.push_back(-std::nextafter(kLargestAngle, 0.0f));
    return angles;
}

TEST(SineCosine, WithinAFewUnitsOfTheLastPlaceOverTheCoveredRange) {
    double worst = 0.0;
    float worstAngle = 0.0f;
    for (const float a : testAngles()) {
        ASSERT_TRUE(coveredAngles(a)) << a;
        float s, c;
        sineCosine(a, s, c);
        const double error = std::max(std::fabs(s - std::sin(static_cast<double>(a))),
                                      std::fabs(c - std::cos(static_cast<double>(a))));
        if (error > worst) {
            worst = error;
            worstAngle = a;
        }
    }
    // 2^-23 is two units in the last place of a float just below 1 (one of one at 1). Measured
    // over every thousandth of a radian: 7.8e-8 at worst, libm's sinf and cosf 3.3e-8.
    EXPECT_LE(worst, std::ldexp(1.0, -23)) << "at " << worstAngle;
}

TEST(SineCosine, ZeroAndUnitLength) {
    float s, c;
    sineCosine(0.0f, s, c);
    EXPECT_EQ(bitsOf(s), bitsOf(0.0f));
    EXPECT_EQ(c, 1.0f);
    // libm's sin(-0) is -0; the polynomial's is +0 (r + r^3 p(r^2) rounds -0 + +0 to +0). A
    // zero's sign changes no rotated vector beyond the sign of a zero component.
    sineCosine(-0.0f, s, c);
    EXPECT_EQ(s, 0.0f);
    EXPECT_EQ(c, 1.0f);
    for (const float a : testAngles()) {
        sineCosine(a, s, c);
        ASSERT_NEAR(s * s + c * c, 1.0f, 1.0e-6f) << a;
    }
}

TEST(SineCosine, AnglesBeyondTheRangeAndNotFiniteAreLibms) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const float a : {kLargestAngle, -kLargestAngle, 1.0e5f, -3.0e7f, 1.0e30f, inf, -inf}) {
        EXPECT_FALSE(coveredAngles(a)) << a;
        float s, c;
        sineCosine(a, s, c);
        const float libmSine = std::sin(a), libmCosine = std::cos(a);
        EXPECT_EQ(bitsOf(s), bitsOf(libmSine)) << a;
        EXPECT_EQ(bitsOf(c), bitsOf(libmCosine)) << a;
    }
    EXPECT_FALSE(coveredAngles(nan));
    float s, c;
    sineCosine(nan, s, c);
    EXPECT_TRUE(std::isnan(s));
    EXPECT_TRUE(std::isnan(c));
}

#if PIVOT_LANES_4
// Every lane of a vector gives the scalar call's bits.
template <typename F>
void expectLanesMatchScalar() {
    constexpr int W = F::kWidth;
    const std::vector<float> angles = testAngles();
    for (std::size_t first = 0; first + W <= angles.size(); first += W) {
        F s, c;
        polynomialSineCosine(F::load(&angles[first]), s, c);
        float ls[W], lc[W];
        lanes::store(ls, s);
        lanes::store(lc, c);
        for (int lane = 0; lane < W; ++lane) {
            float ss, sc;
            polynomialSineCosine(angles[first + lane], ss, sc);
            ASSERT_EQ(bitsOf(ls[lane]), bitsOf(ss)) << angles[first + lane];
            ASSERT_EQ(bitsOf(lc[lane]), bitsOf(sc)) << angles[first + lane];
        }
    }
    const float mixed[8] = {0.5f, 1.0e6f,         -2.0f, std::numeric_limits<float>::quiet_NaN(),
                            3.0f, -kLargestAngle, 7.0f,  8191.0f};
    const F covered = coveredAngles(F::load(mixed));
    float flags[W];
    lanes::store(flags, covered);
    for (int lane = 0; lane < W; ++lane) {
        EXPECT_EQ(bitsOf(flags[lane]) != 0, static_cast<bool>(coveredAngles(mixed[lane]))) << lane;
    }
}

TEST(SineCosine, FourLanesGiveTheScalarBits) {
    expectLanesMatchScalar<lanes::F4>();
}
#endif

#if PIVOT_LANES_8
TEST(SineCosine, EightLanesGiveTheScalarBits) {
    expectLanesMatchScalar<lanes::F8>();
}
#endif

// polynomialRotations, as a substepped world measures its bodies' rotations: each is the scalar
// call's, whatever run it falls in (runs of any length, with a tail, and with lanes the
// polynomial does not cover among covered ones).
TEST(SineCosine, RotationsAtOnceGiveTheScalarBits) {
    std::vector<float> angles = testAngles();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const float odd : {1.0e6f, nan, -kLargestAngle, std::numeric_limits<float>::infinity()}) {
        angles.insert(angles.begin() + 3, odd);
        angles.push_back(odd);
    }
    for (const int begin : {0, 1, 5}) {
        for (const int trim : {0, 3, 7}) {
            const int end = static_cast<int>(angles.size()) - trim;
            std::vector<Rot> rotations(angles.size());
            polynomialRotations(
                begin, end, [&](int i) { return angles[static_cast<std::size_t>(i)]; },
                [&](int i, Rot q) { rotations[static_cast<std::size_t>(i)] = q; });
            for (int i = begin; i < end; ++i) {
                const float a = angles[static_cast<std::size_t>(i)];
                const Rot one = rotationOf(a, true);
                const Rot& many = rotations[static_cast<std::size_t>(i)];
                if (std::isnan(a)) {
                    ASSERT_TRUE(std::isnan(many.s) && std::isnan(many.c)) << i;
                    continue;
                }
                ASSERT_EQ(bitsOf(many.s), bitsOf(one.s)) << a;
                ASSERT_EQ(bitsOf(many.c), bitsOf(one.c)) << a;
            }
        }
    }
}

}  // namespace
