// Queries: ray casts on one shape, and the world's ray casts, box and point queries, checked
// against brute force (every shape tested one by one) on randomised worlds that move, gain and
// lose bodies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

Transform at(Vec2 p, float angle) {
    return Transform{p, Rot(angle)};
}

}  // namespace

TEST(RayCastShape, CircleEnteredFromOutside) {
    const Circle circle{{0.0f, 0.0f}, 1.0f};
    const auto hit = rayCast(circle, at({2.0f, 3.0f}, 0.7f), {-3.0f, 3.0f}, {10.0f, 0.0f});
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit->shape.isNull());
    EXPECT_NEAR(hit->fraction, 0.4f, 1e-6f);
    EXPECT_NEAR(hit->point.x, 1.0f, 1e-5f);
    EXPECT_NEAR(hit->point.y, 3.0f, 1e-5f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-5f);
    EXPECT_NEAR(hit->normal.y, 0.0f, 1e-5f);
}

TEST(RayCastShape, CircleMissedFromInsideBehindAndShort) {
    const Circle circle{{1.0f, 0.0f}, 0.5f};
    const Transform xf = at({0.0f, 0.0f}, 0.0f);
    EXPECT_FALSE(rayCast(circle, xf, {1.0f, 0.0f}, {5.0f, 0.0f}));   // starts inside
    EXPECT_FALSE(rayCast(circle, xf, {3.0f, 0.0f}, {5.0f, 0.0f}));   // the circle is behind
    EXPECT_FALSE(rayCast(circle, xf, {-3.0f, 0.0f}, {2.0f, 0.0f}));  // stops short
    EXPECT_FALSE(rayCast(circle, xf, {-3.0f, 0.6f}, {9.0f, 0.0f}));  // passes by
    EXPECT_FALSE(rayCast(circle, xf, {-3.0f, 0.0f}, {0.0f, 0.0f}));  // no translation
    EXPECT_TRUE(rayCast(circle, xf, {-3.0f, 0.0f}, {3.5f, 0.0f}));   // just reaches it
}

TEST(RayCastShape, PolygonEnteredThroughTheRightEdge) {
    // A 2 x 1 box turned a quarter turn: 1 wide, 2 tall in the world, centred at (5, 0).
    const Polygon box = Polygon::box(1.0f, 0.5f);
    const Transform xf = at({5.0f, 0.0f}, 0.5f * kPi);
    const auto fromLeft = rayCast(box, xf, {0.0f, 0.5f}, {10.0f, 0.0f});
    ASSERT_TRUE(fromLeft);
    EXPECT_NEAR(fromLeft->fraction, 0.45f, 1e-6f);
    EXPECT_NEAR(fromLeft->normal.x, -1.0f, 1e-5f);
    EXPECT_NEAR(fromLeft->normal.y, 0.0f, 1e-5f);
    const auto fromAbove = rayCast(box, xf, {5.2f, 4.0f}, {0.0f, -10.0f});
    ASSERT_TRUE(fromAbove);
    EXPECT_NEAR(fromAbove->point.y, 1.0f, 1e-5f);
    EXPECT_NEAR(fromAbove->normal.y, 1.0f, 1e-5f);
    EXPECT_FALSE(rayCast(box, xf, {5.0f, 0.0f}, {10.0f, 0.0f}));     // starts inside
    EXPECT_FALSE(rayCast(box, xf, {0.0f, 1.5f}, {10.0f, 0.0f}));     // passes above
    EXPECT_FALSE(rayCast(box, xf, {0.0f, 0.5f}, {4.0f, 0.0f}));      // stops short
    EXPECT_FALSE(rayCast(box, xf, {0.0f, 1.0001f}, {10.0f, 0.0f}));  // parallel, just outside
}

TEST(RayCastShape, TestPointOnBothShapes) {
    const Transform xf = at({1.0f, 1.0f}, 0.3f);
    EXPECT_TRUE(testPoint(Circle{{1.0f, 0.0f}, 0.5f}, xf, transformPoint(xf, {1.4f, 0.0f})));
    EXPECT_FALSE(testPoint(Circle{{1.0f, 0.0f}, 0.5f}, xf, transformPoint(xf, {1.6f, 0.0f})));
    const Polygon triangle = Polygon::fromPoints({{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}});
    EXPECT_TRUE(testPoint(triangle, xf, transformPoint(xf, {0.2f, 0.2f})));
    EXPECT_FALSE(testPoint(triangle, xf, transformPoint(xf, {0.6f, 0.6f})));
}

TEST(RayCastShape, BadInputIsRefused) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Transform xf = at({0.0f, 0.0f}, 0.0f);
    EXPECT_THROW(rayCast(Circle{{0.0f, 0.0f}, 1.0f}, xf, {nan, 0.0f}, {1.0f, 0.0f}), Error);
    EXPECT_THROW(rayCast(Circle{{0.0f, 0.0f}, 1.0f}, xf, {0.0f, 0.0f}, {1.0f, nan}), Error);
    EXPECT_THROW(rayCast(Circle{{0.0f, 0.0f}, -1.0f}, xf, {0.0f, 0.0f}, {1.0f, 0.0f}), Error);
    EXPECT_THROW(rayCast(Circle{{0.0f, 0.0f}, 1.0f}, at({nan, 0.0f}, 0.0f), {}, {1.0f, 0.0f}),
                 Error);
    Polygon flat = Polygon::fromPoints({{0.0f, 0.0f}, {1.0f, 0.0f}, {2.0f, 0.0f}});
    EXPECT_THROW(rayCast(flat, xf, {0.0f, -1.0f}, {0.0f, 2.0f}), Error);
    EXPECT_THROW(testPoint(flat, xf, {0.0f, 0.0f}), Error);
    EXPECT_THROW(testPoint(Circle{{0.0f, 0.0f}, 1.0f}, xf, {2e9f, 0.0f}), Error);
}

namespace {

// A world of circles, boxes and random convex polygons on static, kinematic and dynamic bodies,
// and segments on the static and kinematic ones, with shapes in four categories; `churn` steps it,
// creates and destroys bodies and changes two bodies' types between queries.
WorldDef withBoxes(BroadPhaseBoxes boxes) {
    WorldDef def = oneSubstepDef();
    def.broadPhaseBoxes = boxes;
    return def;
}

struct RandomWorld {
    World world{oneSubstepDef()};
    std::mt19937 random;
    std::vector<BodyId> bodies;

    explicit RandomWorld(unsigned seed, BroadPhaseBoxes boxes = BroadPhaseBoxes::Predictive)
        : world(withBoxes(boxes)), random(seed) {
        BodyId ground = world.createBody(BodyDef{});
        world.createShape(ground, ShapeDef{}, Polygon::box(40.0f, 0.5f, {0.0f, -1.0f}, 0.0f));
        for (int i = 0; i < 150; ++i) addBody();
    }

    float uniform(float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(random);
    }

    void addBody() {
        BodyDef def;
        const int kind = static_cast<int>(uniform(0.0f, 10.0f));
        def.type =
            kind == 0 ? BodyType::Static : (kind == 1 ? BodyType::Kinematic : BodyType::Dynamic);
        def.position = {uniform(-30.0f, 30.0f), uniform(0.0f, 30.0f)};
        def.angle = uniform(-3.0f, 3.0f);
        if (def.type == BodyType::Kinematic) def.linearVelocity = {uniform(-2.0f, 2.0f), 0.0f};
        const BodyId body = world.createBody(def);
        ShapeDef shapeDef;
        shapeDef.filter.categoryBits = static_cast<std::uint16_t>(1u << (bodies.size() % 4));
        const int shapeKind = static_cast<int>(uniform(0.0f, 4.0f));
        if (shapeKind == 3 && def.type != BodyType::Dynamic) {
            const float length = uniform(0.5f, 6.0f);
            if (bodies.size() % 2 == 0) {
                world.createShape(body, shapeDef,
                                  Segment{{-0.5f * length, 0.0f}, {0.5f * length, 0.3f}});
            } else {
                // A zigzag chain (one-sided: rays from behind pass through it).
                const float rise = uniform(-0.5f, 0.5f);
                world.createChain(body, shapeDef,
                                  Chain{{{length, 0.0f},
                                         {0.5f * length, rise},
                                         {0.0f, 0.0f},
                                         {-0.5f * length, rise},
                                         {-length, 0.0f}},
                                        false});
            }
        } else if (shapeKind == 0 && bodies.size() % 3 == 0) {
            const float half = uniform(0.1f, 1.5f);
            world.createShape(body, shapeDef,
                              Capsule{{-half, 0.0f}, {half, 0.2f}, uniform(0.1f, 0.8f)});
        } else if (shapeKind == 0) {
            world.createShape(body, shapeDef,
                              Circle{{uniform(-0.5f, 0.5f), 0.0f}, uniform(0.2f, 1.5f)});
        } else if (shapeKind == 1) {
            const float halfWidth = uniform(0.1f, 2.0f);   // one draw per statement: the
            const float halfHeight = uniform(0.1f, 2.0f);  // same worlds with any compiler
            world.createShape(body, shapeDef, Polygon::box(halfWidth, halfHeight));
        } else {
            // Points on a circle at increasing angles: always convex.
            Polygon polygon;
            polygon.count = 3 + static_cast<int>(uniform(0.0f, 5.0f));
            const float radius = uniform(0.3f, 1.5f);
            for (int k = 0; k < polygon.count; ++k) {
                const float angle = (k + uniform(0.1f, 0.6f)) * 2.0f * kPi / polygon.count;
                polygon.vertices[k] = {radius * std::cos(angle), radius * std::sin(angle)};
            }
            world.createShape(body, shapeDef, polygon);
        }
        bodies.push_back(body);
    }

    void churn() {
        for (int i = 0; i < 20; ++i) world.step(kDt);
        for (int i = 0; i < 10; ++i) {
            const std::size_t k = static_cast<std::size_t>(uniform(0.0f, float(bodies.size())));
            world.destroyBody(bodies[std::min(k, bodies.size() - 1)]);
            bodies.erase(bodies.begin() + std::min(k, bodies.size() - 1));
        }
        for (int i = 0; i < 10; ++i) addBody();
        // A teleport between steps: the queries must see the body where it is now.
        const Vec2 to{uniform(-20.0f, 20.0f), uniform(0.0f, 20.0f)};
        world.setBodyTransform(bodies.front(), to, uniform(-3.0f, 3.0f));
        // Under Compact a static body's shapes live in a tree of their own: they change trees.
        for (BodyId body : bodies) {
            if (world.bodyType(body) == BodyType::Dynamic) {
                world.setBodyType(body, BodyType::Static);
                break;
            }
        }
        for (BodyId body : bodies) {
            if (world.bodyType(body) == BodyType::Static) {
                world.setBodyType(body, BodyType::Kinematic);
                break;
            }
        }
    }

    std::vector<ShapeId> allShapes() const {
        std::vector<ShapeId> shapes;
        for (BodyId body : world.bodyIds()) {
            for (ShapeId shape : world.bodyShapes(body)) shapes.push_back(shape);
        }
        return shapes;
    }
};

bool sees(const QueryFilter& filter, const Filter& shape) {
    return (shape.categoryBits & filter.maskBits) != 0 &&
           (shape.maskBits & filter.categoryBits) != 0;
}

bool contains(const World& world, ShapeId shape, Vec2 point) {
    const Transform xf = world.bodyTransform(world.shapeBody(shape));
    if (world.shapeType(shape) == ShapeType::Segment ||
        world.shapeType(shape) == ShapeType::ChainSegment) {
        return false;  // no inside
    }
    if (world.shapeType(shape) == ShapeType::Capsule) {
        return testPoint(world.shapeCapsule(shape), xf, point);
    }
    return world.shapeType(shape) == ShapeType::Circle
               ? testPoint(world.shapeCircle(shape), xf, point)
               : testPoint(world.shapePolygon(shape), xf, point);
}

bool overlaps(const AABB& a, const AABB& b) {
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y &&
           b.lower.y <= a.upper.y;
}

std::uint64_t key(ShapeId id) {
    return (std::uint64_t(id.generation) << 32) | std::uint32_t(id.index);
}

}  // namespace

TEST(WorldQueries, AgreeWithBruteForceOnRandomWorlds) {
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        // Seeds 3 and 4: Compact broad-phase boxes, which keep static shapes in their own tree.
        RandomWorld r(seed, seed > 2 ? BroadPhaseBoxes::Compact : BroadPhaseBoxes::Predictive);
        int hits = 0, boxFinds = 0, pointFinds = 0;
        for (int round = 0; round < 4; ++round) {
            r.churn();
            const std::vector<ShapeId> shapes = r.allShapes();
            for (int q = 0; q < 200; ++q) {
                QueryFilter filter;
                if (q % 3 == 1) filter.maskBits = 0x5;  // categories 1 and 3
                const Vec2 origin{r.uniform(-40.0f, 40.0f), r.uniform(-5.0f, 40.0f)};
                const Vec2 translation{r.uniform(-60.0f, 60.0f), r.uniform(-60.0f, 60.0f)};

                // Closest hit and every hit, against each shape's own ray cast.
                std::optional<RayHit> expected;
                std::set<std::uint64_t> expectedAll;
                for (ShapeId shape : shapes) {
                    if (!sees(filter, r.world.shapeFilter(shape))) continue;
                    const auto hit = r.world.castRayOnShape(shape, origin, translation);
                    if (!hit) continue;
                    expectedAll.insert(key(shape));
                    if (!expected || hit->fraction < expected->fraction) expected = hit;
                }
                const auto closest = r.world.castRayClosest(origin, translation, filter);
                ASSERT_EQ(closest.has_value(), expected.has_value()) << seed << " " << q;
                if (closest) {
                    ++hits;
                    EXPECT_EQ(closest->fraction, expected->fraction);
                    EXPECT_EQ(closest->point, expected->point);
                }
                std::set<std::uint64_t> all;
                r.world.castRay(origin, translation, filter, [&](const RayHit& hit) {
                    EXPECT_TRUE(all.insert(key(hit.shape)).second) << "reported twice";
                    return 1.0f;
                });
                EXPECT_EQ(all, expectedAll);

                // Boxes.
                const Vec2 corner{r.uniform(-40.0f, 40.0f), r.uniform(-5.0f, 40.0f)};
                const AABB box{corner, corner + Vec2{r.uniform(0.0f, 8.0f), r.uniform(0.0f, 8.0f)}};
                std::set<std::uint64_t> expectedBox, foundBox;
                for (ShapeId shape : shapes) {
                    if (sees(filter, r.world.shapeFilter(shape)) &&
                        overlaps(r.world.shapeAABB(shape), box)) {
                        expectedBox.insert(key(shape));
                    }
                }
                r.world.queryAABB(box, filter, [&](ShapeId shape) {
                    foundBox.insert(key(shape));
                    return true;
                });
                EXPECT_EQ(foundBox, expectedBox);
                boxFinds += static_cast<int>(foundBox.size());

                // Points.
                std::set<std::uint64_t> expectedPoint, foundPoint;
                for (ShapeId shape : shapes) {
                    if (sees(filter, r.world.shapeFilter(shape)) &&
                        contains(r.world, shape, corner)) {
                        expectedPoint.insert(key(shape));
                    }
                }
                r.world.queryPoint(corner, filter, [&](ShapeId shape) {
                    foundPoint.insert(key(shape));
                    return true;
                });
                EXPECT_EQ(foundPoint, expectedPoint);
                pointFinds += static_cast<int>(foundPoint.size());
            }
        }
        // The worlds are dense enough that the comparisons are not all of empty answers (about
        // 60% of the 800 rays hit something).
        EXPECT_GT(hits, 300) << seed;
        EXPECT_GT(boxFinds, 500) << seed;
        EXPECT_GT(pointFinds, 50) << seed;
    }
}

TEST(WorldQueries, TheRayCallbackIgnoresClipsAndStops) {
    // Five unit circles in a row along x, at 0, 3, 6, 9 and 12.
    World world(oneSubstepDef({0.0f, 0.0f}));
    std::vector<ShapeId> circles;
    for (int i = 0; i < 5; ++i) {
        BodyDef def;
        def.position = {3.0f * i, 0.0f};
        circles.push_back(world.createShape(world.createBody(def), ShapeDef{}, Circle{{}, 1.0f}));
    }
    const Vec2 origin{-5.0f, 0.0f}, translation{20.0f, 0.0f};
    int seen = 0;
    world.castRay(origin, translation, {}, [&](const RayHit&) {
        ++seen;
        return 1.0f;
    });
    EXPECT_EQ(seen, 5);

    // Ignoring the closest circle makes the second the closest.
    std::optional<RayHit> best;
    world.castRay(origin, translation, {}, [&](const RayHit& hit) {
        if (hit.shape == circles[0]) return -1.0f;
        best = hit;
        return hit.fraction;
    });
    ASSERT_TRUE(best);
    EXPECT_EQ(best->shape, circles[1]);
    EXPECT_NEAR(best->point.x, 2.0f, 1e-5f);

    // Clipping to a fraction keeps out everything beyond it; 0 stops at the first report.
    std::set<std::uint64_t> near;
    world.castRay(origin, translation, {}, [&](const RayHit& hit) {
        near.insert(key(hit.shape));
        return 0.5f;  // x = 5: the circles at 0 and 3 start before it
    });
    for (ShapeId far : {circles[3], circles[4]}) EXPECT_EQ(near.count(key(far)), 0u);
    seen = 0;
    world.castRay(origin, translation, {}, [&](const RayHit&) {
        ++seen;
        return 0.0f;
    });
    EXPECT_EQ(seen, 1);

    const auto closest = world.castRayClosest(origin, translation);
    ASSERT_TRUE(closest);
    EXPECT_EQ(closest->shape, circles[0]);
    EXPECT_NEAR(closest->fraction, 0.2f, 1e-6f);
}

TEST(WorldQueries, FiltersByCategoryAndMask) {
    World world(oneSubstepDef({0.0f, 0.0f}));
    ShapeDef wallDef, glassDef;
    wallDef.filter.categoryBits = 0x1;
    glassDef.filter.categoryBits = 0x2;
    glassDef.filter.maskBits = 0xFFFD;  // glass does not see queries that are glass
    BodyDef at2, at5;
    at2.position = {2.0f, 0.0f};
    at5.position = {5.0f, 0.0f};
    const ShapeId glass = world.createShape(world.createBody(at2), glassDef, Polygon::box(0.1f, 2));
    const ShapeId wall = world.createShape(world.createBody(at5), wallDef, Polygon::box(0.1f, 2));
    const Vec2 o{0.0f, 0.0f}, d{10.0f, 0.0f};
    EXPECT_EQ(world.castRayClosest(o, d)->shape, glass);
    QueryFilter wallsOnly;
    wallsOnly.maskBits = 0x1;
    EXPECT_EQ(world.castRayClosest(o, d, wallsOnly)->shape, wall);
    QueryFilter asGlass;
    asGlass.categoryBits = 0x2;  // a query that is glass: glass's mask leaves it out
    EXPECT_EQ(world.castRayClosest(o, d, asGlass)->shape, wall);
    int found = 0;
    world.queryPoint({2.0f, 1.0f}, wallsOnly, [&](ShapeId) { return ++found, true; });
    EXPECT_EQ(found, 0);
    world.queryPoint({2.0f, 1.0f}, {}, [&](ShapeId) { return ++found, true; });
    EXPECT_EQ(found, 1);
}

TEST(WorldQueries, ACallbackMayReadButNotMoveShapes) {
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.createBody(def);
    const ShapeId shape = world.createShape(body, ShapeDef{}, Circle{{}, 1.0f});
    const std::uint64_t before = world.stateHash();
    int calls = 0;
    world.queryPoint({0.0f, 0.0f}, {}, [&](ShapeId found) {
        ++calls;
        EXPECT_EQ(world.shapeBody(found), body);  // reading is fine
        EXPECT_THROW(world.createShape(body, ShapeDef{}, Circle{{}, 0.5f}), Error);
        EXPECT_THROW(world.destroyShape(found), Error);
        EXPECT_THROW(world.destroyBody(body), Error);
        EXPECT_THROW(world.setBodyTransform(body, {1.0f, 0.0f}, 0.0f), Error);
        EXPECT_THROW(world.step(kDt), Error);
        EXPECT_THROW(world.castRay({-5.0f, 0.0f}, {10.0f, 0.0f}, {},
                                   [&](const RayHit&) {
                                       world.step(kDt);  // a nested query is a query too
                                       return 1.0f;
                                   }),
                     Error);
        return true;
    });
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(world.stateHash(), before);
    EXPECT_TRUE(world.isValid(shape));
    // After the query, the same calls work.
    world.setBodyTransform(body, {1.0f, 0.0f}, 0.0f);
    world.step(kDt);
}

TEST(WorldQueries, BadArgumentsAreRefused) {
    World world{oneSubstepDef()};
    world.createShape(world.createBody(BodyDef{}), ShapeDef{}, Circle{{}, 1.0f});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    auto any = [](const RayHit&) { return 1.0f; };
    auto all = [](ShapeId) { return true; };
    EXPECT_THROW(world.castRay({nan, 0.0f}, {1.0f, 0.0f}, {}, any), Error);
    EXPECT_THROW(world.castRay({0.0f, 0.0f}, {inf, 0.0f}, {}, any), Error);
    EXPECT_THROW(world.castRayClosest({2e9f, 0.0f}, {1.0f, 0.0f}), Error);
    EXPECT_THROW(world.queryAABB(AABB{{1.0f, 0.0f}, {0.0f, 1.0f}}, {}, all), Error);
    EXPECT_THROW(world.queryAABB(AABB{{0.0f, 0.0f}, {nan, 1.0f}}, {}, all), Error);
    EXPECT_THROW(world.queryPoint({0.0f, inf}, {}, all), Error);
    EXPECT_THROW(world.castRayOnShape(ShapeId{}, {0.0f, 0.0f}, {1.0f, 0.0f}), Error);
    EXPECT_THROW(world.shapeAABB(ShapeId{}), Error);
    const Transform xf{{0.0f, 0.0f}, Rot(0.0f)};
    EXPECT_THROW(world.queryShape(Circle{{0.0f, 0.0f}, -1.0f}, xf, {}, all), Error);
    EXPECT_THROW(world.queryShape(Polygon::fromPoints({{0, 0}, {1, 0}, {2, 0}}), xf, {}, all),
                 Error);
    EXPECT_THROW(
        world.queryShape(Circle{{0.0f, 0.0f}, 1.0f}, Transform{{nan, 0.0f}, Rot(0.0f)}, {}, all),
        Error);
    EXPECT_THROW(world.castShape(Circle{{0.0f, 0.0f}, 1.0f}, xf, {inf, 0.0f}, {}, any), Error);
    EXPECT_THROW(
        world.castShapeClosest(Polygon::fromPoints({{0, 0}, {1, 0}, {2, 0}}), xf, {1.0f, 0.0f}),
        Error);
    // A zero translation is a ray of no length: it hits nothing.
    EXPECT_FALSE(world.castRayClosest({-5.0f, 0.0f}, {0.0f, 0.0f}));
}

namespace {

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    const double px = double(p.x) - a.x, py = double(p.y) - a.y;
    const double t = std::clamp((px * ex + py * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    return std::hypot(px - t * ex, py - t * ey);
}

// A convex outline in world coordinates, counter-clockwise (a segment: its two ends).
std::vector<Vec2> outlineOf(const World& world, ShapeId shape) {
    const Transform xf = world.bodyTransform(world.shapeBody(shape));
    std::vector<Vec2> out;
    if (world.shapeType(shape) == ShapeType::Segment ||
        world.shapeType(shape) == ShapeType::ChainSegment) {
        const Segment s = world.shapeType(shape) == ShapeType::Segment
                              ? world.shapeSegment(shape)
                              : world.shapeChainSegment(shape).segment;
        return {transformPoint(xf, s.point1), transformPoint(xf, s.point2)};
    }
    const Polygon p = world.shapePolygon(shape);
    for (int i = 0; i < p.count; ++i) out.push_back(transformPoint(xf, p.vertices[i]));
    return out;
}

// Whether an edge normal of `a` separates it from `b` (exact for convex outlines; a two-point
// outline's two "edges" give both normals of the segment).
bool separates(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Vec2 p = a[i], q = a[(i + 1) % a.size()];
        const double nx = double(q.y) - p.y, ny = double(p.x) - q.x;
        double nearest = 1e30;
        for (Vec2 v : b) {
            nearest = std::min(nearest, nx * (double(v.x) - p.x) + ny * (double(v.y) - p.y));
        }
        if (nearest > 1e-9) return true;
    }
    return false;
}

// Distance from a point to a convex outline (0 inside).
double distanceTo(const std::vector<Vec2>& outline, Vec2 p) {
    if (outline.size() > 2 && !separates(outline, {p})) return 0.0;
    double best = 1e30;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        best =
            std::min(best, pointSegmentDistance(p, outline[i], outline[(i + 1) % outline.size()]));
    }
    return best;
}

// Distance between two convex outlines, -1 when they overlap (by an unknown depth); an outline
// may be one point.
double distanceBetween(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    if (a.size() == 1 && b.size() == 1) return length(b[0] - a[0]);
    if (a.size() == 1) return distanceTo(b, a[0]);
    if (b.size() == 1) return distanceTo(a, b[0]);
    if (!separates(a, b) && !separates(b, a)) return -1.0;
    double best = 1e30;
    for (Vec2 p : a) best = std::min(best, distanceTo(b, p));
    for (Vec2 p : b) best = std::min(best, distanceTo(a, p));
    return best;
}

}  // namespace

TEST(WorldQueries, ShapeOverlapsAgreeWithBruteForce) {
    RandomWorld r(5, BroadPhaseBoxes::Compact);
    int found = 0, nearMisses = 0;
    for (int round = 0; round < 3; ++round) {
        r.churn();
        const std::vector<ShapeId> shapes = r.allShapes();
        for (int q = 0; q < 200; ++q) {
            const Vec2 at{r.uniform(-35.0f, 35.0f), r.uniform(-3.0f, 35.0f)};
            const float angle = r.uniform(-3.0f, 3.0f);
            const int kind = q % 3;  // a circle, a box or a capsule
            const Circle circle{{0.0f, 0.0f}, r.uniform(0.2f, 3.0f)};
            const float halfWidth = r.uniform(0.2f, 3.0f);
            const Polygon box = Polygon::box(halfWidth, r.uniform(0.2f, 3.0f));
            const Capsule capsule{{-halfWidth, 0.0f}, {halfWidth, 0.5f}, r.uniform(0.1f, 1.0f)};
            const Transform xf{at, Rot(angle)};
            // The query as a core (a point, an outline or a segment) and a radius.
            std::vector<Vec2> queryCore;
            float queryRadius = 0.0f;
            if (kind == 0) {
                queryCore = {at};
                queryRadius = circle.radius;
            } else if (kind == 1) {
                for (int i = 0; i < box.count; ++i)
                    queryCore.push_back(transformPoint(xf, box.vertices[i]));
            } else {
                queryCore = {transformPoint(xf, capsule.center1),
                             transformPoint(xf, capsule.center2)};
                queryRadius = capsule.radius;
            }

            std::set<std::uint64_t> expected, margin;
            for (ShapeId shape : shapes) {
                // The brute-force answer, and whether it sits within 1e-4 m of changing: the
                // distance of the two cores less the two radii.
                const Transform bodyXf = r.world.bodyTransform(r.world.shapeBody(shape));
                std::vector<Vec2> core;
                float radius = 0.0f;
                if (r.world.shapeType(shape) == ShapeType::Circle) {
                    const Circle c = r.world.shapeCircle(shape);
                    core = {transformPoint(bodyXf, c.center)};
                    radius = c.radius;
                } else if (r.world.shapeType(shape) == ShapeType::Capsule) {
                    const Capsule c = r.world.shapeCapsule(shape);
                    core = {transformPoint(bodyXf, c.center1), transformPoint(bodyXf, c.center2)};
                    radius = c.radius;
                } else {
                    core = outlineOf(r.world, shape);
                }
                const double gap = distanceBetween(core, queryCore) - radius - queryRadius;
                if (std::abs(gap) < 1e-4) margin.insert(key(shape));
                if (gap <= 0.0) expected.insert(key(shape));
            }
            std::set<std::uint64_t> got;
            auto collect = [&](ShapeId shape) {
                got.insert(key(shape));
                return true;
            };
            if (kind == 0) {
                r.world.queryShape(circle, xf, QueryFilter{}, collect);
            } else if (kind == 1) {
                r.world.queryShape(box, xf, QueryFilter{}, collect);
            } else {
                r.world.queryShape(capsule, xf, QueryFilter{}, collect);
            }
            for (std::uint64_t k : margin) {  // round-off may tip a grazing shape either way
                expected.erase(k);
                got.erase(k);
                ++nearMisses;
            }
            EXPECT_EQ(got, expected) << "query " << q << " round " << round;
            found += static_cast<int>(got.size());
        }
    }
    EXPECT_GT(found, 300);
    EXPECT_LT(nearMisses, 5);
}

TEST(WorldQueries, ShapeCastsStopJustShortOfTheFirstShape) {
    World world(oneSubstepDef({0.0f, 0.0f}));
    BodyDef wallDef;
    wallDef.position = {0.0f, 0.0f};
    const ShapeId wall =
        world.createShape(world.createBody(wallDef), ShapeDef{}, Polygon::box(1.0f, 3.0f));
    const Transform start{{-5.0f, 0.5f}, Rot(0.0f)};
    const auto hit = world.castShapeClosest(Circle{{0.0f, 0.0f}, 0.5f}, start, {10.0f, 0.0f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shape, wall);
    // The circle's edge travels 3.5 m to the wall's face at x = -1; it stops within the cast
    // tolerance (a quarter of the slop) before it.
    EXPECT_LE(hit->fraction, 0.35f);
    EXPECT_GE(hit->fraction, 0.35f - 0.25f * kLinearSlop / 10.0f - 1e-6f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-4f);
    EXPECT_NEAR(hit->point.x, -1.0f, 1e-4f);
    // A box cast turned by 45 degrees: its corner leads, at sqrt(2) / 2 from its centre.
    const Transform turned{{-5.0f, 0.0f}, Rot(0.25f * kPi)};
    const auto corner = world.castShapeClosest(Polygon::box(0.5f, 0.5f), turned, {10.0f, 0.0f});
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->fraction, (4.0f - std::sqrt(0.5f)) / 10.0f, 0.25f * kLinearSlop / 10.0f);
    // Missing, moving away, and starting inside.
    EXPECT_FALSE(world.castShapeClosest(Circle{{0.0f, 0.0f}, 0.5f}, start, {0.0f, 10.0f}));
    EXPECT_FALSE(world.castShapeClosest(Circle{{0.0f, 0.0f}, 0.5f}, start, {-10.0f, 0.0f}));
    const auto inside = world.castShapeClosest(Circle{{0.0f, 0.0f}, 0.5f},
                                               Transform{{0.0f, 0.0f}, Rot(0.0f)}, {1.0f, 0.0f});
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->fraction, 0.0f);
    EXPECT_EQ(inside->normal, (Vec2{0.0f, 0.0f}));
}

TEST(WorldQueries, ShapeCastsAgreeWithOverlapQueriesAlongThePath) {
    // The first hit is where the moving shape starts to touch: just before it, it overlaps
    // nothing the filter sees; just past it, it overlaps the shape hit.
    RandomWorld r(9);
    int hits = 0;
    for (int round = 0; round < 2; ++round) {
        r.churn();
        for (int q = 0; q < 150; ++q) {
            const Vec2 at{r.uniform(-35.0f, 35.0f), r.uniform(-3.0f, 35.0f)};
            const Transform xf{at, Rot(r.uniform(-3.0f, 3.0f))};
            const Vec2 translation{r.uniform(-15.0f, 15.0f), r.uniform(-15.0f, 15.0f)};
            const float halfWidth = r.uniform(0.2f, 1.0f);
            const Polygon box = Polygon::box(halfWidth, r.uniform(0.2f, 1.0f));
            // Every other cast moves a capsule.
            const bool capsuleCast = q % 2 == 1;
            const Capsule capsule{{-halfWidth, 0.0f}, {halfWidth, 0.0f}, 0.3f};
            auto overlapsAt = [&](float fraction, ShapeId only) {
                bool any = false;
                const Transform there{at + fraction * translation, xf.q};
                auto note = [&](ShapeId s) {
                    if (only.isNull() || s == only) any = true;
                    return !any;
                };
                if (capsuleCast) {
                    r.world.queryShape(capsule, there, {}, note);
                } else {
                    r.world.queryShape(box, there, {}, note);
                }
                return any;
            };
            if (overlapsAt(0.0f, ShapeId{})) continue;  // starts touching: not this test's case
            const auto hit = capsuleCast ? r.world.castShapeClosest(capsule, xf, translation)
                                         : r.world.castShapeClosest(box, xf, translation);
            if (!hit) {
                for (int k = 0; k <= 20; ++k) EXPECT_FALSE(overlapsAt(k / 20.0f, ShapeId{})) << q;
                continue;
            }
            ++hits;
            for (int k = 0; k < 20; ++k) {
                EXPECT_FALSE(overlapsAt(hit->fraction * k / 20.0f, ShapeId{})) << q;
            }
            const float past = hit->fraction + 2.0f * kLinearSlop / length(translation);
            if (past <= 1.0f) {
                EXPECT_TRUE(overlapsAt(past, hit->shape)) << q;
            }
        }
    }
    EXPECT_GT(hits, 50);  // about 30% of the casts hit something
}

// Every rotation the API takes is a unit one, within kMaxRotationError: a huge one made a shape
// cast's hit point NaN, and Rot{0, 0} collapsed the shape to a point.
TEST(WorldQueries, RotationsMustBeUnitOnes) {
    auto rot = [](float s, float c) {
        Rot q;
        q.s = s;
        q.c = c;
        return q;
    };
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(5.0f, 0.5f));
    const Capsule capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
    const Circle circle{{0.0f, 0.0f}, 0.5f};
    const Polygon box = Polygon::box(0.5f, 0.5f);
    const std::uint64_t before = world.stateHash();
    // Just past the tolerance either way: 1 + 2e-4 and 1 - 2e-4 squared.
    const float over = std::sqrt(1.0f + 2.0f * kMaxRotationError);
    const float under = std::sqrt(1.0f - 2.0f * kMaxRotationError);
    for (const Rot bad : {rot(1e20f, 0.0f), rot(0.0f, 0.0f), rot(0.0f, 2.0f), rot(0.0f, over),
                          rot(under, 0.0f), rot(std::nanf(""), 1.0f)}) {
        const Transform xf{{0.0f, 3.0f}, bad};
        EXPECT_THROW(world.castShapeClosest(capsule, xf, {0.0f, -5.0f}), Error);
        EXPECT_THROW(
            world.castShape(circle, xf, {0.0f, -5.0f}, {}, [](const RayHit&) { return 1.0f; }),
            Error);
        EXPECT_THROW(world.queryShape(box, xf, {}, [](ShapeId) { return true; }), Error);
        EXPECT_THROW(rayCast(circle, xf, {-3.0f, 3.0f}, {6.0f, 0.0f}), Error);
        EXPECT_THROW(rayCast(box, xf, {-3.0f, 3.0f}, {6.0f, 0.0f}), Error);
        EXPECT_THROW(testPoint(capsule, xf, {0.0f, 3.0f}), Error);
        struct NoDraw : DebugDraw {
            void drawPolygon(const Vec2*, int, DebugColor) override {}
            void drawSolidPolygon(const Vec2*, int, float, DebugColor) override {}
            void drawSolidCircle(Vec2, float, Vec2, DebugColor) override {}
            void drawSolidCapsule(Vec2, Vec2, float, DebugColor) override {}
            void drawSegment(Vec2, Vec2, DebugColor) override {}
            void drawPoint(Vec2, float, DebugColor) override {}
        } draw;
        EXPECT_THROW(world.debugDrawBody(ground, xf, draw), Error);
    }
    EXPECT_EQ(world.stateHash(), before);
    // Rot(angle), one just inside the tolerance, and a body's own transform all pass.
    const float inside = std::sqrt(1.0f + 0.5f * kMaxRotationError);
    for (const Rot good :
         {Rot(0.3f), Rot(-2.0f), rot(0.0f, inside), world.bodyTransform(ground).q}) {
        const Transform xf{{0.0f, 3.0f}, good};
        const std::optional<RayHit> hit = world.castShapeClosest(capsule, xf, {0.0f, -5.0f});
        ASSERT_TRUE(hit.has_value());
        EXPECT_TRUE(std::isfinite(hit->point.x) && std::isfinite(hit->point.y));
        EXPECT_NEAR(hit->point.y, 0.5f, 0.01f);
    }
}
