// Events and callbacks (issue 15 item 2): contact hit events, the pre-solve callback (one-way
// platforms), the custom filter, breakable joints and body move events; what a callback may do,
// and that every list comes out in the same order on any worker count.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pivot/pivot.h"
#include "scenes/scene.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodyId bodyAt(World& world, BodyType type, Vec2 at, Vec2 velocity = {}) {
    BodyDef def;
    def.type = type;
    def.position = at;
    def.linearVelocity = velocity;
    return world.createBody(def);
}

ShapeId groundBox(World& world, const ShapeDef& def, float y = 0.0f, float halfHeight = 0.5f) {
    const BodyId ground = bodyAt(world, BodyType::Static, {0.0f, y});
    return world.createShape(ground, def, Polygon::box(20.0f, halfHeight));
}

ShapeDef hitDef() {
    ShapeDef def;
    def.enableHitEvents = true;
    return def;
}

}  // namespace

// A ball dropped 1.25 m lands at 5 m/s: one hit, at the landing point, with the ground's normal
// and the speed it fell with; resting afterwards is no hit. Continuous collision catches this
// landing as an impact; without it the discrete step does.
TEST(HitEvents, ADroppedBallReportsOneHitWithItsSpeedPointAndNormal) {
    for (bool continuous : {true, false}) {
        SCOPED_TRACE(continuous ? "continuous" : "discrete");
        World world{oneSubstepDef()};
        world.setContinuousEnabled(continuous);
        const ShapeId ground = groundBox(world, hitDef());
        const BodyId ball = bodyAt(world, BodyType::Dynamic, {1.0f, 0.5f + 0.25f + 1.25f});
        const ShapeId ballShape = world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
        std::vector<ContactHitEvent> hits;
        for (int i = 0; i < 180; ++i) {
            world.step(kDt);
            for (const ContactHitEvent& e : world.contactHitEvents()) hits.push_back(e);
        }
        ASSERT_EQ(hits.size(), 1u);
        const ContactHitEvent& hit = hits[0];
        EXPECT_EQ(hit.shapeA, ground);  // polygons come before circles in a contact
        EXPECT_EQ(hit.shapeB, ballShape);
        EXPECT_NEAR(hit.normal.x, 0.0f, 1e-6f);
        EXPECT_NEAR(hit.normal.y, 1.0f, 1e-6f);
        EXPECT_NEAR(hit.point.x, 1.0f, 1e-3f);
        EXPECT_NEAR(hit.point.y, 0.5f, 0.05f);  // the discrete landing sinks in up to a step
        // sqrt(2 g h) = 5 m/s; the step it lands in starts up to one step's gravity earlier.
        EXPECT_NEAR(hit.approachSpeed, 5.0f, 10.0f * kDt + 0.01f);
    }
}

TEST(HitEvents, NeedTheShapeFlagAndASpeedAboveTheThreshold) {
    // Without the flag; with it but a threshold above the 5 m/s landing.
    for (int variant = 0; variant < 2; ++variant) {
        WorldDef def = oneSubstepDef();
        if (variant == 1) def.hitEventThreshold = 6.0f;
        World world(def);
        const ShapeId ground = groundBox(world, variant == 0 ? ShapeDef{} : hitDef());
        const BodyId ball = bodyAt(world, BodyType::Dynamic, {0.0f, 2.0f});
        world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
        int hits = 0;
        for (int i = 0; i < 120; ++i) {
            world.step(kDt);
            hits += static_cast<int>(world.contactHitEvents().size());
        }
        EXPECT_EQ(hits, 0) << "variant " << variant;
        if (variant == 0) {
            world.setShapeHitEventsEnabled(ground, true);
            EXPECT_TRUE(world.shapeHitEventsEnabled(ground));
        }
    }
    World world{oneSubstepDef()};
    EXPECT_FLOAT_EQ(world.hitEventThreshold(), kDefaultHitEventThreshold);
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(world.setHitEventThreshold(-1.0f), Error);
    EXPECT_THROW(world.setHitEventThreshold(NAN), Error);
    EXPECT_THROW(world.setHitEventThreshold(2.0f * kMaxSpeed), Error);
    EXPECT_EQ(world.stateHash(), before);
    WorldDef bad = oneSubstepDef();
    bad.hitEventThreshold = -0.5f;
    EXPECT_THROW(World{bad}, Error);
}

namespace {

// A one-way platform: contacts with it are kept only while the other body moves down onto it
// from above (the normal, from the platform to the body, points up).
struct OneWayPlatform {
    ShapeId platform;
    int asked = 0;
    bool operator()(World& world, const ContactData& c) {
        ++asked;
        const bool platformIsA = c.shapeA == platform;
        const ShapeId other = platformIsA ? c.shapeB : c.shapeA;
        const Vec2 up = platformIsA ? c.normal : -c.normal;
        const float vy = world.bodyLinearVelocity(world.shapeBody(other)).y;
        return up.y > 0.7f && vy <= 0.5f;
    }
};

}  // namespace

// A ball thrown up through a thin platform passes it, then lands on it and stays; the callback
// sees only contacts of the flagged shape. With continuous collision on (the default) and a fast
// ball, so the impact search consults the callback too.
TEST(PreSolve, MakesAOneWayPlatformAlsoForFastBodies) {
    for (float speed : {8.0f, 40.0f}) {
        World world{oneSubstepDef()};
        ShapeDef platformDef;
        platformDef.enablePreSolve = true;
        const ShapeId platform = groundBox(world, platformDef, 0.0f, 0.05f);
        EXPECT_TRUE(world.shapePreSolveEnabled(platform));
        groundBox(world, ShapeDef{}, -30.0f);  // a floor far below, not asked about
        const BodyId ball = bodyAt(world, BodyType::Dynamic, {0.0f, -1.0f}, {0.0f, speed});
        world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.2f});
        OneWayPlatform rule{platform};
        world.setPreSolveCallback([&](const ContactData& c) { return rule(world, c); });
        float highest = -1.0f;
        for (int i = 0; i < 600; ++i) {
            world.step(kDt);
            highest = std::max(highest, world.bodyPosition(ball).y);
        }
        const float apex = -1.0f + speed * speed / 20.0f;
        EXPECT_GT(highest, 0.9f * apex) << speed;  // it went through on the way up
        EXPECT_NEAR(world.bodyPosition(ball).y, 0.05f + 0.2f, 0.02f) << speed;  // and landed
        EXPECT_GT(rule.asked, 0);
    }
}

TEST(PreSolve, WithoutTheFlagOrWithTheCallbackClearedContactsAreSolved) {
    World world{oneSubstepDef()};
    const ShapeId platform = groundBox(world, ShapeDef{});
    const BodyId ball = bodyAt(world, BodyType::Dynamic, {0.0f, 1.0f});
    world.createShape(ball, ShapeDef{}, Circle{{0, 0}, 0.25f});
    int asked = 0;
    world.setPreSolveCallback([&](const ContactData&) {
        ++asked;
        return false;
    });
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_EQ(asked, 0);  // the platform did not ask
    EXPECT_NEAR(world.bodyPosition(ball).y, 0.75f, 0.01f);
    world.setShapePreSolveEnabled(platform, true);
    world.step(kDt);
    EXPECT_GT(asked, 0);
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(ball).y, 0.0f);  // refused: it falls through
    // The contact still touches (its begin was told), it is just not solved.
    world.setPreSolveCallback(nullptr);
    world.setBodyTransform(ball, {3.0f, 1.0f}, 0.0f);
    world.setBodyLinearVelocity(ball, {});
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.bodyPosition(ball).y, 0.75f, 0.01f);
}

// A callback may read the world, not change it; an exception it throws comes out of step once
// the step is done, and the step is the one a callback saying yes would have made.
TEST(Callbacks, MayReadTheWorldButNotChangeItAndTheirExceptionsComeOutOfStep) {
    auto build = [](World& world) {
        ShapeDef asking;
        asking.enablePreSolve = true;
        groundBox(world, asking);
        for (int i = 0; i < 3; ++i) {
            const BodyId box = bodyAt(world, BodyType::Dynamic, {i * 1.5f, 0.9f});
            world.createShape(box, ShapeDef{}, Polygon::box(0.4f, 0.4f));
        }
    };
    World reference, throwing;
    build(reference);
    build(throwing);
    reference.setPreSolveCallback([](const ContactData&) { return true; });
    int refused = 0;
    int calls = 0;
    throwing.setPreSolveCallback([&](const ContactData& c) {
        ++calls;
        EXPECT_TRUE(throwing.isValid(c.shapeA));  // reading is fine
        const BodyId body = throwing.shapeBody(c.shapeB);
        try {
            throwing.setBodyLinearVelocity(body, {1.0f, 0.0f});
        } catch (const Error&) {
            ++refused;
        }
        EXPECT_THROW(throwing.destroyBody(body), Error);
        EXPECT_THROW(throwing.step(kDt), Error);
        EXPECT_THROW(throwing.setPreSolveCallback(nullptr), Error);
        if (calls == 2) throw std::runtime_error("from the game");
        return true;
    });
    for (int i = 0; i < 5; ++i) reference.step(kDt);
    bool thrown = false;
    for (int i = 0; i < 5; ++i) {
        try {
            throwing.step(kDt);
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "from the game");
            EXPECT_FALSE(thrown);
            thrown = true;
        }
    }
    EXPECT_TRUE(thrown);
    EXPECT_EQ(refused, calls);
    EXPECT_EQ(reference.stateHash(), throwing.stateHash());
}

// The custom filter keeps a pair apart; asked again when a shape's filter is set.
TEST(CustomFilter, KeepsPairsApartAndIsAskedAgainOnRefiltering) {
    World world{oneSubstepDef()};
    const ShapeId ground = groundBox(world, ShapeDef{});
    const BodyId a = bodyAt(world, BodyType::Dynamic, {-2.0f, 1.0f});
    const BodyId b = bodyAt(world, BodyType::Dynamic, {2.0f, 1.0f});
    const ShapeId shapeA = world.createShape(a, ShapeDef{}, Circle{{0, 0}, 0.25f});
    const ShapeId shapeB = world.createShape(b, ShapeDef{}, Circle{{0, 0}, 0.25f});
    ShapeId refuse = shapeA;
    std::vector<std::pair<ShapeId, ShapeId>> asked;
    world.setCustomFilterCallback([&](ShapeId s1, ShapeId s2) {
        asked.push_back({s1, s2});
        return s1 != refuse && s2 != refuse;
    });
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(a).y, 0.0f);  // fell through
    EXPECT_NEAR(world.bodyPosition(b).y, 0.75f, 0.01f);
    EXPECT_FALSE(asked.empty());
    for (const auto& pair : asked) {
        EXPECT_TRUE(pair.first == ground || pair.second == ground);
    }
    // Refusing b now takes effect when its filter is set again: its contact goes, with an end.
    refuse = shapeB;
    world.setShapeFilter(shapeB, world.shapeFilter(shapeB));
    world.step(kDt);
    const std::vector<ContactEvent> ends = world.contactEndEvents();
    ASSERT_EQ(ends.size(), 1u);
    EXPECT_TRUE(ends[0].shapeA == shapeB || ends[0].shapeB == shapeB);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(b).y, 0.0f);
}

// A 1 kg body hanging from a revolute joint pulls 10 N: a break force above holds it, one
// below lets go in the next step with the force that broke it.
TEST(BreakableJoints, LetGoWhenTheirForceOrTorquePassesTheThreshold) {
    World world{oneSubstepDef()};
    const BodyId anchor = bodyAt(world, BodyType::Static, {0.0f, 5.0f});
    const BodyId weight = bodyAt(world, BodyType::Dynamic, {0.0f, 4.0f});
    ShapeDef dense;
    dense.density = 1.0f / 0.04f;  // a 0.2 m square of 1 kg
    world.createShape(weight, dense, Polygon::box(0.1f, 0.1f));
    RevoluteJointDef pin = RevoluteJointDef::atWorldAnchor(anchor, weight, {0.0f, 5.0f});
    pin.breakForce = 15.0f;
    const JointId joint = world.createJoint(pin);
    EXPECT_FLOAT_EQ(world.jointBreakForce(joint), 15.0f);
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        EXPECT_TRUE(world.jointLetGoEvents().empty());
    }
    EXPECT_NEAR(length(world.jointReactionForce(joint)), 10.0f, 0.05f);
    world.setJointBreakForce(joint, 8.0f);
    world.step(kDt);
    const std::vector<JointLetGoEvent> events = world.jointLetGoEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].joint, joint);
    EXPECT_EQ(events[0].reason, JointLetGoReason::Force);
    EXPECT_NEAR(events[0].reaction, 10.0f, 0.05f);
    EXPECT_TRUE(world.isJointLetGo(joint));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.bodyPosition(weight).y, 3.0f);  // it fell

    // A weld holding a 1 kg body 1 m out holds 10 N m.
    const BodyId arm = bodyAt(world, BodyType::Dynamic, {1.0f, 5.0f});
    world.createShape(arm, dense, Polygon::box(0.1f, 0.1f));
    WeldJointDef weld;
    weld.bodyA = anchor;
    weld.bodyB = arm;
    weld.worldAnchor = Vec2{0.0f, 5.0f};
    weld.breakTorque = 12.0f;
    const JointId weldJoint = world.createJoint(weld);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_FALSE(world.isJointLetGo(weldJoint));
    world.setJointBreakTorque(weldJoint, 9.0f);
    world.step(kDt);
    ASSERT_EQ(world.jointLetGoEvents().size(), 1u);
    EXPECT_EQ(world.jointLetGoEvents()[0].reason, JointLetGoReason::Torque);
    EXPECT_NEAR(world.jointLetGoEvents()[0].reaction, 10.0f, 0.2f);
    EXPECT_FLOAT_EQ(world.jointBreakTorque(weldJoint), 9.0f);

    // Checked as the defs are.
    const std::uint64_t before = world.stateHash();
    EXPECT_THROW(world.setJointBreakForce(weldJoint, -1.0f), Error);
    EXPECT_THROW(world.setJointBreakTorque(weldJoint, INFINITY), Error);
    EXPECT_THROW(world.setJointBreakForce(weldJoint, 2.0f * kMaxMagnitude), Error);
    pin.breakForce = NAN;
    EXPECT_THROW(world.createJoint(pin), Error);
    EXPECT_EQ(world.stateHash(), before);
}

// A break force is a force over the step, whatever the substeps: a 36 kg crate dropped on a 40 kg
// plank pinned at both ends is stopped within one substep, which per substep would read four or
// eight times the force of the step it lands in. Thresholds set from the largest force of a step
// at one substep (at 1.5 and 0.5 times it) decide the same at 1, 4 and 8 substeps. (A plank much
// lighter than the crate gives way under it at one substep, and its joints' impulses stop the
// crate over several steps: there the force itself differs with the substeps, not its reading.)
TEST(BreakableJoints, BreakTheSameWhateverTheSubsteps) {
    struct Drop {
        World world{oneSubstepDef()};
        JointId left, right;
        explicit Drop(int substeps) : world(makeDef(substeps)) {
            const BodyId ground = world.createBody(BodyDef{});
            const BodyId plank = bodyAt(world, BodyType::Dynamic, {0.0f, 5.0f});
            ShapeDef plankShape;
            plankShape.density = 80.0f;  // 40 kg
            world.createShape(plank, plankShape, Polygon::box(1.0f, 0.125f));
            left = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, plank, {-1.0f, 5.0f}));
            right = world.createJoint(RevoluteJointDef::atWorldAnchor(ground, plank, {1.0f, 5.0f}));
            const BodyId crate = bodyAt(world, BodyType::Dynamic, {0.0f, 7.0f});
            ShapeDef heavy;
            heavy.density = 36.0f;  // 36 kg
            world.createShape(crate, heavy, Polygon::box(0.5f, 0.5f));
        }
        static WorldDef makeDef(int substeps) {
            WorldDef def = oneSubstepDef();
            def.substepCount = substeps;
            return def;
        }
        // The largest force either pin applied in a step, over `steps` steps.
        float peakForce(int steps) {
            float peak = 0.0f;
            for (int i = 0; i < steps; ++i) {
                world.step(kDt);
                for (JointId j : {left, right}) {
                    peak = std::max(peak, length(world.jointReactionForce(j)));
                }
            }
            return peak;
        }
        bool breaks(float threshold, int steps) {
            world.setJointBreakForce(left, threshold);
            world.setJointBreakForce(right, threshold);
            for (int i = 0; i < steps; ++i) {
                world.step(kDt);
                if (!world.jointLetGoEvents().empty()) return true;
            }
            return false;
        }
    };
    const float peak = Drop(1).peakForce(120);
    EXPECT_GT(peak, 3.0f * 36.0f * 10.0f / 2.0f) << "the landing is an impact, not the weight";
    for (int substeps : {1, 4, 8}) {
        EXPECT_FALSE(Drop(substeps).breaks(1.5f * peak, 120)) << substeps << " substeps";
        EXPECT_TRUE(Drop(substeps).breaks(0.5f * peak, 120)) << substeps << " substeps";
    }
}

// Every awake dynamic or kinematic body is listed with its transform; one falling asleep is
// listed once more with the flag, then no longer.
TEST(BodyMoveEvents, ListAwakeBodiesAndTheirFallingAsleep) {
    World world{oneSubstepDef()};
    groundBox(world, ShapeDef{});
    const BodyId box = bodyAt(world, BodyType::Dynamic, {0.0f, 1.0f});
    world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.5f));
    const BodyId mover = bodyAt(world, BodyType::Kinematic, {5.0f, 5.0f}, {1.0f, 0.0f});
    world.createShape(mover, ShapeDef{}, Circle{{0, 0}, 0.5f});
    bool sawAsleep = false;
    for (int i = 0; i < 300; ++i) {
        world.step(kDt);
        bool listedBox = false, listedMover = false;
        for (const BodyMoveEvent& e : world.bodyMoveEvents()) {
            EXPECT_EQ(e.transform.p, world.bodyPosition(e.body));
            if (e.body == box) {
                listedBox = true;
                EXPECT_FALSE(sawAsleep);
                if (e.fellAsleep) {
                    sawAsleep = true;
                    EXPECT_FALSE(world.isBodyAwake(box));
                }
            }
            listedMover |= e.body == mover;
        }
        EXPECT_EQ(listedBox, world.isBodyAwake(box) || (sawAsleep && listedBox));
        EXPECT_TRUE(listedMover);  // a moving kinematic body never sleeps
    }
    EXPECT_TRUE(sawAsleep);
}

// Rain of hit-event balls onto a ramp of boxes: the hit, move, begin and let-go lists are the
// same, entry for entry, on 1 and 2 workers.
TEST(Events, ComeInTheSameOrderOnAnyWorkerCount) {
    auto run = [](int workers) {
        WorldDef def = oneSubstepDef();
        def.workerCount = workers;
        World world(def);
        groundBox(world, hitDef());
        std::vector<float> trace;
        for (int i = 0; i < 120; ++i) {
            const BodyId ball =
                bodyAt(world, BodyType::Dynamic, {-8.0f + (i % 16) * 1.0f, 2.0f + (i / 16) * 1.2f});
            world.createShape(ball, hitDef(), Circle{{0, 0}, 0.3f + 0.01f * (i % 7)});
        }
        for (int s = 0; s < 240; ++s) {
            world.step(kDt);
            for (const ContactHitEvent& e : world.contactHitEvents()) {
                trace.push_back(static_cast<float>(e.shapeB.index));
                trace.push_back(e.approachSpeed);
                trace.push_back(e.point.x);
            }
            for (const BodyMoveEvent& e : world.bodyMoveEvents()) {
                trace.push_back(static_cast<float>(e.body.index));
                trace.push_back(e.transform.p.y);
            }
        }
        return trace;
    };
    const std::vector<float> one = run(1);
    EXPECT_GT(one.size(), 1000u);
    EXPECT_EQ(one, run(2));
}

TEST(StepStats, TouchingCountIsEveryTouchingContact) {
    // StepStats::touchingCount is counted as contacts begin and end, not by a pass over the
    // contacts; it must agree with one in every scene (contacts made, destroyed, filtered,
    // sensors, sleep, continuous collision, bodies destroyed by the scenes' scripts), and after
    // a snapshot is restored.
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        scenes::SceneOptions options;
        scenes::Scene scene = scenes::buildScene(info, options);
        for (int i = 0; i < 240; ++i) {
            if (scene.beforeStep) scene.beforeStep(scene, i);
            scene.world->step(1.0f / options.hz);
            ASSERT_EQ(scene.world->lastStepStats().touchingCount,
                      static_cast<int>(scene.world->contacts().size()))
                << info.name << ", step " << i;
            if (i == 120) scene.world->restore(scene.world->snapshot());
        }
    }
}

// A step's contact events are the change it made: its begin events, then its end events,
// applied to the pairs touching before it give the pairs touching after it (a pair in both lists
// began and then ended within the step). Continuous collision measures contacts again within
// a step, and a contact the step's update saw part could touch again: reported as both an end
// and a begin, the lists said nothing of the order. Every scene, with both continuous
// collisions, and a shower of fast balls bouncing on a floor (impacts every step).
TEST(ContactEvents, ApplyBeginsThenEndsToGetTheTouchingPairs) {
    using Pair = std::pair<std::int32_t, std::int32_t>;
    auto touchingNow = [](const World& world) {
        std::set<Pair> now;
        for (const ContactData& c : world.contacts()) now.insert({c.shapeA.index, c.shapeB.index});
        return now;
    };
    auto follow = [&](World& world, const std::function<void(int)>& beforeStep, int steps,
                      const std::string& name) {
        std::set<Pair> known = touchingNow(world);
        for (int i = 0; i < steps; ++i) {
            if (beforeStep) beforeStep(i);
            // What a script did between steps (destroying shapes, switching sensors) is
            // reported at once and cleared by the step: take the world's word for it.
            known = touchingNow(world);
            world.step(kDt);
            for (const ContactEvent& e : world.contactBeginEvents()) {
                EXPECT_TRUE(known.insert({e.shapeA.index, e.shapeB.index}).second)
                    << name << ", step " << i << ": a begin for a pair already touching";
            }
            for (const ContactEvent& e : world.contactEndEvents()) {
                EXPECT_EQ(known.erase({e.shapeA.index, e.shapeB.index}), 1u)
                    << name << ", step " << i << ": an end for a pair not touching";
            }
            if (known != touchingNow(world)) {
                ADD_FAILURE() << name << ", step " << i
                              << ": the events do not give the pairs touching after the step";
                return;
            }
        }
    };
    for (const ContinuousCollision policy :
         {ContinuousCollision::Substeps, ContinuousCollision::FastBodies}) {
        for (const scenes::SceneInfo& info : scenes::allScenes()) {
            scenes::SceneOptions options;
            options.continuousCollision = policy;
            scenes::Scene scene = scenes::buildScene(info, options);
            follow(
                *scene.world,
                [&](int i) {
                    if (scene.beforeStep) scene.beforeStep(scene, i);
                },
                120, info.name);
        }
    }
    World shower{oneSubstepDef()};
    ShapeDef bouncy;
    bouncy.restitution = 1.0f;
    groundBox(shower, bouncy, 0.0f, 0.5f);
    for (int i = 0; i < 40; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.bullet = i % 2 == 0;
        def.position = {-10.0f + 0.5f * float(i), 1.0f + 0.3f * float(i % 5)};
        def.linearVelocity = {0.0f, -60.0f - 5.0f * float(i % 7)};
        shower.createShape(shower.createBody(def), bouncy, Circle{{}, 0.1f});
    }
    follow(shower, nullptr, 240, "shower");
}
