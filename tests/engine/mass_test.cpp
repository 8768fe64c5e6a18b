// Mass properties against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
BodyId dynamicBody(World& world, Vec2 position = {}) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    return world.createBody(def);
}
ShapeDef withDensity(float density) {
    ShapeDef def;
    def.density = density;
    return def;
}
}  // namespace

TEST(Mass, Circle) {
    // m = rho pi r^2 = 2 pi 0.25; I = m r^2 / 2 about the centre.
    MassData md = computeMass(Circle{{1.0f, -2.0f}, 0.5f}, 2.0f);
    EXPECT_FLOAT_EQ(md.mass, 2.0f * kPi * 0.25f);
    EXPECT_FLOAT_EQ(md.rotationalInertia, md.mass * 0.125f);
    EXPECT_EQ(md.center, (Vec2{1.0f, -2.0f}));
}

TEST(Mass, Box) {
    // 2 m x 1 m, density 3: m = 6, I = m (w^2 + h^2) / 12 = 2.5.
    MassData md = computeMass(Polygon::box(1.0f, 0.5f), 3.0f);
    EXPECT_FLOAT_EQ(md.mass, 6.0f);
    EXPECT_FLOAT_EQ(md.rotationalInertia, 2.5f);
    EXPECT_NEAR(md.center.x, 0.0f, 1e-7f);
    EXPECT_NEAR(md.center.y, 0.0f, 1e-7f);
}

TEST(Mass, OffsetRotatedBoxKeepsItsInertiaAboutItsOwnCentre) {
    MassData md = computeMass(Polygon::box(0.5f, 0.5f, {2.0f, 1.0f}, 0.3f), 1.0f);
    EXPECT_NEAR(md.mass, 1.0f, 1e-6f);
    EXPECT_NEAR(md.center.x, 2.0f, 1e-6f);
    EXPECT_NEAR(md.center.y, 1.0f, 1e-6f);
    EXPECT_NEAR(md.rotationalInertia, 1.0f / 6.0f, 1e-6f);  // a square's I = m a^2 / 6
}

TEST(Mass, RightTriangleEitherWinding) {
    // Legs a = b = 3 m: area 4.5, centroid (1, 1). About the centroid Ix = m b^2 / 18 and
    // Iy = m a^2 / 18, so the polar moment is m (a^2 + b^2) / 18 = 4.5.
    Polygon ccw = Polygon::fromPoints({{0, 0}, {3, 0}, {0, 3}});
    Polygon cw = Polygon::fromPoints({{0, 0}, {0, 3}, {3, 0}});
    for (const Polygon& p : {ccw, cw}) {
        MassData md = computeMass(p, 1.0f);
        EXPECT_NEAR(md.mass, 4.5f, 1e-5f);
        EXPECT_NEAR(md.center.x, 1.0f, 1e-6f);
        EXPECT_NEAR(md.center.y, 1.0f, 1e-6f);
        EXPECT_NEAR(md.rotationalInertia, 4.5f, 1e-5f);
    }
}

TEST(Mass, BodyCombinesShapesWithTheParallelAxisTheorem) {
    World world{oneSubstepDef()};
    BodyId body = dynamicBody(world, {10.0f, 0.0f});
    // Two unit squares (density 1) centred at x = -1 and x = +1 in the body frame.
    world.createShape(body, withDensity(1.0f), Polygon::box(0.5f, 0.5f, {-1.0f, 0.0f}, 0.0f));
    world.createShape(body, withDensity(1.0f), Polygon::box(0.5f, 0.5f, {1.0f, 0.0f}, 0.0f));
    EXPECT_NEAR(world.bodyMass(body), 2.0f, 1e-6f);
    EXPECT_NEAR(world.bodyLocalCenter(body).x, 0.0f, 1e-6f);
    // Each square: 1/6 about its centre + 1 * 1^2 moved to the body centre.
    EXPECT_NEAR(world.bodyRotationalInertia(body), 2.0f * (1.0f / 6.0f + 1.0f), 1e-5f);
    EXPECT_NEAR(world.bodyWorldCenter(body).x, 10.0f, 1e-5f);
}

TEST(Mass, OffCentreShapeMovesTheCentreOfMass) {
    World world{oneSubstepDef()};
    BodyId body = dynamicBody(world, {1.0f, 1.0f});
    world.createShape(body, withDensity(2.0f), Circle{{0.0f, 3.0f}, 0.5f});
    EXPECT_NEAR(world.bodyLocalCenter(body).y, 3.0f, 1e-6f);
    EXPECT_NEAR(world.bodyWorldCenter(body).y, 4.0f, 1e-6f);
    EXPECT_NEAR(world.bodyRotationalInertia(body), 2.0f * kPi * 0.25f * 0.125f, 1e-6f);
    // The origin stays where the body was put.
    EXPECT_EQ(world.bodyPosition(body), (Vec2{1.0f, 1.0f}));
}

TEST(Mass, DestroyingAShapeUpdatesTheMass) {
    World world{oneSubstepDef()};
    BodyId body = dynamicBody(world);
    ShapeId a = world.createShape(body, withDensity(1.0f), Polygon::box(0.5f, 0.5f));
    world.createShape(body, withDensity(3.0f), Polygon::box(0.5f, 0.5f));
    EXPECT_NEAR(world.bodyMass(body), 4.0f, 1e-6f);
    world.destroyShape(a);
    EXPECT_NEAR(world.bodyMass(body), 3.0f, 1e-6f);
    EXPECT_EQ(world.shapeCount(), 1);
}

TEST(Mass, StaticAndKinematicBodiesHaveNoMass) {
    World world{oneSubstepDef()};
    BodyDef def;
    BodyId ground = world.createBody(def);
    world.createShape(ground, withDensity(5.0f), Polygon::box(1, 1));
    def.type = BodyType::Kinematic;
    BodyId mover = world.createBody(def);
    world.createShape(mover, withDensity(5.0f), Polygon::box(1, 1));
    EXPECT_EQ(world.bodyMass(ground), 0.0f);
    EXPECT_EQ(world.bodyMass(mover), 0.0f);
    EXPECT_EQ(world.bodyRotationalInertia(mover), 0.0f);
}

TEST(Mass, DynamicBodyWithoutShapesIsAUnitPointMass) {
    World world{oneSubstepDef()};
    BodyId body = dynamicBody(world);
    EXPECT_EQ(world.bodyMass(body), 1.0f);
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
}

TEST(Mass, FixedRotationHasNoRotationalInertia) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.fixedRotation = true;
    BodyId body = world.createBody(def);
    world.createShape(body, withDensity(1.0f), Polygon::box(1, 1));
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
    EXPECT_NEAR(world.bodyMass(body), 4.0f, 1e-6f);
}

TEST(Geometry, ShapesReadBackInTheirBodyFrame) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId body = world.createBody(def);
    ShapeId disc = world.createShape(body, ShapeDef{}, Circle{{1.0f, 2.0f}, 0.25f});
    // Given clockwise, stored and returned counter-clockwise.
    ShapeId tri =
        world.createShape(body, ShapeDef{}, Polygon::fromPoints({{0, 0}, {0, 1}, {1, 0}}));
    EXPECT_EQ(world.shapeType(disc), ShapeType::Circle);
    EXPECT_EQ(world.shapeCircle(disc).radius, 0.25f);
    EXPECT_EQ(world.shapeCircle(disc).center, (Vec2{1.0f, 2.0f}));
    Polygon p = world.shapePolygon(tri);
    ASSERT_EQ(p.count, 3);  // the clockwise input, reversed
    EXPECT_EQ(p.vertices[0], (Vec2{1, 0}));
    EXPECT_EQ(p.vertices[1], (Vec2{0, 1}));
    EXPECT_EQ(p.vertices[2], (Vec2{0, 0}));
    EXPECT_THROW(world.shapeCircle(tri), Error);
    EXPECT_THROW(world.shapePolygon(disc), Error);
    std::vector<ShapeId> shapes = world.bodyShapes(body);
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_EQ(shapes[0], tri);  // newest first
    EXPECT_EQ(world.bodyIds().size(), 1u);
    EXPECT_TRUE(world.jointIds().empty());
}

// Far from the body origin, shifting the second moment about the origin to the centre of mass
// subtracts two nearly equal huge numbers; the body must still get its shape's own inertia.
TEST(Mass, AShapeFarFromTheBodyOriginKeepsItsInertia) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Circle{{kMaxCoordinate, -0.9f}, 1.0f});
    float mass = kPi;
    EXPECT_FLOAT_EQ(world.bodyMass(body), mass);
    EXPECT_NEAR(world.bodyRotationalInertia(body), 0.5f * mass, 1e-3f * mass);
    world.createShape(body, ShapeDef{},
                      Polygon::box(1.0f, 1.0f, {kMaxCoordinate - 2.0f, 2.0f}, 0.3f));
    EXPECT_GT(world.bodyRotationalInertia(body), 0.5f * mass);
    world.setBodyAngularVelocity(body, 1.0f);
    for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
    EXPECT_TRUE(isFinite(world.bodyPosition(body)));
    EXPECT_NEAR(world.bodyAngularVelocity(body), 1.0f, 1e-3f);
}

// Polygon::convexHull: random clouds give a valid polygon that holds every point.
TEST(ConvexHull, OfRandomCloudsIsValidAndHoldsEveryPoint) {
    std::mt19937 random(7);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(random);
    };
    int made = 0, tooManyCorners = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<Vec2> cloud;
        const int n = 3 + static_cast<int>(uniform(0.0f, 30.0f));
        const Vec2 center{uniform(-100.0f, 100.0f), uniform(-100.0f, 100.0f)};
        const float scale = uniform(0.05f, 3.0f);
        for (int i = 0; i < n; ++i) {
            cloud.push_back(center +
                            Vec2{scale * uniform(-1.0f, 1.0f), scale * uniform(-1.0f, 1.0f)});
        }
        if (trial % 5 == 0) cloud.push_back(cloud.front());  // a repeated point
        Polygon hull;
        try {
            hull = Polygon::convexHull(cloud.data(), static_cast<int>(cloud.size()));
        } catch (const Error& e) {
            // The only refusal a cloud of this kind may get: too many corners for a polygon.
            EXPECT_NE(std::string(e.what()).find("more than kMaxPolygonVertices"),
                      std::string::npos)
                << e.what();
            ++tooManyCorners;
            continue;
        }
        ++made;
        // Accepted as a shape as it is, and counter-clockwise.
        EXPECT_GT(computeMass(hull, 1.0f).mass, 0.0f);
        for (int i = 0; i < hull.count; ++i) {
            const Vec2 a = hull.vertices[i], b = hull.vertices[(i + 1) % hull.count];
            const Vec2 outward{b.y - a.y, a.x - b.x};
            for (Vec2 p : cloud) {
                // Every point inside or on the hull, up to the slop its cleaning may drop.
                EXPECT_LE(dot(outward, p - a) / length(outward), kLinearSlop) << trial;
            }
        }
    }
    EXPECT_GT(made, 1000);
    EXPECT_GT(tooManyCorners, 0);  // the big clouds do reach the limit
}

TEST(ConvexHull, RefusesCloudsWithoutAreaOrBadPoints) {
    EXPECT_THROW(Polygon::convexHull({{0, 0}, {1, 0}}), Error);
    EXPECT_THROW(Polygon::convexHull({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), Error);    // on a line
    EXPECT_THROW(Polygon::convexHull({{0, 0}, {0.001f, 0}, {0, 0.001f}}), Error);  // a speck
    EXPECT_THROW(Polygon::convexHull({{0, 0}, {1, 0}, {std::nanf(""), 1}}), Error);
    EXPECT_THROW(Polygon::convexHull({{0, 0}, {1, 0}, {0, 2e5f}}), Error);
    // A square with points inside, on its edges and repeated comes back as the square.
    const Polygon square = Polygon::convexHull(
        {{0.5f, 0.5f}, {1, 0}, {0, 0}, {1, 1}, {0, 1}, {0.5f, 0}, {0, 0}, {1, 0.3f}});
    ASSERT_EQ(square.count, 4);
    EXPECT_NEAR(computeMass(square, 1.0f).mass, 1.0f, 1e-6f);
}
