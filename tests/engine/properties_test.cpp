// Reading and changing bodies' and shapes' properties between steps (issue 15, item 4): each
// setter validates like the def, takes effect at the next step and wakes what it must; the
// per-body lists of joints and contacts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;
const float kNan = std::numeric_limits<float>::quiet_NaN();

BodyId box(World& world, Vec2 at, float angle = 0.0f) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    def.angle = angle;
    const BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    return body;
}

void steps(World& world, int n) {
    for (int i = 0; i < n; ++i) world.step(kDt);
}

// A refused call leaves the world as it was.
template <typename Call>
void expectRefused(World& world, Call&& call) {
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(call(), Error);
    EXPECT_EQ(world.stateHash(), before);
}

}  // namespace

TEST(Properties, DampingAndGravityScaleAreReadAndChanged) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId a = box(world, {0, 10});
    const BodyId b = box(world, {5, 10});
    EXPECT_EQ(world.bodyLinearDamping(a), 0.0f);
    EXPECT_EQ(world.bodyGravityScale(a), 1.0f);
    world.setBodyLinearDamping(b, 2.0f);
    world.setBodyAngularDamping(b, 3.0f);
    EXPECT_EQ(world.bodyLinearDamping(b), 2.0f);
    EXPECT_EQ(world.bodyAngularDamping(b), 3.0f);
    steps(world, 30);
    // The damped body falls slower.
    EXPECT_GT(world.bodyLinearVelocity(b).y, world.bodyLinearVelocity(a).y);

    // Gravity scale 0: it floats on at the speed it has; a sleeping body is woken to feel it.
    world.setBodyGravityScale(a, 0.0f);
    const Vec2 v = world.bodyLinearVelocity(a);
    steps(world, 10);
    EXPECT_EQ(world.bodyLinearVelocity(a), v);
    world.setBodyAwake(b, false);
    world.setBodyGravityScale(b, -1.0f);
    EXPECT_TRUE(world.isBodyAwake(b));

    expectRefused(world, [&] { world.setBodyLinearDamping(a, -1.0f); });
    expectRefused(world, [&] { world.setBodyAngularDamping(a, kNan); });
    expectRefused(world, [&] { world.setBodyGravityScale(a, 2.0f * kMaxGravityScale); });
    expectRefused(world, [&] { world.setBodyGravityScale(a, kNan); });
}

TEST(Properties, FixingTheRotationStopsTheSpinAndKeepsTheCentre) {
    World world{oneSubstepDef()};
    const BodyId body = box(world, {0, 0});
    const float inertia = world.bodyRotationalInertia(body);
    ASSERT_GT(inertia, 0.0f);
    world.setBodyAngularVelocity(body, 3.0f);
    world.applyTorque(body, 10.0f);
    const Vec2 center = world.bodyWorldCenter(body);
    world.setBodyFixedRotation(body, true);
    EXPECT_TRUE(world.bodyFixedRotation(body));
    EXPECT_EQ(world.bodyAngularVelocity(body), 0.0f);
    EXPECT_EQ(world.bodyRotationalInertia(body), 0.0f);
    EXPECT_EQ(world.bodyWorldCenter(body), center);
    EXPECT_THROW(world.applyTorque(body, 1.0f), Error);
    steps(world, 10);
    EXPECT_EQ(world.bodyAngle(body), 0.0f);  // the torque applied before was dropped
    world.setBodyFixedRotation(body, false);
    EXPECT_EQ(world.bodyRotationalInertia(body), inertia);
    world.applyTorque(body, 1.0f);
    steps(world, 1);
    EXPECT_GT(world.bodyAngularVelocity(body), 0.0f);
}

TEST(Properties, SleepAllowedIsRead) {
    World world{oneSubstepDef()};
    const BodyId body = box(world, {0, 0});
    EXPECT_TRUE(world.isBodySleepAllowed(body));
    world.setBodySleepAllowed(body, false);
    EXPECT_FALSE(world.isBodySleepAllowed(body));
}

TEST(Properties, ABodyListsItsJointsAndTouchingContacts) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(10.0f, 0.5f, {0, -0.5f}, 0.0f));
    const BodyId resting = box(world, {0, 0.5f});
    const BodyId hanging = box(world, {5, 5});
    const JointId j1 = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, hanging, {5, 6}));
    const JointId j2 = world.createJoint(RevoluteJointDef::atWorldAnchor(resting, hanging, {3, 3}));
    std::vector<JointId> joints = world.bodyJoints(hanging);
    ASSERT_EQ(joints.size(), 2u);
    EXPECT_TRUE((joints[0] == j1 && joints[1] == j2) || (joints[0] == j2 && joints[1] == j1));
    world.destroyJoint(j2);
    joints = world.bodyJoints(hanging);
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_EQ(joints[0], j1);
    EXPECT_TRUE(world.bodyJoints(resting).empty());

    steps(world, 30);
    const std::vector<ContactData> contacts = world.bodyContacts(resting);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_EQ(contacts[0].pointCount, 2);
    EXPECT_EQ(world.bodyContacts(ground).size(), 1u);  // the hanging box touches nothing
    EXPECT_TRUE(world.bodyContacts(hanging).empty());
}

// A box resting on a 30 degree slope with friction 1 (tan 30 = 0.58) slides once its friction
// drops below that, from the next step: the contact takes the new mix at once. Mixed with the
// slope's 1, a box friction of 0.1 gives sqrt(0.1) = 0.32: 10 (sin 30 - 0.32 cos 30) = 2.3
// m/s^2, 0.28 m in half a second (with the old mix it would not move).
TEST(Properties, FrictionChangesReachTheContactsAtOnce) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, -10.0f});
    const float slope = 30.0f * kPi / 180.0f;
    ShapeDef rough;
    rough.friction = 1.0f;
    BodyDef def;
    def.angle = -slope;  // the ground body turned: the slope goes down to the right
    const BodyId tilted = world.createBody(def);
    world.createShape(tilted, rough, Polygon::box(20.0f, 0.5f, {0, -0.5f}, 0.0f));
    const BodyId body = box(world, {std::sin(slope) * 0.51f, std::cos(slope) * 0.51f}, -slope);
    const ShapeId shape = world.bodyShapes(body)[0];
    world.setShapeFriction(shape, 1.0f);
    EXPECT_EQ(world.shapeFriction(shape), 1.0f);
    steps(world, 60);
    const Vec2 rest = world.bodyPosition(body);
    EXPECT_LT(length(world.bodyLinearVelocity(body)), 0.05f);
    world.setBodyAwake(body, false);
    world.setShapeFriction(shape, 0.1f);
    EXPECT_TRUE(world.isBodyAwake(body));
    steps(world, 30);
    EXPECT_NEAR(length(world.bodyPosition(body) - rest), 0.28f, 0.05f);

    world.setShapeRestitution(shape, 0.5f);
    EXPECT_EQ(world.shapeRestitution(shape), 0.5f);
    expectRefused(world, [&] { world.setShapeFriction(shape, -0.1f); });
    expectRefused(world, [&] { world.setShapeFriction(shape, 2.0f * kMaxFriction); });
    expectRefused(world, [&] { world.setShapeFriction(shape, kNan); });
    expectRefused(world, [&] { world.setShapeRestitution(shape, 1.5f); });
    expectRefused(world, [&] { world.setShapeRestitution(shape, kNan); });
}

// Joints: every def field can be read back; collideConnected can be changed, and the change
// makes or ends the contacts between the two bodies at the next step.
TEST(Properties, JointDefFieldsReadBackAndCollideConnectedChanges) {
    World world{oneSubstepDef()};
    world.setGravity({0.0f, 0.0f});
    const BodyId a = box(world, {0.0f, 0.0f}, 0.3f);
    const BodyId b = box(world, {0.5f, 0.0f}, 0.0f);  // overlapping a
    RevoluteJointDef pin = RevoluteJointDef::atWorldAnchor(a, b, {0.25f, 0.0f});
    const JointId joint = world.createJoint(pin);
    EXPECT_EQ(world.jointLocalAnchorA(joint),
              inverseTransformPoint(world.bodyTransform(a), {0.25f, 0.0f}));
    EXPECT_EQ(world.jointLocalAnchorB(joint), (Vec2{-0.25f, 0.0f}));
    EXPECT_FLOAT_EQ(world.jointReferenceAngle(joint), -0.3f);
    EXPECT_FALSE(world.jointCollideConnected(joint));
    steps(world, 2);
    EXPECT_TRUE(world.contacts().empty());
    world.setJointCollideConnected(joint, true);
    EXPECT_TRUE(world.jointCollideConnected(joint));
    steps(world, 1);
    EXPECT_EQ(world.contacts().size(), 1u);
    world.setJointCollideConnected(joint, false);
    steps(world, 1);
    EXPECT_TRUE(world.contacts().empty());
    EXPECT_EQ(world.contactEndEvents().size(), 1u);

    WheelJointDef wheel;
    wheel.bodyA = a;
    wheel.bodyB = box(world, {3.0f, 0.0f}, 0.0f);
    wheel.worldAxis = Vec2{0.0f, 1.0f};
    wheel.worldAnchor = Vec2{3.0f, 0.0f};
    const JointId wheelJoint = world.createJoint(wheel);
    const Vec2 axis = world.wheelJointAxis(wheelJoint);
    EXPECT_NEAR(axis.x, 0.0f, 1e-6f);
    EXPECT_NEAR(axis.y, 1.0f, 1e-6f);
    EXPECT_THROW(world.wheelJointAxis(joint), Error);

    PulleyJointDef pulley;
    pulley.bodyA = box(world, {-2.0f, 5.0f}, 0.0f);
    pulley.bodyB = box(world, {2.0f, 4.0f}, 0.0f);
    pulley.groundAnchorA = {-2.0f, 10.0f};
    pulley.groundAnchorB = {2.0f, 10.0f};
    const JointId pulleyJoint = world.createJoint(pulley);
    EXPECT_FLOAT_EQ(world.pulleyJointRestLengthA(pulleyJoint), 5.0f);
    EXPECT_FLOAT_EQ(world.pulleyJointRestLengthB(pulleyJoint), 6.0f);
    EXPECT_THROW(world.pulleyJointRestLengthA(joint), Error);

    MouseJointDef drag;
    drag.body = b;
    drag.target = {0.5f, 0.0f};
    const MouseJointId mouse = world.createMouseJoint(drag);
    EXPECT_EQ(world.mouseJointBody(mouse), b);
    EXPECT_EQ(world.mouseJointMaxForce(mouse), drag.maxForce);
    world.setMouseJointMaxForce(mouse, 50.0f);
    EXPECT_EQ(world.mouseJointMaxForce(mouse), 50.0f);
    world.setMouseJointSpring(mouse, 2.0f, 1.0f);
    EXPECT_EQ(world.mouseJointHertz(mouse), 2.0f);
    EXPECT_EQ(world.mouseJointDampingRatio(mouse), 1.0f);
    expectRefused(world, [&] { world.setMouseJointMaxForce(mouse, 0.0f); });
    expectRefused(world, [&] { world.setMouseJointSpring(mouse, -1.0f, 0.5f); });
    expectRefused(world, [&] { world.setMouseJointSpring(mouse, 1.0f, kNan); });
}
