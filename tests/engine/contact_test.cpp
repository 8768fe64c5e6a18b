// Contacts: resting, stacking, friction, restitution, filtering, events; for both contact
// position corrections where the behaviour is promised for both.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pivot/pivot.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

WorldDef worldWith(ContactCorrection correction) {
    WorldDef def = oneSubstepDef();
    def.contactCorrection = correction;
    return def;
}

BodyId addGround(World& world, float friction = 0.6f, float restitution = 0.0f) {
    BodyId ground = world.createBody(BodyDef{});
    ShapeDef def;
    def.density = 0.0f;
    def.friction = friction;
    def.restitution = restitution;
    world.createShape(ground, def, Polygon::box(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return ground;
}

BodyId addBox(World& world, Vec2 position, float half = 0.5f, float angle = 0.0f,
              float friction = 0.6f) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.angle = angle;
    BodyId body = world.createBody(def);
    ShapeDef shape;
    shape.friction = friction;
    world.createShape(body, shape, Polygon::box(half, half));
    return body;
}

float deepestPenetration(const World& world) {
    float deepest = 0.0f;
    for (const ContactData& c : world.contacts()) {
        for (int i = 0; i < c.pointCount; ++i) deepest = std::min(deepest, c.points[i].separation);
    }
    return -deepest;
}

std::string correctionName(const testing::TestParamInfo<ContactCorrection>& info) {
    return info.param == ContactCorrection::NGS ? "NGS" : "Baumgarte";
}

}  // namespace

class EveryContactCorrection : public testing::TestWithParam<ContactCorrection> {};

TEST_P(EveryContactCorrection, ADroppedBoxComesToRestWithin2sThenSleeps) {
    World world(worldWith(GetParam()));
    addGround(world);
    BodyId box = addBox(world, {0.0f, 3.0f});
    for (int i = 0; i < 120; ++i) world.step(kDt);  // 2 s: it lands after ~0.7 s
    EXPECT_LT(length(world.bodyLinearVelocity(box)), kLinearSleepTolerance);
    EXPECT_LT(std::fabs(world.bodyAngularVelocity(box)), kAngularSleepTolerance);
    EXPECT_LT(deepestPenetration(world), 2.0f * kLinearSlop);
    EXPECT_NEAR(world.bodyPosition(box).y, 0.5f, 2.0f * kPolygonRadius + 2.0f * kLinearSlop);
    // At rest, it sleeps once kTimeToSleep has passed.
    bool slept = false;
    for (int i = 0; i < 60 && !slept; ++i) {
        world.step(kDt);
        slept = !world.isBodyAwake(box);
    }
    EXPECT_TRUE(slept);
    EXPECT_EQ(world.lastStepStats().sleepingBodyCount, 1);
}

TEST_P(EveryContactCorrection, TwentyRowPyramidStandsFor10s) {
    World world(worldWith(GetParam()));
    addGround(world);
    const float restGap = 2.0f * kPolygonRadius - kLinearSlop;
    BodyId top;
    for (int row = 0; row < 20; ++row) {
        int count = 20 - row;
        for (int i = 0; i < count; ++i) {
            float x = -0.525f * float(count - 1) + 1.05f * float(i);
            top = addBox(world, {x, 0.5f + restGap + (1.0f + restGap) * float(row)});
        }
    }
    Vec2 start = world.bodyPosition(top);
    for (int i = 0; i < 600; ++i) world.step(kDt);
    EXPECT_LT(distance(world.bodyPosition(top), start), 0.1f);
}

TEST_P(EveryContactCorrection, FrictionHoldsABoxOnASlopeOrLetsItSlide) {
    // A 20 degree slope: tan(20 deg) = 0.36, so friction 0.6 holds and 0.1 slides with
    // acceleration g (sin 20 - 0.1 cos 20).
    const float angle = 20.0f / 180.0f * kPi;
    const Vec2 down{-std::cos(angle), -std::sin(angle)};
    for (float friction : {0.6f, 0.1f}) {
        World world(worldWith(GetParam()));
        BodyId slope = world.createBody(BodyDef{});
        ShapeDef ground;
        ground.density = 0.0f;
        ground.friction = friction;
        world.createShape(slope, ground, Polygon::box(20.0f, 0.5f, {0, 0}, angle));
        // Resting on the surface: 0.5 (slab) + 0.5 (box) + the skin gap along the normal.
        Vec2 normal{-std::sin(angle), std::cos(angle)};
        BodyId box = addBox(world, (1.0f + 2.0f * kPolygonRadius - kLinearSlop) * normal, 0.5f,
                            angle, friction);
        Vec2 start = world.bodyPosition(box);
        for (int i = 0; i < 120; ++i) world.step(kDt);
        float travelled = dot(world.bodyPosition(box) - start, down);
        if (friction > 0.5f) {
            EXPECT_LT(std::fabs(travelled), 0.01f) << "friction " << friction;
        } else {
            float expected = 0.5f * 10.0f * (std::sin(angle) - friction * std::cos(angle)) * 4.0f;
            EXPECT_NEAR(travelled, expected, 0.05f * expected) << "friction " << friction;
        }
    }
}

TEST_P(EveryContactCorrection, ABallWithRestitutionOneBouncesBackTo2m) {
    World world(worldWith(GetParam()));
    addGround(world);
    BodyDef def;
    def.type = BodyType::Dynamic;
    const float radius = 0.25f;
    def.position = {0.0f, 2.0f + radius};  // lowest point 2 m above the ground
    BodyId ball = world.createBody(def);
    ShapeDef shape;
    shape.restitution = 1.0f;
    world.createShape(ball, shape, Circle{{0, 0}, radius});
    bool bounced = false;
    float peak = 0.0f;
    for (int i = 0; i < 240; ++i) {
        world.step(kDt);
        float vy = world.bodyLinearVelocity(ball).y;
        if (vy > 0.0f) bounced = true;
        if (bounced) {
            peak = std::max(peak, world.bodyPosition(ball).y - radius);
            if (vy < 0.0f) break;  // past the top of the first bounce
        }
    }
    ASSERT_TRUE(bounced);
    EXPECT_NEAR(peak, 2.0f, 0.05f * 2.0f);
}

TEST_P(EveryContactCorrection, SlowImpactsDoNotBounce) {
    // Dropped from 2 cm the ball arrives at about 0.6 m/s, below the 1 m/s threshold.
    World world(worldWith(GetParam()));
    addGround(world);
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 0.25f + 0.02f};
    BodyId ball = world.createBody(def);
    ShapeDef shape;
    shape.restitution = 1.0f;
    world.createShape(ball, shape, Circle{{0, 0}, 0.25f});
    float highest = 0.0f;
    bool landed = false;
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        landed = landed || !world.contacts().empty();
        if (landed) highest = std::max(highest, world.bodyLinearVelocity(ball).y);
    }
    ASSERT_TRUE(landed);
    EXPECT_LT(highest, 0.1f);
}

TEST_P(EveryContactCorrection, FrictionMixesAsTheGeometricMean) {
    // Ground 0.6, box 0.1: the contact has sqrt(0.06) = 0.245 < tan 20 deg, so the box slides
    // with acceleration g (sin 20 - 0.245 cos 20).
    const float angle = 20.0f / 180.0f * kPi;
    World world(worldWith(GetParam()));
    BodyId slope = world.createBody(BodyDef{});
    ShapeDef ground;
    ground.density = 0.0f;
    ground.friction = 0.6f;
    world.createShape(slope, ground, Polygon::box(20.0f, 0.5f, {0, 0}, angle));
    Vec2 normal{-std::sin(angle), std::cos(angle)};
    BodyId box =
        addBox(world, (1.0f + 2.0f * kPolygonRadius - kLinearSlop) * normal, 0.5f, angle, 0.1f);
    Vec2 start = world.bodyPosition(box);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    float travelled = distance(world.bodyPosition(box), start);
    float mixed = std::sqrt(0.6f * 0.1f);
    float expected = 0.5f * 10.0f * (std::sin(angle) - mixed * std::cos(angle)) * 4.0f;
    EXPECT_NEAR(travelled, expected, 0.05f * expected);
}

INSTANTIATE_TEST_SUITE_P(Contacts, EveryContactCorrection,
                         testing::Values(ContactCorrection::NGS, ContactCorrection::Baumgarte),
                         correctionName);

TEST(ContactFiltering, CategoryMaskAndGroup) {
    auto touching = [](Filter a, Filter b) {
        World world(oneSubstepDef({0, 0}));
        BodyDef def;
        def.type = BodyType::Dynamic;
        BodyId first = world.createBody(def);
        def.position = {0.5f, 0.0f};
        BodyId second = world.createBody(def);
        ShapeDef sa, sb;
        sa.filter = a;
        sb.filter = b;
        world.createShape(first, sa, Polygon::box(0.5f, 0.5f));
        world.createShape(second, sb, Polygon::box(0.5f, 0.5f));
        world.step(kDt);
        return !world.contacts().empty();
    };
    Filter plain;
    EXPECT_TRUE(touching(plain, plain));
    Filter player{0x0002, 0xFFFD, 0};  // does not collide with its own category
    EXPECT_FALSE(touching(player, player));
    EXPECT_TRUE(touching(player, plain));
    Filter friendly{0x0001, 0xFFFF, -3};
    EXPECT_FALSE(touching(friendly, friendly));  // same negative group: never
    Filter clump{0x0002, 0x0000, 4};
    EXPECT_TRUE(touching(clump, clump));  // same positive group: always, masks aside
}

TEST(ContactFiltering, ChangingAFilterTakesEffectAtTheNextStep) {
    World world(oneSubstepDef({0, 0}));
    BodyDef def;
    def.type = BodyType::Dynamic;
    BodyId a = world.createBody(def);
    def.position = {0.5f, 0.0f};
    BodyId b = world.createBody(def);
    ShapeId sa = world.createShape(a, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    world.createShape(b, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    world.step(kDt);
    ASSERT_EQ(world.contacts().size(), 1u);
    world.setShapeFilter(sa, Filter{0x0001, 0x0000, 0});
    world.step(kDt);
    EXPECT_TRUE(world.contacts().empty());
    world.setShapeFilter(sa, Filter{});
    world.step(kDt);
    EXPECT_EQ(world.contacts().size(), 1u);
}

TEST(ContactFiltering, JointedBodiesCollideOnlyWhenTheJointSaysSo) {
    for (bool collideConnected : {false, true}) {
        World world(oneSubstepDef({0, 0}));
        BodyDef def;
        def.type = BodyType::Dynamic;
        BodyId a = world.createBody(def);
        def.position = {0.8f, 0.0f};
        BodyId b = world.createBody(def);
        world.createShape(a, ShapeDef{}, Polygon::box(0.5f, 0.25f));
        world.createShape(b, ShapeDef{}, Polygon::box(0.5f, 0.25f));
        world.step(kDt);
        ASSERT_EQ(world.contacts().size(), 1u);  // overlapping, not yet jointed
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(a, b, {0.4f, 0.0f});
        jd.collideConnected = collideConnected;
        JointId joint = world.createJoint(jd);
        world.step(kDt);
        EXPECT_EQ(world.contacts().size(), collideConnected ? 1u : 0u);
        world.destroyJoint(joint);
        world.step(kDt);
        EXPECT_EQ(world.contacts().size(), 1u) << "without the joint they collide again";
    }
}

TEST(ContactEvents, BeginWhenLandingEndWhenLifted) {
    World world{oneSubstepDef()};
    addGround(world);
    BodyId box = addBox(world, {0.0f, 1.0f});
    int begins = 0;
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        begins += static_cast<int>(world.contactBeginEvents().size());
        EXPECT_TRUE(world.contactEndEvents().empty());
    }
    EXPECT_EQ(begins, 1);
    world.setBodyTransform(box, {0.0f, 5.0f}, 0.0f);
    world.step(kDt);
    EXPECT_EQ(world.contactEndEvents().size(), 1u);
    EXPECT_TRUE(world.contacts().empty());
}

TEST(Contacts, CircleAgainstPolygonAndCircle) {
    World world{oneSubstepDef()};
    addGround(world);
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 1.0f};
    BodyId lower = world.createBody(def);
    world.createShape(lower, ShapeDef{}, Circle{{0, 0}, 0.5f});
    def.position = {0.1f, 2.5f};
    BodyId upper = world.createBody(def);
    world.createShape(upper, ShapeDef{}, Circle{{0, 0}, 0.5f});
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_EQ(world.contacts().size(), 2u);
    // The lower ball rests on the ground (polygon-circle), the upper one on it and rolls off.
    EXPECT_NEAR(world.bodyPosition(lower).y, 0.5f, 0.02f);
    EXPECT_GT(world.bodyPosition(upper).y, 1.3f);
}

TEST(Contacts, DestroyingABodyWakesWhatRestedOnIt) {
    World world{oneSubstepDef()};
    addGround(world);
    BodyId lower = addBox(world, {0.0f, 0.515f});
    BodyId upper = addBox(world, {0.0f, 1.53f});
    for (int i = 0; i < 120; ++i) world.step(kDt);
    ASSERT_FALSE(world.isBodyAwake(upper));
    float restingHeight = world.bodyPosition(upper).y;
    world.destroyBody(lower);
    EXPECT_TRUE(world.isBodyAwake(upper));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(upper).y, restingHeight - 0.5f);
}

TEST(Contacts, JointsAndNgsContactsShareThePositionSweepsAndTheEarlyExit) {
    // A box pinned to a static anchor and placed 0.3 m deep in the ground, more than the
    // position phase can push out in one step: an NGS contact keeps every sweep busy, while a
    // Baumgarte contact (no position phase) leaves the early exit to the joint alone.
    for (ContactCorrection correction : {ContactCorrection::NGS, ContactCorrection::Baumgarte}) {
        World world(worldWith(correction));
        addGround(world);
        BodyId anchor = world.createBody(BodyDef{});  // not the ground: the joint would forbid
                                                      // the very contact under test
        BodyId box = addBox(world, {0.0f, 0.2f});
        world.createJoint(RevoluteJointDef::atWorldAnchor(anchor, box, {0.0f, 0.2f}));
        for (int i = 0; i < 3; ++i) world.step(kDt, 8, 3);
        if (correction == ContactCorrection::NGS) {
            EXPECT_EQ(world.lastStepStats().positionIterations, 3);
        } else {
            // Only the joint is checked: it converges once the contact's push is absorbed.
            EXPECT_LT(world.lastStepStats().positionIterations, 3);
        }
    }
}

TEST(ContactFiltering, AShapeThatCouldMeetNothingIsFoundOnceSomethingItMeetsAppears) {
    // A box that collides only with category 1 falls while no category-1 shape exists (the broad
    // phase does not even query it then); a category-1 ground added later must still stop it.
    World world{oneSubstepDef()};
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = {0.0f, 3.0f};
    BodyId box = world.createBody(def);
    ShapeDef boxShape;
    boxShape.filter = {0x0002, 0x0001, 0};
    world.createShape(box, boxShape, Polygon::box(0.5f, 0.5f));
    for (int i = 0; i < 10; ++i) world.step(kDt);
    ShapeDef groundShape;
    groundShape.density = 0.0f;
    groundShape.filter = {0x0001, 0xFFFF, 0};
    BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, groundShape, Polygon::box(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(box).y, 0.5f, 0.05f);
}

// Under Compact broad-phase boxes a static body's shapes sit in a tree of their own, so a body
// whose type changes must change trees and still meet what it touches, under both policies.
TEST(ContactBodyTypes, ABodyTurnedStaticOrDynamicKeepsMeetingWhatItTouches) {
    for (const BroadPhaseBoxes boxes : {BroadPhaseBoxes::Predictive, BroadPhaseBoxes::Compact}) {
        WorldDef worldDef = oneSubstepDef();
        worldDef.broadPhaseBoxes = boxes;
        World world(worldDef);
        addGround(world);
        BodyDef def;
        def.position = {0.0f, 5.0f};
        const BodyId shelf = world.createBody(def);  // static, in the air
        world.createShape(shelf, ShapeDef{}, Polygon::box(1.0f, 0.5f));
        def.type = BodyType::Dynamic;
        def.position = {0.0f, 7.0f};
        const BodyId box = world.createBody(def);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));

        for (int i = 0; i < 120; ++i) world.step(kDt);
        EXPECT_NEAR(world.bodyPosition(box).y, 6.0f, 0.02f) << "rests on the static shelf";

        world.setBodyType(shelf, BodyType::Dynamic);  // falls to the ground, carrying the box
        for (int i = 0; i < 180; ++i) world.step(kDt);
        EXPECT_NEAR(world.bodyPosition(shelf).y, 0.5f, 0.02f) << "meets the static ground";
        EXPECT_NEAR(world.bodyPosition(box).y, 1.5f, 0.03f);

        world.setBodyType(shelf, BodyType::Static);
        world.setBodyTransform(box, {0.0f, 3.0f}, 0.0f);  // dropped again onto the shelf
        for (int i = 0; i < 120; ++i) world.step(kDt);
        // On the shelf: a fall stopped by continuous collision may rest up to the two shapes'
        // skins (kPolygonRadius each) apart, as in Box2D.
        const float gap = world.bodyPosition(box).y - world.bodyPosition(shelf).y - 1.0f;
        EXPECT_GT(gap, -kLinearSlop);
        EXPECT_LT(gap, 2.0f * kPolygonRadius);
        // The box's; the ground's went, as two static bodies never touch.
        EXPECT_EQ(world.bodyContacts(shelf).size(), 1u);
    }
}
