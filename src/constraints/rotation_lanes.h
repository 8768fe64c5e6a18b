// Many rotations at once: the sine and cosine of a run of angles by core/sine_cosine.h's
// polynomial, eight lanes at a time where the build has AVX2, four with SSE2, one at a time for
// the rest. A lane gives the bits the scalar call gives (sine_cosine.h), so the result is the
// same for any build width, any worker count and any cut of the run into blocks.
//
// Why: a substepped world measures every body's rotation at every substep (for the contacts'
// and joints' set-up, and the soft contacts' motion since the step began). One at a time, libm's
// sincosf was 5% of `many_chains`' soft step; eight lanes of the polynomial cost a fraction of
// that. Worlds of one substep keep libm, whose bits the Box2D 2.4.1 reference tests compare.
#pragma once

#include "constraints/lanes.h"
#include "core/sine_cosine.h"

namespace pivot {

/// store(i, Rot) for i in [begin, end), with the rotation by angleOf(i) (a float), as
/// rotationOf(angleOf(i), true) gives it.
template <typename AngleOf, typename Store>
void polynomialRotations(int begin, int end, const AngleOf& angleOf, const Store& store) {
    int i = begin;
#if PIVOT_LANES_8
    using Lanes = lanes::F8;
#elif PIVOT_LANES_4
    using Lanes = lanes::F4;
#endif
#if PIVOT_LANES_8 || PIVOT_LANES_4
    constexpr int W = Lanes::kWidth;
    for (; i + W <= end; i += W) {
        float a[W], s[W], c[W];
        for (int lane = 0; lane < W; ++lane) a[lane] = angleOf(i + lane);
        const Lanes angles = Lanes::load(a);
        if (all(coveredAngles(angles))) {
            Lanes sines, cosines;
            polynomialSineCosine(angles, sines, cosines);
            lanes::store(s, sines);
            lanes::store(c, cosines);
            for (int lane = 0; lane < W; ++lane) {
                Rot q;
                q.s = s[lane];
                q.c = c[lane];
                store(i + lane, q);
            }
        } else {
            for (int lane = 0; lane < W; ++lane) store(i + lane, rotationOf(a[lane], true));
        }
    }
#endif
    for (; i < end; ++i) store(i, rotationOf(angleOf(i), true));
}

}  // namespace pivot
