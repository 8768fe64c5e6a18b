// The narrow phase against cases worked out by hand: circles, polygon against circle (face,
// vertex and inside regions), and polygon against polygon (resting, on a corner, apart,
// clipped, the reference face on either shape), plus the world manifold of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "collision/manifold.h"

using namespace pivot;

namespace {

// Hand-computed lengths are exact to a few float ulps of the 1 m scale.
constexpr float kTol = 1e-5f;
constexpr float kTotalRadius = 2.0f * kPolygonRadius;

Transform at(float x, float y, float angle = 0.0f) {
    Transform xf;
    xf.p = {x, y};
    xf.q = Rot(angle);
    return xf;
}

// Vertices 0..3 are (-hx,-hy), (hx,-hy), (hx,hy), (-hx,hy); faces 0..3 are bottom, right,
// top, left.
ConvexPolygon box(float hx, float hy) {
    ConvexPolygon p;
    const std::string error = makeConvexPolygon(Polygon::box(hx, hy), p);
    EXPECT_EQ(error, "");
    return p;
}

std::uint32_t id(int indexA, int indexB, FeatureType typeA, FeatureType typeB) {
    return makeFeatureId(static_cast<std::uint8_t>(indexA), static_cast<std::uint8_t>(indexB),
                         typeA, typeB);
}

constexpr FeatureType kFace = FeatureType::Face;
constexpr FeatureType kVertex = FeatureType::Vertex;

void expectVec(Vec2 actual, Vec2 expected, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, kTol) << what;
    EXPECT_NEAR(actual.y, expected.y, kTol) << what;
}

// Largest separation over the faces of p1 (world frame, double precision): for each face, how
// far p2's deepest vertex lies in front of it. Independent of the code under test.
double maxFaceSeparation(const ConvexPolygon& p1, const Transform& xf1, const ConvexPolygon& p2,
                         const Transform& xf2) {
    double best = -1e30;
    for (int i = 0; i < p1.count; ++i) {
        const double c1 = xf1.q.c, s1 = xf1.q.s;
        const Vec2 n = p1.normals[i];
        const Vec2 v = p1.vertices[i];
        const double nx = c1 * n.x - s1 * n.y, ny = s1 * n.x + c1 * n.y;
        const double vx = c1 * v.x - s1 * v.y + xf1.p.x, vy = s1 * v.x + c1 * v.y + xf1.p.y;
        double deepest = 1e30;
        for (int j = 0; j < p2.count; ++j) {
            const double c2 = xf2.q.c, s2 = xf2.q.s;
            const Vec2 w = p2.vertices[j];
            const double wx = c2 * w.x - s2 * w.y + xf2.p.x, wy = s2 * w.x + c2 * w.y + xf2.p.y;
            deepest = std::min(deepest, nx * (wx - vx) + ny * (wy - vy));
        }
        best = std::max(best, deepest);
    }
    return best;
}

}  // namespace

// --- feature ids ------------------------------------------------------------------------------

TEST(FeatureId, PacksLikeBox2dsContactFeatureKey) {
    // Little-endian bytes: indexA, indexB, typeA, typeB.
    EXPECT_EQ(makeFeatureId(3, 5, FeatureType::Vertex, FeatureType::Face), 0x01000503u);
    EXPECT_EQ(makeFeatureId(0, 0, FeatureType::Face, FeatureType::Vertex), 0x00010000u);
}

// --- circles ----------------------------------------------------------------------------------

TEST(CollideCircles, OverlappingGiveOnePointMidwayBetweenTheSurfaces) {
    const Circle a{{0.0f, 0.0f}, 0.5f};
    const Circle b{{0.0f, 0.0f}, 0.5f};
    Manifold m;
    collideCircles(m, a, at(1.0f, 2.0f), b, at(1.8f, 2.0f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_EQ(m.type, ManifoldType::Circles);
    EXPECT_EQ(m.points[0].id, 0u);

    // Surfaces at x = 1.5 (A) and 1.3 (B): 0.2 m of overlap, midpoint 1.4.
    const WorldManifold w = computeWorldManifold(m, at(1.0f, 2.0f), 0.5f, at(1.8f, 2.0f), 0.5f);
    expectVec(w.normal, {1.0f, 0.0f}, "normal");
    expectVec(w.points[0], {1.4f, 2.0f}, "point");
    EXPECT_NEAR(w.separations[0], -0.2f, kTol);
}

TEST(CollideCircles, KeepsCentresInTheBodyFramesOfTurnedBodies) {
    // A's body is turned a quarter turn, so its circle at local (1, 0) sits at world (0, 1).
    const Circle a{{1.0f, 0.0f}, 0.5f};
    const Circle b{{0.0f, -0.7f}, 0.4f};
    const Transform xfA = at(0.0f, 0.0f, 0.5f * kPi);
    const Transform xfB = at(0.0f, 2.5f);  // B's centre at world (0, 1.8)
    Manifold m;
    collideCircles(m, a, xfA, b, xfB);
    ASSERT_EQ(m.pointCount, 1);
    expectVec(m.localPoint, {1.0f, 0.0f}, "localPoint is A's centre in A's frame");
    expectVec(m.points[0].localPoint, {0.0f, -0.7f}, "point is B's centre in B's frame");

    const WorldManifold w = computeWorldManifold(m, xfA, 0.5f, xfB, 0.4f);
    expectVec(w.normal, {0.0f, 1.0f}, "normal");
    expectVec(w.points[0], {0.0f, 1.45f}, "midway between y = 1.5 and y = 1.4");
    EXPECT_NEAR(w.separations[0], -0.1f, kTol);
}

TEST(CollideCircles, ApartGiveNoPoint) {
    Manifold m;
    collideCircles(m, Circle{{}, 0.5f}, at(0.0f, 0.0f), Circle{{}, 0.5f}, at(1.01f, 0.0f));
    EXPECT_EQ(m.pointCount, 0);
}

TEST(CollideCircles, JustWithinAndExactlyAtTheRadiusTouch) {
    Manifold m;
    collideCircles(m, Circle{{}, 0.5f}, at(0.0f, 0.0f), Circle{{}, 0.5f}, at(0.0f, 0.999f));
    ASSERT_EQ(m.pointCount, 1);
    WorldManifold w = computeWorldManifold(m, at(0.0f, 0.0f), 0.5f, at(0.0f, 0.999f), 0.5f);
    expectVec(w.normal, {0.0f, 1.0f}, "normal");
    EXPECT_NEAR(w.separations[0], -0.001f, 1e-6f);

    // 1.0 is exact in float: distance equal to the radius sum counts as touching.
    collideCircles(m, Circle{{}, 0.5f}, at(0.0f, 0.0f), Circle{{}, 0.5f}, at(1.0f, 0.0f));
    ASSERT_EQ(m.pointCount, 1);
    w = computeWorldManifold(m, at(0.0f, 0.0f), 0.5f, at(1.0f, 0.0f), 0.5f);
    EXPECT_EQ(w.separations[0], 0.0f);
}

TEST(CollideCircles, ConcentricCirclesUseTheXAxis) {
    Manifold m;
    collideCircles(m, Circle{{}, 0.5f}, at(2.0f, 3.0f), Circle{{}, 0.25f}, at(2.0f, 3.0f));
    ASSERT_EQ(m.pointCount, 1);
    const WorldManifold w = computeWorldManifold(m, at(2.0f, 3.0f), 0.5f, at(2.0f, 3.0f), 0.25f);
    expectVec(w.normal, {1.0f, 0.0f}, "normal");
    EXPECT_NEAR(w.separations[0], -0.75f, kTol);
}

// --- polygon against circle -------------------------------------------------------------------

TEST(CollidePolygonAndCircle, CircleAgainstAFace) {
    // Unit box; circle of radius 0.25 centred 0.2 m above the top face, off-centre.
    const ConvexPolygon square = box(0.5f, 0.5f);
    const Circle ball{{}, 0.25f};
    Manifold m;
    collidePolygonAndCircle(m, square, at(0.0f, 0.0f), ball, at(0.2f, 0.7f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.localNormal, {0.0f, 1.0f}, "top face normal");
    expectVec(m.localPoint, {0.0f, 0.5f}, "top face centre");
    expectVec(m.points[0].localPoint, {0.0f, 0.0f}, "circle centre in B's frame");
    EXPECT_EQ(m.points[0].id, 0u);

    // Box surface at 0.5 + skin = 0.51, ball surface at 0.7 - 0.25 = 0.45.
    const WorldManifold w =
        computeWorldManifold(m, at(0.0f, 0.0f), kPolygonRadius, at(0.2f, 0.7f), 0.25f);
    expectVec(w.normal, {0.0f, 1.0f}, "normal");
    expectVec(w.points[0], {0.2f, 0.48f}, "point");
    EXPECT_NEAR(w.separations[0], -0.06f, kTol);
}

TEST(CollidePolygonAndCircle, FaceContactCountsThePolygonSkin) {
    const ConvexPolygon square = box(0.5f, 0.5f);
    Manifold m;
    // Centre 0.2 m out: radius 0.18 + skin 0.01 falls short, 0.195 + 0.01 reaches.
    collidePolygonAndCircle(m, square, at(0.0f, 0.0f), Circle{{}, 0.18f}, at(0.2f, 0.7f));
    EXPECT_EQ(m.pointCount, 0);
    collidePolygonAndCircle(m, square, at(0.0f, 0.0f), Circle{{}, 0.195f}, at(0.2f, 0.7f));
    ASSERT_EQ(m.pointCount, 1);
    const WorldManifold w =
        computeWorldManifold(m, at(0.0f, 0.0f), kPolygonRadius, at(0.2f, 0.7f), 0.195f);
    EXPECT_NEAR(w.separations[0], -0.005f, kTol);
}

TEST(CollidePolygonAndCircle, CircleAgainstACornerUsesTheVertexRegion) {
    // Centre (0.7, 0.65) is beyond corner (0.5, 0.5) on both axes: the normal is along
    // (0.2, 0.15), i.e. (0.8, 0.6), and the distance to the corner is 0.25.
    const ConvexPolygon square = box(0.5f, 0.5f);
    Manifold m;
    collidePolygonAndCircle(m, square, at(0.0f, 0.0f), Circle{{}, 0.3f}, at(0.7f, 0.65f));
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.localNormal, {0.8f, 0.6f}, "corner normal");
    expectVec(m.localPoint, {0.5f, 0.5f}, "the corner");

    // Surfaces at the corner + 0.01 n and the centre - 0.3 n = corner - 0.05 n.
    const WorldManifold w =
        computeWorldManifold(m, at(0.0f, 0.0f), kPolygonRadius, at(0.7f, 0.65f), 0.3f);
    expectVec(w.normal, {0.8f, 0.6f}, "normal");
    expectVec(w.points[0], {0.484f, 0.488f}, "corner - 0.02 n");
    EXPECT_NEAR(w.separations[0], -0.06f, kTol);
}

TEST(CollidePolygonAndCircle, CornerAtTheStartOfTheNearestFace) {
    // Mirrored across the diagonal: now the top face (from (0.5, 0.5) to (-0.5, 0.5)) is the
    // nearest and the corner is its first vertex.
    Manifold m;
    collidePolygonAndCircle(m, box(0.5f, 0.5f), at(0.0f, 0.0f), Circle{{}, 0.3f}, at(0.65f, 0.7f));
    ASSERT_EQ(m.pointCount, 1);
    expectVec(m.localNormal, {0.6f, 0.8f}, "corner normal");
    expectVec(m.localPoint, {0.5f, 0.5f}, "the corner");
}

TEST(CollidePolygonAndCircle, CornerTestsTheDistanceToTheCornerNotToTheFace) {
    // 0.2 m in front of the nearest face (within radius 0.2 + skin) but 0.25 m from the
    // corner, on either side of the diagonal.
    Manifold m;
    collidePolygonAndCircle(m, box(0.5f, 0.5f), at(0.0f, 0.0f), Circle{{}, 0.2f}, at(0.7f, 0.65f));
    EXPECT_EQ(m.pointCount, 0);
    collidePolygonAndCircle(m, box(0.5f, 0.5f), at(0.0f, 0.0f), Circle{{}, 0.2f}, at(0.65f, 0.7f));
    EXPECT_EQ(m.pointCount, 0);
}

TEST(CollidePolygonAndCircle, CentreInsideLeavesThroughTheNearestFace) {
    // Centre (0.1, 0.3): 0.2 m below the top face, further from the others.
    Manifold m;
    collidePolygonAndCircle(m, box(0.5f, 0.5f), at(0.0f, 0.0f), Circle{{}, 0.1f}, at(0.1f, 0.3f));
    ASSERT_EQ(m.pointCount, 1);
    expectVec(m.localNormal, {0.0f, 1.0f}, "top face normal");
    expectVec(m.localPoint, {0.0f, 0.5f}, "top face centre");
    const WorldManifold w =
        computeWorldManifold(m, at(0.0f, 0.0f), kPolygonRadius, at(0.1f, 0.3f), 0.1f);
    // Box surface 0.51, ball surface 0.3 - 0.1 = 0.2.
    EXPECT_NEAR(w.separations[0], -0.31f, kTol);
    expectVec(w.points[0], {0.1f, 0.355f}, "point");
}

TEST(CollidePolygonAndCircle, NormalIsInThePolygonsFrame) {
    // A 2 x 0.5 plank turned a quarter turn stands at x in [0.75, 1.25]; the ball is 0.15 m
    // right of it. In the plank's frame the ball is below its bottom face.
    const Transform xfA = at(1.0f, 0.0f, 0.5f * kPi);
    Manifold m;
    collidePolygonAndCircle(m, box(1.0f, 0.25f), xfA, Circle{{}, 0.2f}, at(1.4f, 0.3f));
    ASSERT_EQ(m.pointCount, 1);
    expectVec(m.localNormal, {0.0f, -1.0f}, "bottom face normal, plank frame");
    expectVec(m.localPoint, {0.0f, -0.25f}, "bottom face centre");
    const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, at(1.4f, 0.3f), 0.2f);
    expectVec(w.normal, {1.0f, 0.0f}, "world normal");
    expectVec(w.points[0], {1.23f, 0.3f}, "midway between x = 1.26 and x = 1.2");
    EXPECT_NEAR(w.separations[0], -0.06f, kTol);
}

// --- polygon against polygon ------------------------------------------------------------------

TEST(CollidePolygons, BoxRestingOnAWideBox) {
    // Ground A (4 x 1, top at y = 0.5); unit box B with its bottom at 0.495: 5 mm of overlap.
    const ConvexPolygon ground = box(2.0f, 0.5f);
    const ConvexPolygon crate = box(0.5f, 0.5f);
    const Transform xfA = at(0.0f, 0.0f);
    const Transform xfB = at(0.3f, 0.995f);
    Manifold m;
    collidePolygons(m, ground, xfA, crate, xfB);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.localNormal, {0.0f, 1.0f}, "ground's top face");
    expectVec(m.localPoint, {0.0f, 0.5f}, "centre of the top face");
    // The crate's bottom corners, in the crate's frame, each named by (ground face 2, crate
    // vertex).
    expectVec(m.points[0].localPoint, {-0.5f, -0.5f}, "point 0");
    expectVec(m.points[1].localPoint, {0.5f, -0.5f}, "point 1");
    EXPECT_EQ(m.points[0].id, id(2, 0, kFace, kVertex));
    EXPECT_EQ(m.points[1].id, id(2, 1, kFace, kVertex));

    // Cores overlap by 5 mm and each skin adds 1 cm: -0.025. Midway between 0.51 and 0.485.
    const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, xfB, kPolygonRadius);
    expectVec(w.normal, {0.0f, 1.0f}, "normal from A up to B");
    EXPECT_NEAR(w.separations[0], -0.005f - kTotalRadius, kTol);
    EXPECT_NEAR(w.separations[1], -0.005f - kTotalRadius, kTol);
    expectVec(w.points[0], {-0.2f, 0.4975f}, "world point 0");
    expectVec(w.points[1], {0.8f, 0.4975f}, "world point 1");
}

TEST(CollidePolygons, SmallBoxAsAClipsTheGroundsFaceToItsOwnSides) {
    // The same contact with the crate as A. Equal separations keep the reference on A (the
    // crate's bottom face); the ground's top edge is clipped to the crate's sides pushed out by
    // the total radius: x = -0.2 - 0.02 and 0.8 + 0.02.
    const ConvexPolygon crate = box(0.5f, 0.5f);
    const ConvexPolygon ground = box(2.0f, 0.5f);
    const Transform xfA = at(0.3f, 0.995f);
    const Transform xfB = at(0.0f, 0.0f);
    Manifold m;
    collidePolygons(m, crate, xfA, ground, xfB);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.localNormal, {0.0f, -1.0f}, "crate's bottom face");
    expectVec(m.localPoint, {0.0f, -0.5f}, "centre of the bottom face");
    expectVec(m.points[0].localPoint, {-0.22f, 0.5f}, "clipped at the first side");
    expectVec(m.points[1].localPoint, {0.82f, 0.5f}, "clipped at the second side");
    // Each point is where a crate vertex's side plane cuts the ground's top face 2.
    EXPECT_EQ(m.points[0].id, id(0, 2, kVertex, kFace));
    EXPECT_EQ(m.points[1].id, id(1, 2, kVertex, kFace));

    const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, xfB, kPolygonRadius);
    expectVec(w.normal, {0.0f, -1.0f}, "normal from A down to B");
    EXPECT_NEAR(w.separations[0], -0.005f - kTotalRadius, kTol);
    EXPECT_NEAR(w.separations[1], -0.005f - kTotalRadius, kTol);
    expectVec(w.points[0], {-0.22f, 0.4975f}, "world point 0");
    expectVec(w.points[1], {0.82f, 0.4975f}, "world point 1");
}

TEST(CollidePolygons, OverhangingBoxIsClippedAtTheGroundsEnd) {
    // The crate spans x in [1.3, 2.3]; the ground ends at 2. Its outer corner is cut at the
    // ground's side plane, 2 + 0.02, where ground vertex 2 meets the crate's bottom face 0.
    const Transform xfB = at(1.8f, 0.995f);
    Manifold m;
    collidePolygons(m, box(2.0f, 0.5f), at(0.0f, 0.0f), box(0.5f, 0.5f), xfB);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.points[0].localPoint, {-0.5f, -0.5f}, "inner corner");
    expectVec(m.points[1].localPoint, {0.22f, -0.5f}, "cut at x = 2.02");
    EXPECT_EQ(m.points[0].id, id(2, 0, kFace, kVertex));
    EXPECT_EQ(m.points[1].id, id(2, 0, kVertex, kFace));
}

TEST(CollidePolygons, BoxOnItsCornerHasOnePoint) {
    // A unit box turned 45 degrees with its lowest corner (vertex 0) 5 mm into the ground.
    const Transform xfB = at(0.1f, 0.5f + std::sqrt(0.5f) - 0.005f, 0.25f * kPi);
    const Transform xfA = at(0.0f, 0.0f);
    Manifold m;
    collidePolygons(m, box(2.0f, 0.5f), xfA, box(0.5f, 0.5f), xfB);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_EQ(m.type, ManifoldType::FaceA);
    expectVec(m.localNormal, {0.0f, 1.0f}, "ground's top face");
    expectVec(m.points[0].localPoint, {-0.5f, -0.5f}, "the corner, box frame");
    EXPECT_EQ(m.points[0].id, id(2, 0, kFace, kVertex));
    const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, xfB, kPolygonRadius);
    expectVec(w.normal, {0.0f, 1.0f}, "normal");
    EXPECT_NEAR(w.separations[0], -0.005f - kTotalRadius, kTol);
    expectVec(w.points[0], {0.1f, 0.4975f}, "world point");
}

TEST(CollidePolygons, ReferenceFaceOnBWhenBSeparatesBetter) {
    // The corner case with the turned box as A: the ground's face (on B) separates far better
    // than any of the box's faces, so the manifold is FaceB. Ids still name A's feature first,
    // and the world normal still points from A (the box, above) to B (the ground).
    const Transform xfA = at(0.1f, 0.5f + std::sqrt(0.5f) - 0.005f, 0.25f * kPi);
    const Transform xfB = at(0.0f, 0.0f);
    Manifold m;
    collidePolygons(m, box(0.5f, 0.5f), xfA, box(2.0f, 0.5f), xfB);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_EQ(m.type, ManifoldType::FaceB);
    expectVec(m.localNormal, {0.0f, 1.0f}, "ground's top face, ground frame");
    expectVec(m.localPoint, {0.0f, 0.5f}, "centre of the ground's top face");
    expectVec(m.points[0].localPoint, {-0.5f, -0.5f}, "the corner, in A's (box) frame");
    EXPECT_EQ(m.points[0].id, id(0, 2, kVertex, kFace));
    const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, xfB, kPolygonRadius);
    expectVec(w.normal, {0.0f, -1.0f}, "normal from A down to B");
    EXPECT_NEAR(w.separations[0], -0.005f - kTotalRadius, kTol);
    expectVec(w.points[0], {0.1f, 0.4975f}, "world point");
}

TEST(CollidePolygons, ReferenceSwitchesToBOnlyBeyondTheTolerance) {
    // A unit box A under a 4 x 1 plank B whose lowest corner (vertex 0) is 4 mm into A's top
    // face at x = -1.8, and which is tilted up by theta. A's top-left corner then meets the
    // plank's bottom face 1.3 m along it, and B's separation exceeds A's by about 1.3 theta.
    // Sweeping theta takes that margin through the tolerance 0.1 * kLinearSlop: B's face must
    // become the reference only once the margin is beyond it.
    const ConvexPolygon small = box(0.5f, 0.5f);
    const ConvexPolygon plank = box(2.0f, 0.5f);
    const Transform xfA = at(0.0f, 0.0f);
    const double tolerance = 0.1 * kLinearSlop;
    int faceA = 0, faceB = 0, faceAWithBBetter = 0;
    for (int k = 0; k <= 80; ++k) {
        const float theta = 1e-5f * static_cast<float>(k);
        Transform xfB = at(0.0f, 0.0f, theta);
        xfB.p = Vec2{-1.8f, 0.496f} - rotate(xfB.q, Vec2{-2.0f, -0.5f});
        const double margin =
            maxFaceSeparation(plank, xfB, small, xfA) - maxFaceSeparation(small, xfA, plank, xfB);
        Manifold m;
        collidePolygons(m, small, xfA, plank, xfB);
        ASSERT_EQ(m.pointCount, 2) << "theta " << theta;
        // A's top corners 2 and 3 against the plank's bottom face 0, whichever is the
        // reference: unclipped A vertices under B's face, or A's side planes cutting B's face.
        EXPECT_EQ(m.points[0].id, id(2, 0, kVertex, kFace)) << "theta " << theta;
        EXPECT_EQ(m.points[1].id, id(3, 0, kVertex, kFace)) << "theta " << theta;
        const WorldManifold w = computeWorldManifold(m, xfA, kPolygonRadius, xfB, kPolygonRadius);
        EXPECT_GT(w.normal.y, 0.999f) << "normal points from A up to B, theta " << theta;

        if (std::abs(margin - tolerance) < 1e-6) continue;  // a tie with the tolerance itself
        const ManifoldType expected =
            margin > tolerance ? ManifoldType::FaceB : ManifoldType::FaceA;
        EXPECT_EQ(m.type, expected) << "theta " << theta << " margin " << margin;
        if (m.type == ManifoldType::FaceA) ++faceA;
        if (m.type == ManifoldType::FaceB) ++faceB;
        if (m.type == ManifoldType::FaceA && margin > 1e-6) ++faceAWithBBetter;
    }
    // The sweep really crosses the tolerance, and a plain "larger separation wins" rule would
    // have switched earlier.
    EXPECT_GT(faceA, 10);
    EXPECT_GT(faceB, 10);
    EXPECT_GT(faceAWithBBetter, 10);
}

TEST(CollidePolygons, ApartBeyondTheTotalRadiusGiveNoPoints) {
    // Unit boxes one above the other: a gap of 21 mm is beyond the two skins (20 mm), 19 mm is
    // within them.
    const ConvexPolygon crate = box(0.5f, 0.5f);
    Manifold m;
    collidePolygons(m, crate, at(0.0f, 0.0f), crate, at(0.0f, 1.021f));
    EXPECT_EQ(m.pointCount, 0);
    collidePolygons(m, crate, at(0.0f, 0.0f), crate, at(1.021f, 0.3f));
    EXPECT_EQ(m.pointCount, 0);

    collidePolygons(m, crate, at(0.0f, 0.0f), crate, at(0.0f, 1.019f));
    ASSERT_EQ(m.pointCount, 2);
    const WorldManifold w =
        computeWorldManifold(m, at(0.0f, 0.0f), kPolygonRadius, at(0.0f, 1.019f), kPolygonRadius);
    EXPECT_NEAR(w.separations[0], 0.019f - kTotalRadius, kTol);
    EXPECT_NEAR(w.separations[1], 0.019f - kTotalRadius, kTol);
}

TEST(CollidePolygons, FeatureIdsStayWhileABoxSlides) {
    const ConvexPolygon ground = box(2.0f, 0.5f);
    const ConvexPolygon crate = box(0.5f, 0.5f);
    // Fully supported, and hanging over the end (one point clipped): each keeps its ids
    // as the crate moves a few centimetres, so warm starting can carry impulses over.
    for (float start : {0.3f, 1.8f}) {
        Manifold before;
        collidePolygons(before, ground, at(0.0f, 0.0f), crate, at(start, 0.995f));
        ASSERT_EQ(before.pointCount, 2);
        EXPECT_NE(before.points[0].id, before.points[1].id);
        for (float dx : {0.01f, 0.05f, -0.03f}) {
            Manifold after;
            collidePolygons(after, ground, at(0.0f, 0.0f), crate, at(start + dx, 0.99f));
            ASSERT_EQ(after.pointCount, 2) << start << " + " << dx;
            EXPECT_EQ(after.type, before.type);
            EXPECT_EQ(after.points[0].id, before.points[0].id) << start << " + " << dx;
            EXPECT_EQ(after.points[1].id, before.points[1].id) << start << " + " << dx;
        }
    }
}

TEST(CollidePolygons, OutputImpulsesAreZero) {
    Manifold m;
    m.points[0].normalImpulse = 3.0f;
    m.points[1].tangentImpulse = -2.0f;
    collidePolygons(m, box(2.0f, 0.5f), at(0.0f, 0.0f), box(0.5f, 0.5f), at(0.3f, 0.995f));
    ASSERT_EQ(m.pointCount, 2);
    for (const ManifoldPoint& p : m.points) {
        EXPECT_EQ(p.normalImpulse, 0.0f);
        EXPECT_EQ(p.tangentImpulse, 0.0f);
    }
}
