// Sensors (ShapeDef::isSensor, issue 15 item 1): they report overlap begin and end events,
// with static, kinematic and dynamic bodies alike, and never push.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

ShapeDef sensorDef() {
    ShapeDef def;
    def.isSensor = true;
    return def;
}

BodyId bodyAt(World& world, BodyType type, Vec2 at, Vec2 velocity = {}) {
    BodyDef def;
    def.type = type;
    def.position = at;
    def.linearVelocity = velocity;
    return world.createBody(def);
}

bool has(const std::vector<SensorEvent>& events, ShapeId sensor, ShapeId visitor) {
    return std::any_of(events.begin(), events.end(), [&](const SensorEvent& e) {
        return e.sensor == sensor && e.visitor == visitor;
    });
}

}  // namespace

// A ball falls through a static sensor box: it begins overlapping, falls on as if the box were
// not there, and ends overlapping below it.
TEST(Sensor, ABodyFallsThroughAStaticSensorAndIsReportedInAndOut) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId zoneBody = world.createBody(BodyDef{});
    const ShapeId zone = world.createShape(zoneBody, sensorDef(), Polygon::box(2.0f, 1.0f));
    EXPECT_TRUE(world.isShapeSensor(zone));
    const BodyId ball = bodyAt(world, BodyType::Dynamic, {0.0f, 3.0f});
    const ShapeId ballShape = world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
    int began = -1, ended = -1;
    for (int i = 0; i < 90; ++i) {
        world.step(kDt);
        if (has(world.sensorBeginEvents(), zone, ballShape)) began = i;
        if (has(world.sensorEndEvents(), zone, ballShape)) ended = i;
        EXPECT_TRUE(world.contactBeginEvents().empty());  // no contact, only a sensor overlap
        EXPECT_TRUE(world.contacts().empty());
    }
    ASSERT_GE(began, 0);
    ASSERT_GT(ended, began);
    // Free fall all the way: the sensor pushed nothing (semi-implicit Euler, 90 steps).
    EXPECT_NEAR(world.bodyLinearVelocity(ball).y, -10.0f * 90 * kDt, 1e-3f);
}

// Any body type: a kinematic platform passing through a static sensor, and a sensor on a dynamic
// body touching static ground.
TEST(Sensor, SensesKinematicAndStaticBodiesToo) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId zoneBody = world.createBody(BodyDef{});
    const ShapeId zone = world.createShape(zoneBody, sensorDef(), Circle{{0, 0}, 1.0f});
    const BodyId platform = bodyAt(world, BodyType::Kinematic, {-5.0f, 0.0f}, {5.0f, 0.0f});
    const ShapeId platformShape = world.createShape(platform, ShapeDef{}, Polygon::box(0.5f, 0.1f));
    const BodyId ground = world.createBody(BodyDef{});
    const ShapeId groundShape =
        world.createShape(ground, ShapeDef{}, Polygon::box(20.0f, 0.5f, {0, -5.5f}, 0.0f));
    const BodyId feeler = bodyAt(world, BodyType::Dynamic, {8.0f, -4.0f});
    world.createShape(feeler, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    const ShapeId foot = world.createShape(feeler, sensorDef(), Circle{{0, -0.5f}, 0.2f});
    bool platformIn = false, platformOut = false, footOn = false;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        platformIn = platformIn || has(world.sensorBeginEvents(), zone, platformShape);
        platformOut = platformOut || has(world.sensorEndEvents(), zone, platformShape);
        footOn = footOn || has(world.sensorBeginEvents(), foot, groundShape);
    }
    EXPECT_TRUE(platformIn);
    EXPECT_TRUE(platformOut);
    EXPECT_TRUE(footOn);
    // The static sensor never met the static ground; the box (not the foot) rests on it.
    EXPECT_NEAR(world.bodyPosition(feeler).y, -4.5f, 0.03f);
}

TEST(Sensor, TwoSensorsDoNotSenseEachOtherAndFiltersApply) {
    World world{oneSubstepDef()};
    const BodyId a = bodyAt(world, BodyType::Dynamic, {0, 0});
    world.createShape(a, sensorDef(), Circle{{0, 0}, 1.0f});
    const BodyId b = bodyAt(world, BodyType::Dynamic, {0.5f, 0});
    world.createShape(b, sensorDef(), Circle{{0, 0}, 1.0f});
    ShapeDef hidden;
    hidden.filter.categoryBits = 0x0002;
    hidden.filter.maskBits = 0x0002;
    const BodyId c = bodyAt(world, BodyType::Dynamic, {0, 0.5f});
    world.createShape(c, hidden, Circle{{0, 0}, 0.3f});
    world.step(kDt);
    EXPECT_TRUE(world.sensorBeginEvents().empty());
}

// Switching the flag: a solid floor holds a ball; made a sensor, it lets it fall and reports
// the contact's end; made solid again, it catches what comes next.
TEST(Sensor, SwitchingTheFlagDropsTheContactsAndPairsAgain) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId floorBody = world.createBody(BodyDef{});
    const ShapeId floor = world.createShape(floorBody, ShapeDef{}, Polygon::box(5.0f, 0.5f));
    const BodyId ball = bodyAt(world, BodyType::Dynamic, {0.0f, 0.8f});
    const ShapeId ballShape = world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(ball).y, 0.75f, 0.02f);
    world.setShapeSensor(floor, true);
    EXPECT_EQ(world.contactEndEvents().size(), 1u);  // reported at once
    world.step(kDt);
    EXPECT_TRUE(has(world.sensorBeginEvents(), floor, ballShape));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(ball).y, 0.0f);
    world.setShapeSensor(floor, false);
    EXPECT_FALSE(world.isShapeSensor(floor));
}
