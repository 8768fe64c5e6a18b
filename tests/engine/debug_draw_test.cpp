// Debug drawing (issue 15 item 3): World::debugDraw describes every shape, joint, box, contact
// point and centre of mass the options ask for, coloured by state; debugDrawBody draws one
// body's shapes where the caller says; drawing code may read the world but not change it.
#include <gtest/gtest.h>

#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Recorder : DebugDraw {
    struct Item {
        char kind;  // o: outline, p: solid polygon, c: circle, k: capsule, s: segment, d: dot
        std::vector<Vec2> points;
        float radius = 0.0f;
        DebugColor color;
    };
    std::vector<Item> items;
    struct JointItem {
        JointId id;
        JointType type;
        Vec2 a, b;
        float separation;
        DebugColor color;
    };
    std::vector<JointItem> joints;
    World* world = nullptr;  // when set, every call tries to change it
    int refused = 0;

    void tryChange() {
        if (world == nullptr) return;
        try {
            world->setGravity({0.0f, -5.0f});
        } catch (const Error&) {
            ++refused;
        }
    }
    void drawPolygon(const Vec2* v, int n, DebugColor color) override {
        items.push_back({'o', {v, v + n}, 0.0f, color});
        tryChange();
    }
    void drawSolidPolygon(const Vec2* v, int n, float radius, DebugColor color) override {
        items.push_back({'p', {v, v + n}, radius, color});
        tryChange();
    }
    void drawSolidCircle(Vec2 center, float radius, Vec2 axis, DebugColor color) override {
        items.push_back({'c', {center, axis}, radius, color});
        tryChange();
    }
    void drawSolidCapsule(Vec2 c1, Vec2 c2, float radius, DebugColor color) override {
        items.push_back({'k', {c1, c2}, radius, color});
    }
    void drawSegment(Vec2 p1, Vec2 p2, DebugColor color) override {
        items.push_back({'s', {p1, p2}, 0.0f, color});
    }
    void drawPoint(Vec2 p, float, DebugColor color) override {
        items.push_back({'d', {p}, 0.0f, color});
    }
    void drawJoint(JointId id, JointType type, Vec2 a, Vec2 b, float separation,
                   DebugColor color) override {
        joints.push_back({id, type, a, b, separation, color});
        DebugDraw::drawJoint(id, type, a, b, separation, color);  // the default's segment, dots
    }
    int count(char kind) const {
        int n = 0;
        for (const Item& item : items) n += item.kind == kind;
        return n;
    }
    int count(char kind, DebugColor color) const {
        int n = 0;
        for (const Item& item : items) n += item.kind == kind && item.color == color;
        return n;
    }
};

struct Fixture {
    World world{oneSubstepDef()};
    BodyId ground, box, ball, capsule, kinematic, sleeper;
    ShapeId groundShape, sensor;
    JointId pin, rope;

    Fixture() {
        ground = world.createBody(BodyDef{});
        groundShape = world.createShape(ground, ShapeDef{}, Polygon::box(10.0f, 0.5f));
        world.createShape(ground, ShapeDef{}, Segment{{-10, 5}, {-10, 0}});
        world.createChain(ground, ShapeDef{}, Chain{{{14, 3}, {12, 0.5f}, {10, 0.5f}, {9, 2}}});
        ShapeDef sensorDef;
        sensorDef.isSensor = true;
        sensor = world.createShape(ground, sensorDef, Circle{{0, 4}, 1.0f});
        BodyDef dynamic;
        dynamic.type = BodyType::Dynamic;
        dynamic.position = {-3.0f, 1.0f};
        box = world.createBody(dynamic);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
        dynamic.position = {0.0f, 0.75f};
        ball = world.createBody(dynamic);
        world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
        dynamic.position = {3.0f, 0.75f};
        capsule = world.createBody(dynamic);
        world.createShape(capsule, ShapeDef{}, Capsule{{-0.4f, 0}, {0.4f, 0}, 0.25f});
        dynamic.position = {6.0f, 0.75f};
        sleeper = world.createBody(dynamic);
        world.createShape(sleeper, ShapeDef{}, Polygon::box(0.25f, 0.25f));
        BodyDef moving;
        moving.type = BodyType::Kinematic;
        moving.position = {0.0f, 8.0f};
        kinematic = world.createBody(moving);
        world.createShape(kinematic, ShapeDef{}, Polygon::box(1.0f, 0.2f));
        pin = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, box, {-3.0f, 1.5f}));
        DistanceJointDef distance;
        distance.bodyA = ball;
        distance.bodyB = capsule;
        distance.length = 3.0f;
        rope = world.createJoint(distance);
        for (int i = 0; i < 10; ++i) world.step(kDt);
        world.setBodyAwake(sleeper, false);
    }
};

}  // namespace

TEST(DebugDraw, DrawsEveryShapeAndJointColouredByState) {
    Fixture f;
    Recorder r;
    f.world.debugDraw(r);
    // Shapes: the ground box, the kinematic plank, the box and the sleeper are polygons; the
    // ball and the sensor circles; one capsule; a segment and one chain segment.
    EXPECT_EQ(r.count('p'), 4);
    EXPECT_EQ(r.count('c'), 2);
    EXPECT_EQ(r.count('k'), 1);
    EXPECT_EQ(r.count('p', debug_colors::kStatic), 1);
    EXPECT_EQ(r.count('p', debug_colors::kKinematic), 1);
    EXPECT_EQ(r.count('p', debug_colors::kSleeping), 1);
    EXPECT_EQ(r.count('c', debug_colors::kSensor), 1);
    EXPECT_EQ(r.count('k', debug_colors::kDynamic), 1);
    // Two shape segments plus one segment per joint (the default drawJoint).
    EXPECT_EQ(r.count('s', debug_colors::kStatic), 2);
    ASSERT_EQ(r.joints.size(), 2u);
    EXPECT_EQ(r.joints[0].id, f.pin);
    EXPECT_EQ(r.joints[0].a, f.world.jointAnchorA(f.pin));
    EXPECT_EQ(r.joints[0].b, f.world.jointAnchorB(f.pin));
    EXPECT_EQ(r.joints[0].separation, f.world.jointSeparation(f.pin));
    EXPECT_EQ(r.joints[1].type, JointType::Distance);
    EXPECT_EQ(r.count('d'), 4);  // two dots per joint
    EXPECT_EQ(r.count('o'), 0);  // no boxes unless asked
    // A polygon's vertices are its shape's, placed by its body.
    for (const Recorder::Item& item : r.items) {
        if (item.kind != 'p' || item.color != debug_colors::kDynamic) continue;
        const Polygon local = f.world.shapePolygon(f.world.bodyShapes(f.box)[0]);
        const Transform xf = f.world.bodyTransform(f.box);
        ASSERT_EQ(item.points.size(), 4u);
        for (int i = 0; i < 4; ++i)
            EXPECT_EQ(item.points[i], transformPoint(xf, local.vertices[i]));
    }
}

TEST(DebugDraw, OptionsAddBoxesContactsAndCentresOfMass) {
    Fixture f;
    Recorder r;
    DebugDrawOptions options;
    options.shapes = false;
    options.joints = false;
    options.aabbs = true;
    options.contactPoints = true;
    options.contactNormals = true;
    options.centersOfMass = true;
    f.world.debugDraw(r, options);
    EXPECT_EQ(r.count('o'), f.world.shapeCount());
    const AABB box = f.world.shapeAABB(f.groundShape);
    bool found = false;
    for (const Recorder::Item& item : r.items) {
        found = found ||
                (item.kind == 'o' && item.points[0] == box.lower && item.points[2] == box.upper);
    }
    EXPECT_TRUE(found);
    int points = 0;
    for (const ContactData& c : f.world.contacts()) points += c.pointCount;
    EXPECT_GT(points, 0);
    EXPECT_EQ(r.count('d', debug_colors::kContactPoint), points);
    EXPECT_EQ(r.count('s', debug_colors::kContactNormal), points);
    // Two axes (segments) per non-static body: box, ball, capsule, sleeper, kinematic plank.
    EXPECT_EQ(r.count('s') - points, 2 * 5);
    EXPECT_EQ(r.count('p') + r.count('c') + r.count('k'), 0);
}

TEST(DebugDraw, ShowsJointsComingApartAndLetGo) {
    Fixture f;
    // Pull the pin's anchors apart: drawn as come apart, with its separation.
    f.world.setBodyTransform(f.box, {-3.0f, 0.9f}, 0.0f);
    Recorder r;
    f.world.debugDraw(r);
    EXPECT_EQ(r.joints[0].color, debug_colors::kSeparatedJoint);
    EXPECT_NEAR(r.joints[0].separation, 0.1f, 1e-5f);
    f.world.setJointLetGoSeparation(f.pin, 0.05f);
    f.world.step(kDt);
    ASSERT_TRUE(f.world.isJointLetGo(f.pin));
    Recorder after;
    f.world.debugDraw(after);
    EXPECT_EQ(after.joints[0].color, debug_colors::kLetGoJoint);
}

TEST(DebugDraw, DrawsOneBodyWhereTheCallerSays) {
    Fixture f;
    Recorder r;
    f.world.debugDrawBody(f.capsule, Transform{}, r);
    ASSERT_EQ(r.items.size(), 1u);
    const Capsule c = f.world.shapeCapsule(f.world.bodyShapes(f.capsule)[0]);
    EXPECT_EQ(r.items[0].points[0], c.center1);  // the body's own frame
    EXPECT_EQ(r.items[0].points[1], c.center2);
    EXPECT_EQ(r.items[0].radius, c.radius);
    Recorder moved;
    f.world.debugDrawBody(f.capsule, Transform{{1.0f, 2.0f}, Rot{0.0f}}, moved);
    EXPECT_EQ(moved.items[0].points[0], (c.center1 + Vec2{1.0f, 2.0f}));
    EXPECT_THROW(f.world.debugDrawBody(BodyId{}, Transform{}, r), Error);
    EXPECT_THROW(f.world.debugDrawBody(f.capsule, Transform{{NAN, 0.0f}, Rot{}}, r), Error);
}

TEST(DebugDraw, DrawingCodeMayNotChangeTheWorld) {
    Fixture f;
    const std::uint64_t before = f.world.stateHash();
    Recorder r;
    r.world = &f.world;
    f.world.debugDraw(r);
    EXPECT_GT(r.refused, 0);
    EXPECT_EQ(f.world.stateHash(), before);
    f.world.setGravity({0.0f, -5.0f});  // allowed again once drawing is done
}
