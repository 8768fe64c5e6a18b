// Floats in SIMD lanes with the scalar operators, for the contact solver's wide sweeps
// (contact_solver_wide.cpp): F4, four lanes of SSE2 (the x86-64 baseline), and, when the build
// targets AVX2 (the PIVOT_AVX2 option), F8, eight lanes.
//
// Every operation rounds each lane exactly as the scalar operation does: add, subtract,
// multiply, divide and square root are IEEE-exact in both widths, nothing is fused (the build
// never contracts a*b+c into one rounding, and AVX2 does not imply FMA), and the choices below
// (maxOf, clampOf, the comparisons) make std::max's and std::clamp's choices for ties, signed
// zeros and NaN. So a lane computes the same bits as the one-contact code, whatever the width.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#define PIVOT_LANES_4 1
#endif
#if defined(__AVX2__)
#include <immintrin.h>
#define PIVOT_LANES_8 1
#endif

namespace pivot {
namespace lanes {

#if PIVOT_LANES_4

struct F4 {
    static constexpr int kWidth = 4;
    __m128 v;
    F4() : v(_mm_setzero_ps()) {}
    explicit F4(__m128 m) : v(m) {}
    explicit F4(float s) : v(_mm_set1_ps(s)) {}

    static F4 load(const float* p) { return F4(_mm_loadu_ps(p)); }
    /// Lanes where counts[lane] > n (all ones), else zeros.
    static F4 above(const std::int32_t* counts, int n) {
        const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(counts));
        return F4(_mm_castsi128_ps(_mm_cmpgt_epi32(c, _mm_set1_epi32(n))));
    }
    /// Lanes where values[lane] == n (all ones), else zeros.
    static F4 equal(const std::int32_t* values, std::int32_t n) {
        const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(values));
        return F4(_mm_castsi128_ps(_mm_cmpeq_epi32(c, _mm_set1_epi32(n))));
    }
    static F4 allLanes() { return F4(_mm_castsi128_ps(_mm_set1_epi32(-1))); }
};
inline void store(float* p, F4 a) {
    _mm_storeu_ps(p, a.v);
}
inline F4 operator+(F4 a, F4 b) {
    return F4(_mm_add_ps(a.v, b.v));
}
inline F4 operator-(F4 a, F4 b) {
    return F4(_mm_sub_ps(a.v, b.v));
}
inline F4 operator*(F4 a, F4 b) {
    return F4(_mm_mul_ps(a.v, b.v));
}
inline F4 operator/(F4 a, F4 b) {
    return F4(_mm_div_ps(a.v, b.v));
}
inline F4 squareRoot(F4 a) {
    return F4(_mm_sqrt_ps(a.v));
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
inline F4 butNot(F4 a, F4 b) {  // a and not b
    return F4(_mm_andnot_ps(b.v, a.v));
}
// mask ? a : b, lane by lane.
inline F4 select(F4 mask, F4 a, F4 b) {
    return F4(_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v)));
}
inline bool any(F4 mask) {
    return _mm_movemask_ps(mask.v) != 0;
}
inline bool all(F4 mask) {
    return _mm_movemask_ps(mask.v) == 0xf;
}

/// Lane i of x, y, z, w: the four floats at rows[i] (a transpose: one vector load per row
/// instead of four scalar ones). Any of the rows may be the same.
inline void loadColumns(const float* const rows[4], F4& x, F4& y, F4& z, F4& w) {
    __m128 r0 = _mm_loadu_ps(rows[0]), r1 = _mm_loadu_ps(rows[1]);
    __m128 r2 = _mm_loadu_ps(rows[2]), r3 = _mm_loadu_ps(rows[3]);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    x = F4(r0);
    y = F4(r1);
    z = F4(r2);
    w = F4(r3);
}
/// The first three columns only (rows of four floats whose last is a spare).
inline void loadColumns(const float* const rows[4], F4& x, F4& y, F4& z) {
    F4 spare;
    loadColumns(rows, x, y, z, spare);
}
/// The reverse, for lanes [0, count): writes lane i of x, y, z and a zero over the four floats
/// at rows[i] (the rows of lanes below count must be distinct).
inline void storeColumns(float* const rows[4], F4 x, F4 y, F4 z, int count) {
    __m128 r0 = x.v, r1 = y.v, r2 = z.v, r3 = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    const __m128 r[4] = {r0, r1, r2, r3};
    for (int lane = 0; lane < count; ++lane) _mm_storeu_ps(rows[lane], r[lane]);
}

#endif  // PIVOT_LANES_4

#if PIVOT_LANES_8

struct F8 {
    static constexpr int kWidth = 8;
    __m256 v;
    F8() : v(_mm256_setzero_ps()) {}
    explicit F8(__m256 m) : v(m) {}
    explicit F8(float s) : v(_mm256_set1_ps(s)) {}

    static F8 load(const float* p) { return F8(_mm256_loadu_ps(p)); }
    static F8 above(const std::int32_t* counts, int n) {
        const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(counts));
        return F8(_mm256_castsi256_ps(_mm256_cmpgt_epi32(c, _mm256_set1_epi32(n))));
    }
    static F8 equal(const std::int32_t* values, std::int32_t n) {
        const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(values));
        return F8(_mm256_castsi256_ps(_mm256_cmpeq_epi32(c, _mm256_set1_epi32(n))));
    }
    static F8 allLanes() { return F8(_mm256_castsi256_ps(_mm256_set1_epi32(-1))); }
};
inline void store(float* p, F8 a) {
    _mm256_storeu_ps(p, a.v);
}
inline F8 operator+(F8 a, F8 b) {
    return F8(_mm256_add_ps(a.v, b.v));
}
inline F8 operator-(F8 a, F8 b) {
    return F8(_mm256_sub_ps(a.v, b.v));
}
inline F8 operator*(F8 a, F8 b) {
    return F8(_mm256_mul_ps(a.v, b.v));
}
inline F8 operator/(F8 a, F8 b) {
    return F8(_mm256_div_ps(a.v, b.v));
}
inline F8 squareRoot(F8 a) {
    return F8(_mm256_sqrt_ps(a.v));
}
inline F8 operator-(F8 a) {
    return F8(_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f)));
}
// The ordered, non-signalling predicates: false when either lane is NaN, as SSE's cmplt/cmpge.
inline F8 lessThan(F8 a, F8 b) {
    return F8(_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ));
}
inline F8 atLeast(F8 a, F8 b) {
    return F8(_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ));
}
inline F8 both(F8 a, F8 b) {
    return F8(_mm256_and_ps(a.v, b.v));
}
inline F8 either(F8 a, F8 b) {
    return F8(_mm256_or_ps(a.v, b.v));
}
inline F8 butNot(F8 a, F8 b) {
    return F8(_mm256_andnot_ps(b.v, a.v));
}
inline F8 select(F8 mask, F8 a, F8 b) {
    return F8(_mm256_blendv_ps(b.v, a.v, mask.v));
}
inline bool any(F8 mask) {
    return _mm256_movemask_ps(mask.v) != 0;
}
inline bool all(F8 mask) {
    return _mm256_movemask_ps(mask.v) == 0xff;
}

/// As for F4, eight rows.
inline void loadColumns(const float* const rows[8], F8& x, F8& y, F8& z, F8& w) {
    // Rows i and i + 4 side by side, then a 4x4 transpose within each half.
    const __m256 r0 = _mm256_set_m128(_mm_loadu_ps(rows[4]), _mm_loadu_ps(rows[0]));
    const __m256 r1 = _mm256_set_m128(_mm_loadu_ps(rows[5]), _mm_loadu_ps(rows[1]));
    const __m256 r2 = _mm256_set_m128(_mm_loadu_ps(rows[6]), _mm_loadu_ps(rows[2]));
    const __m256 r3 = _mm256_set_m128(_mm_loadu_ps(rows[7]), _mm_loadu_ps(rows[3]));
    const __m256 xy01 = _mm256_unpacklo_ps(r0, r1);  // x0 x1 y0 y1 | x4 x5 y4 y5
    const __m256 xy23 = _mm256_unpacklo_ps(r2, r3);
    const __m256 zw01 = _mm256_unpackhi_ps(r0, r1);  // z0 z1 w0 w1 | z4 z5 w4 w5
    const __m256 zw23 = _mm256_unpackhi_ps(r2, r3);
    x = F8(_mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0)));
    y = F8(_mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2)));
    z = F8(_mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(1, 0, 1, 0)));
    w = F8(_mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(3, 2, 3, 2)));
}
inline void loadColumns(const float* const rows[8], F8& x, F8& y, F8& z) {
    F8 spare;
    loadColumns(rows, x, y, z, spare);
}
inline void storeColumns(float* const rows[8], F8 x, F8 y, F8 z, int count) {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 xy01 = _mm256_unpacklo_ps(x.v, y.v);  // x0 y0 x1 y1 | x4 y4 x5 y5
    const __m256 xy23 = _mm256_unpackhi_ps(x.v, y.v);  // x2 y2 x3 y3 | x6 y6 x7 y7
    const __m256 z01 = _mm256_unpacklo_ps(z.v, zero);  // z0 0 z1 0 | z4 0 z5 0
    const __m256 z23 = _mm256_unpackhi_ps(z.v, zero);
    const __m256 r04 = _mm256_shuffle_ps(xy01, z01, _MM_SHUFFLE(1, 0, 1, 0));  // x0 y0 z0 0 | 4
    const __m256 r15 = _mm256_shuffle_ps(xy01, z01, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 r26 = _mm256_shuffle_ps(xy23, z23, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 r37 = _mm256_shuffle_ps(xy23, z23, _MM_SHUFFLE(3, 2, 3, 2));
    const __m128 r[8] = {_mm256_castps256_ps128(r04),   _mm256_castps256_ps128(r15),
                         _mm256_castps256_ps128(r26),   _mm256_castps256_ps128(r37),
                         _mm256_extractf128_ps(r04, 1), _mm256_extractf128_ps(r15, 1),
                         _mm256_extractf128_ps(r26, 1), _mm256_extractf128_ps(r37, 1)};
    for (int lane = 0; lane < count; ++lane) _mm_storeu_ps(rows[lane], r[lane]);
}

#endif  // PIVOT_LANES_8

// Shared by both widths.
template <typename F>
F maxOf(F a, F b) {  // std::max(a, b): b only if a < b
    return select(lessThan(a, b), b, a);
}
template <typename F>
F clampOf(F x, F lo, F hi) {  // std::clamp(x, lo, hi)
    return select(lessThan(x, lo), lo, select(lessThan(hi, x), hi, x));
}

}  // namespace lanes
}  // namespace pivot
