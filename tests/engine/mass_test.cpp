// Mass properties against values worked out by hand.
#include <gtest/gtest.h>

#include "pivot/pivot.h"

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
    World world;
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
    World world;
    BodyId body = dynamicBody(world, {1.0f, 1.0f});
    world.createShape(body, withDensity(2.0f), Circle{{0.0f, 3.0f}, 0.5f});
    EXPECT_NEAR(world.bodyLocalCenter(body).y, 3.0f, 1e-6f);
    EXPECT_NEAR(world.bodyWorldCenter(body).y, 4.0f, 1e-6f);
    EXPECT_NEAR(world.bodyRotationalInertia(body), 2.0f * kPi * 0.25f * 0.125f, 1e-6f);
    // The origin stays where the body was put.
    EXPECT_EQ(world.bodyPosition(body), (Vec2{1.0f, 1.0f}));
}

TEST(Mass, DestroyingAShapeUpdatesTheMass) {
    World world;
    BodyId body = dynamicBody(world);
    ShapeId a = world.createShape(body, withDensity(1.0f), Polygon::box(0.5f, 0.5f));
    world.createShape(body, withDensity(3.0f), Polygon::box(0.5f, 0.5f));
    EXPECT_NEAR(world.bodyMass(body), 4.0f, 1e-6f);
    world.destroyShape(a);
    EXPECT_NEAR(world.bodyMass(body), 3.0f, 1e-6f);
    EXPECT_EQ(world.shapeCount(), 1);
}

TEST(Mass, StaticAndKinematicBodiesHaveNoMass) {
    World world;
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
    World world;
    BodyId body = dynamicBody(world);
    EXPECT_EQ(world.bodyMass(body), 1.0f);
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
}

TEST(Mass, FixedRotationHasNoRotationalInertia) {
    World world;
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.fixedRotation = true;
    BodyId body = world.createBody(def);
    world.createShape(body, withDensity(1.0f), Polygon::box(1, 1));
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
    EXPECT_NEAR(world.bodyMass(body), 4.0f, 1e-6f);
}

TEST(Geometry, ShapesReadBackInTheirBodyFrame) {
    World world;
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
    World world;
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
