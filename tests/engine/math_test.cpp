#include <gtest/gtest.h>

#include "pivot/math.h"

using namespace pivot;

TEST(Math, CrossProductsFollowTheRightHandRule) {
    EXPECT_EQ(cross(Vec2{1, 0}, Vec2{0, 1}), 1.0f);
    EXPECT_EQ(cross(Vec2{0, 1}, Vec2{1, 0}), -1.0f);
    // w x r for w about +z: (1,0) turns towards +y.
    EXPECT_EQ(cross(2.0f, Vec2{1, 0}), (Vec2{0, 2}));
    EXPECT_EQ(cross(Vec2{1, 0}, 2.0f), (Vec2{0, -2}));
    EXPECT_EQ(leftPerp(Vec2{3, 4}), (Vec2{-4, 3}));
}

TEST(Math, RotationTurnsCounterClockwiseAndInvertsExactlyEnough) {
    Rot q(kPi / 2.0f);
    Vec2 v = rotate(q, Vec2{1, 0});
    EXPECT_NEAR(v.x, 0.0f, 1e-7f);
    EXPECT_NEAR(v.y, 1.0f, 1e-7f);
    Vec2 back = inverseRotate(q, v);
    EXPECT_NEAR(back.x, 1.0f, 1e-7f);
    EXPECT_NEAR(back.y, 0.0f, 1e-7f);
    EXPECT_NEAR(Rot(0.7f).angle(), 0.7f, 1e-6f);
}

TEST(Math, TransformRoundTrip) {
    Transform xf{{3, -2}, Rot(0.4f)};
    Vec2 p{1.5f, 0.25f};
    Vec2 world = transformPoint(xf, p);
    Vec2 local = inverseTransformPoint(xf, world);
    EXPECT_NEAR(local.x, p.x, 1e-6f);
    EXPECT_NEAR(local.y, p.y, 1e-6f);
    // The origin maps to the translation.
    EXPECT_EQ(transformPoint(xf, Vec2{}), xf.p);
}

TEST(Math, Mat22SolvesByCramersRule) {
    // [2 1; 1 3] x = [3; 5]  =>  x = [0.8; 1.4]
    Mat22 a{{2, 1}, {1, 3}};
    Vec2 x = a.solve({3, 5});
    EXPECT_NEAR(x.x, 0.8f, 1e-6f);
    EXPECT_NEAR(x.y, 1.4f, 1e-6f);
}

TEST(Math, Mat22WhoseProductsOverflowIsSolvedRescaled) {
    // [4 1; 1 3] 1e20: det = 11e40 overflows a float, so Cramer's rule runs on the matrix / 4e20.
    Mat22 a{{4e20f, 1e20f}, {1e20f, 3e20f}};
    Vec2 x = a.solve({1, 1});
    EXPECT_NEAR(x.x, 2.0f / 11.0f * 1e-20f, 1e-6f * 1e-20f);
    EXPECT_NEAR(x.y, 3.0f / 11.0f * 1e-20f, 1e-6f * 1e-20f);
    const Mat22 inverse = a.inverse();
    EXPECT_NEAR(inverse.cx.x, 3.0f / 11.0f * 1e-20f, 1e-6f * 1e-20f);
    EXPECT_NEAR(inverse.cy.y, 4.0f / 11.0f * 1e-20f, 1e-6f * 1e-20f);
    EXPECT_EQ(a.cramer().invDet, a.rescaledCramer().invDet);
}

TEST(Math, SingularMatrixGivesZeroInsteadOfInfinity) {
    Mat22 singular{{1, 2}, {2, 4}};
    EXPECT_EQ(singular.solve({1, 1}), (Vec2{0, 0}));
}
