// The promises of the input limits, each from a report of a world that broke one (issue 11,
// docs/reliability.md): a time step too short to divide by is refused; calls cannot pile up
// velocities or forces beyond the limits between steps; accepted input at the corners of every
// limit steps without an overflow (no body state discarded, no joint let go); and every state the
// engine produces is one the API accepts back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "all_solvers.h"
#include "pivot/pivot.h"
#include "scenes/scene.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {
constexpr float kDt = 1.0f / 60.0f;
constexpr const auto& kSolvers = test_support::kAllSolvers;
constexpr ContactCorrection kCorrections[] = {ContactCorrection::NGS, ContactCorrection::Baumgarte};

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

void expectRefused(World& world, const std::function<void()>& call,
                   const std::vector<std::string>& words) {
    const std::uint64_t before = world.stateHash();
    try {
        call();
        ADD_FAILURE() << "accepted a call that must be refused";
    } catch (const Error& e) {
        for (const std::string& w : words) {
            EXPECT_NE(std::string(e.what()).find(w), std::string::npos)
                << "\"" << e.what() << "\" does not mention \"" << w << "\"";
        }
    }
    EXPECT_EQ(world.stateHash(), before) << "a refused call changed the world";
}

// The report's pendulum: a 1 x 0.2 m box on a revolute joint at the origin, with a mouse joint
// holding its far end, after 30 steps.
struct Pendulum {
    World world{oneSubstepDef()};
    BodyId box;
    JointId pin;

    Pendulum(PositionSolver solver, ContactCorrection correction)
        : world([&] {
              WorldDef def = oneSubstepDef();
              def.contactCorrection = correction;
              return def;
          }()) {
        BodyId ground = world.createBody(BodyDef{});
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {0.5f, 0.0f};
        box = world.createBody(bd);
        world.createShape(box, ShapeDef{}, Polygon::box(0.5f, 0.1f));
        RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(ground, box, {0.0f, 0.0f});
        jd.positionSolver = solver;
        pin = world.createJoint(jd);
        MouseJointDef md;
        md.body = box;
        md.target = {1.0f, 0.0f};
        world.createMouseJoint(md);
        for (int i = 0; i < 30; ++i) world.step(kDt);
    }
};

}  // namespace

// --- the time step -----------------------------------------------------------------------------

TEST(TimeStep, TooShortToDivideByIsRefused) {
    for (PositionSolver solver : kSolvers) {
        Pendulum p(solver, ContactCorrection::NGS);
        // 1e-40 s made 1/dt infinite and every joint's reaction NaN; 1e-30 s let a Baumgarte
        // pendulum reach 1.6e27 m/s.
        for (float dt : {1e-40f, 1e-30f, 1e-12f, 0.5f * kMinTimeStep}) {
            expectRefused(p.world, [&] { p.world.step(dt); }, {"World::step", "kMinTimeStep"});
        }
    }
}

// A short step between ordinary ones leaves the pendulum on its pin, whatever the strategy
// and contact correction: finite reactions, nothing let go, the joint still together.
TEST(TimeStep, AShortStepKeepsThePendulumOnItsPin) {
    for (PositionSolver solver : kSolvers) {
        for (ContactCorrection correction : kCorrections) {
            for (float dt : {kMinTimeStep, 1e-4f, 1e-3f}) {
                Pendulum p(solver, correction);
                p.world.step(dt);
                for (int i = 0; i < 60; ++i) {
                    p.world.step(kDt);
                    ASSERT_EQ(p.world.lastStepStats().letGoJointCount, 0);
                    ASSERT_EQ(p.world.lastStepStats().discardedBodyCount, 0);
                    ASSERT_TRUE(finite(p.world.jointReactionForce(p.pin)));
                }
                EXPECT_LT(p.world.jointSeparation(p.pin), 0.01f)
                    << positionSolverName(solver) << " dt " << dt;
            }
        }
    }
}

// Warm starting scales the last step's impulses by the ratio of the steps, but never up: after
// a very short step its impulses say nothing about the next step's forces (scaled by
// (1/60) / 1e-5 they threw a FullNGS chain apart by a metre). The NGS strategies and
// PseudoVelocity now carry the chain through a short step as if it had not happened; Baumgarte
// turns the error left by the long steps into a velocity error / dt in the short one, which is
// what that method does (docs/position-correction.md).
TEST(TimeStep, AShortStepDoesNotThrowTheChainApart) {
    for (PositionSolver solver :
         {PositionSolver::PseudoVelocity, PositionSolver::ModifiedNGS, PositionSolver::FullNGS}) {
        auto largestSeparation = [&](bool shortStep) {
            scenes::SceneOptions options;
            options.solver = solver;
            scenes::Scene chain = scenes::buildScene(*scenes::findScene("chain"), options);
            for (int i = 0; i < 90; ++i) chain.world->step(kDt);
            if (shortStep) chain.world->step(kMinTimeStep);
            float largest = 0.0f;
            for (int i = 0; i < 60; ++i) {
                chain.world->step(kDt);
                for (JointId j : chain.joints) {
                    largest = std::max(largest, chain.world->jointSeparation(j));
                }
            }
            return largest;
        };
        EXPECT_LT(largestSeparation(true), largestSeparation(false) + 0.05f)
            << positionSolverName(solver);
    }
}

// --- what calls accumulate between steps ---------------------------------------------------------

// A sliver triangle at density 1e-6 far from the origin: inverse inertia near 1e17. 1.85 million
// accepted impulses used to make its angular velocity infinite, and a shape created and
// destroyed on it then made its velocity NaN. Every impulse that would take it beyond the
// limits is refused now, so it never gets there.
TEST(Accumulation, ImpulsesCannotPileUpBeyondTheLimits) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {-1e5f, -1e5f};
    BodyId b = world.createBody(bd);
    ShapeDef sliver;
    sliver.density = kMinDensity;
    world.createShape(b, sliver, Polygon::fromPoints({{0, 0}, {0.01f, 0}, {0.005f, 0.00051f}}));
    expectRefused(world,
                  [&] {
                      world.applyLinearImpulse(b, {0, 1e10f}, {1e5f, -1e5f});
                  },
                  {"applyLinearImpulse", "velocity", "beyond"});
    int accepted = 0, refused = 0;
    for (int i = 0; i < 20000; ++i) {
        try {
            world.applyLinearImpulse(b, {0, 1e-18f}, {1e5f, -1e5f});
            ++accepted;
        } catch (const Error& e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find("kMaxAngularSpeed"), std::string::npos);
        }
        ASSERT_LE(std::fabs(world.bodyAngularVelocity(b)), kMaxAngularSpeed);
    }
    EXPECT_GT(accepted, 0);
    EXPECT_GT(refused, 0);
    world.destroyShape(world.createShape(b, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f}));
    EXPECT_TRUE(finite(world.bodyLinearVelocity(b)));
    EXPECT_TRUE(std::isfinite(world.bodyAngularVelocity(b)));
    world.step(kDt);
    EXPECT_EQ(world.lastStepStats().discardedBodyCount, 0);
}

TEST(Accumulation, ForcesCannotPileUpBeyondTheLimits) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId b = world.createBody(bd);
    world.createShape(b, ShapeDef{}, Circle{{0.0f, 0.0f}, 1.0f});  // 3.1 kg
    world.applyForceToCenter(b, {0.0f, 0.6f * kMaxMagnitude});
    expectRefused(world,
                  [&] {
                      world.applyForceToCenter(b, {0.0f, 0.6f * kMaxMagnitude});
                  },
                  {"pending force", "kMaxMagnitude"});
    // Far from the centre, a force within its limit is a torque beyond its own.
    BodyId c = world.createBody(bd);
    world.createShape(c, ShapeDef{}, Circle{{0.0f, 0.0f}, 1.0f});
    expectRefused(world,
                  [&] {
                      world.applyForce(c, {1e6f, 0.0f}, {0.0f, kMaxCoordinate});
                  },
                  {"pending torque"});
    // A light body: the force is within its limit, the acceleration it would give is not.
    BodyId light = world.createBody(bd);
    ShapeDef feather;
    feather.density = kMinDensity;
    world.createShape(light, feather, Circle{{0.0f, 0.0f}, kLinearSlop});  // 7.9e-11 kg
    expectRefused(world,
                  [&] {
                      world.applyForceToCenter(light, {1.0f, 0.0f});
                  },
                  {"linear acceleration", "kMaxMagnitude"});
    expectRefused(world, [&] { world.applyTorque(light, 1.0f); }, {"angular acceleration"});
    EXPECT_NO_THROW(world.applyForceToCenter(light, {0.1f, 0.0f}));
}

// One rule for the five calls that set or push a body's motion: refused when they could have
// no effect.
TEST(Accumulation, CallsThatCouldHaveNoEffectAreRefused) {
    World world{oneSubstepDef()};
    BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(1.0f, 1.0f));
    expectRefused(world, [&] { world.setBodyLinearVelocity(ground, {1, 0}); }, {"static"});
    expectRefused(world, [&] { world.setBodyAngularVelocity(ground, 1); }, {"static"});
    expectRefused(world, [&] { world.applyForceToCenter(ground, {0, 1}); }, {"static"});
    expectRefused(world, [&] { world.applyForce(ground, {0, 1}, {1, 0}); }, {"static"});
    expectRefused(world, [&] { world.applyTorque(ground, 1); }, {"static"});
    expectRefused(world, [&] { world.applyLinearImpulse(ground, {0, 1}, {0, 0}); }, {"static"});
    expectRefused(world, [&] { world.applyAngularImpulse(ground, 1); }, {"static"});

    BodyDef kinematic;
    kinematic.type = BodyType::Kinematic;
    BodyId k = world.createBody(kinematic);
    EXPECT_NO_THROW(world.setBodyLinearVelocity(k, {1, 0}));
    EXPECT_NO_THROW(world.setBodyAngularVelocity(k, 1));
    expectRefused(world,
                  [&] {
                      world.applyForceToCenter(k, {0, 1});
                  },
                  {"kinematic", "set a kinematic body's velocity"});
    expectRefused(world, [&] { world.applyLinearImpulse(k, {0, 1}, {0, 0}); }, {"kinematic"});
    expectRefused(world, [&] { world.applyTorque(k, 1); }, {"kinematic"});

    BodyDef fixed;
    fixed.type = BodyType::Dynamic;
    fixed.fixedRotation = true;
    BodyId f = world.createBody(fixed);
    expectRefused(world, [&] { world.applyTorque(f, 1); }, {"fixed rotation"});
    expectRefused(world, [&] { world.applyAngularImpulse(f, 1); }, {"fixed rotation"});
    expectRefused(world, [&] { world.setBodyAngularVelocity(f, 1); }, {"fixed rotation"});
    EXPECT_NO_THROW(world.setBodyAngularVelocity(f, 0));
    EXPECT_NO_THROW(world.applyForce(f, {0, 1}, {1, 0}));  // the linear part acts
    EXPECT_NO_THROW(world.applyLinearImpulse(f, {0, 1}, {1, 0}));
    EXPECT_EQ(world.bodyAngularVelocity(f), 0.0f);
    fixed.angularVelocity = 2.0f;
    EXPECT_THROW(world.createBody(fixed), Error);
}

// --- products inside a step ---------------------------------------------------------------------

// Three boxes of 1e5 m at density 1e6 (1.2e17 kg) held by a 1e10 Hz mouse joint: the spring's
// stiffness m w^2 overflowed, and the body was discarded on every other step and never moved.
TEST(StepProducts, AHeavyBodyOnAStiffMouseJointMoves) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId b = world.createBody(bd);
    ShapeDef heavy;
    heavy.density = kMaxDensity;
    for (int i = 0; i < 3; ++i) world.createShape(b, heavy, Polygon::box(1e5f, 1e5f));
    MouseJointDef md;
    md.body = b;
    md.target = {10.0f, 0.0f};
    md.hertz = kMaxMagnitude;
    md.maxForce = kMaxMagnitude;
    world.createMouseJoint(md);
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.lastStepStats().discardedBodyCount, 0) << "step " << i;
    }
    EXPECT_LT(world.bodyPosition(b).y, -4.0f);  // falls under gravity: the hand cannot hold it
}

// A thousand such boxes with gravity 1e10 and gravity scale 1e10 were discarded every step. Both
// are bounded now so their product stays within kMaxMagnitude; at the new limits they fall.
TEST(StepProducts, HeavyBoxesUnderTheStrongestGravityFall) {
    WorldDef def = oneSubstepDef();
    def.gravity = {0.0f, 1e10f};
    EXPECT_THROW(World{def}, Error);
    def.gravity = {0.0f, -kMaxGravity};
    World world(def);
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.gravityScale = 1e10f;
    EXPECT_THROW(world.createBody(bd), Error);
    bd.gravityScale = kMaxGravityScale;
    ShapeDef heavy;
    heavy.density = kMaxDensity;
    std::vector<BodyId> boxes;
    for (int i = 0; i < 1000; ++i) {
        bd.position = {float(i % 40) * 4.0f, float(i / 40) * 4.0f};
        boxes.push_back(world.createBody(bd));
        world.createShape(boxes.back(), heavy, Polygon::box(1e5f, 1e5f));
    }
    // They overlap, half a million contacts: two steps (the report saw every step discarded).
    for (int i = 0; i < 2; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.lastStepStats().discardedBodyCount, 0) << "step " << i;
    }
    for (BodyId b : boxes) ASSERT_TRUE(finite(world.bodyPosition(b)));
    EXPECT_LT(world.bodyPosition(boxes[0]).y, 0.0f);
}

// Worlds drawn from the corners of every input limit (sizes, densities, speeds, gravity and
// its scale, friction, restitution, damping, forces, torques and impulses at their limits,
// mouse joints at their stiffest and softest, the shortest and longest steps, 0 to 1000
// iterations, both contact corrections, every strategy), stepped 30 times: no product may
// overflow, so no body state is discarded and no joint let go. The joints hold bodies side by
// side by anchors on their shapes; a joint whose anchor is kilometres from a light body's
// centre is another matter (below).
TEST(StepProducts, TheCornersOfEveryLimitStepInRange) {
    std::uint64_t state = 2026;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<std::uint32_t>(state >> 33);
    };
    auto pick = [&](std::initializer_list<float> values) {
        return *(values.begin() + next() % values.size());
    };
    auto coin = [&] { return (next() & 1) != 0; };
    int worlds = 0;
    for (int w = 0; w < 400; ++w) {
        WorldDef def = oneSubstepDef();
        const float g = pick({0.0f, -10.0f, kMaxGravity, -kMaxGravity});
        def.gravity = {g, -g};
        def.contactCorrection = kCorrections[next() % 2];
        def.defaultPositionSolver = kSolvers[next() % 4];
        World world(def);
        ShapeDef groundShape;
        groundShape.density = 0.0f;
        world.createShape(world.createBody(BodyDef{}), groundShape,
                          Polygon::box(kMaxCoordinate, 1.0f));
        const bool jointed = coin();
        std::vector<BodyId> bodies;
        const int count = 2 + static_cast<int>(next() % 4);
        for (int i = 0; i < count; ++i) {
            BodyDef bd;
            bd.type = !jointed && next() % 3 == 0 ? BodyType::Kinematic : BodyType::Dynamic;
            bd.position = {jointed ? float(i) : pick({float(i), kMaxCoordinate, -kMaxCoordinate}),
                           jointed ? 2.0f : pick({0.5f, 2.0f, kMaxCoordinate})};
            bd.angle = pick({0.0f, kMaxMagnitude, -kMaxMagnitude});
            const float v = pick({0.0f, kMaxSpeed, -kMaxSpeed});
            bd.linearVelocity = {v, -v};
            bd.fixedRotation = next() % 5 == 0;
            bd.angularVelocity =
                bd.fixedRotation ? 0.0f : pick({0.0f, kMaxAngularSpeed, -kMaxAngularSpeed});
            bd.linearDamping = pick({0.0f, kMaxMagnitude});
            bd.angularDamping = pick({0.0f, kMaxMagnitude});
            bd.gravityScale = pick({1.0f, kMaxGravityScale, -kMaxGravityScale});
            BodyId b = world.createBody(bd);
            for (int s = 0, shapes = coin() ? 3 : 1; s < shapes; ++s) {
                ShapeDef sd;
                sd.density = pick({kMinDensity, 1.0f, kMaxDensity});
                sd.friction = pick({0.0f, 0.6f, kMaxFriction});
                sd.restitution = pick({0.0f, 1.0f});
                // A shape that moves the centre of a body turning at the limit refuses to
                // take its velocity past kMaxSpeed; the body then keeps the shapes it has.
                try {
                    switch (next() % 4) {
                        case 0:
                            world.createShape(
                                b, sd,
                                Circle{{0, 0},
                                       jointed ? pick({kLinearSlop, 0.5f})
                                               : pick({kLinearSlop, 0.5f, kMaxCoordinate})});
                            break;
                        case 1:
                            world.createShape(b, sd,
                                              jointed
                                                  ? Polygon::box(0.5f, 0.5f)
                                                  : Polygon::box(kMaxCoordinate, kMaxCoordinate));
                            break;
                        case 2:  // a sliver: the largest inverse inertia
                            world.createShape(
                                b, sd,
                                Polygon::fromPoints({{0, 0}, {0.01f, 0}, {0.005f, 0.00051f}}));
                            break;
                        default:
                            world.createShape(
                                b, sd,
                                Polygon::box(0.5f, 0.5f,
                                             {jointed ? 0.0f : pick({0.0f, kMaxCoordinate - 1}), 0},
                                             0));
                    }
                } catch (const Error&) {
                }
            }
            bodies.push_back(b);
        }
        for (int i = 0; jointed && i + 1 < count; ++i) {
            RevoluteJointDef jd;
            jd.bodyA = bodies[i];
            jd.bodyB = bodies[i + 1];
            jd.localAnchorA = {0.5f, 0.0f};
            jd.localAnchorB = {-0.5f, 0.0f};
            jd.limit = {coin(), -kMaxMagnitude, pick({0.0f, kMaxMagnitude})};
            jd.motor = {coin(), pick({kMaxAngularSpeed, -kMaxAngularSpeed}),
                        pick({0.0f, kMaxMagnitude})};
            jd.biasFactor = pick({0.0f, 1.0f});
            world.createJoint(jd);
        }
        for (BodyId b : bodies) {
            if (world.bodyType(b) != BodyType::Dynamic || coin()) continue;
            MouseJointDef md;
            md.body = b;
            const float t = pick({0.0f, kMaxCoordinate});
            md.target = {t, t};
            md.maxForce = pick({1.0f, kMaxMagnitude});
            md.hertz = pick({5.0f, kMaxMagnitude, 1e-30f});
            md.dampingRatio = pick({0.0f, 0.7f, kMaxMagnitude});
            world.createMouseJoint(md);
        }
        for (int s = 0; s < 30; ++s) {
            // Pushes at the limits; the ones the body cannot take are refused.
            for (BodyId b : bodies) {
                if (world.bodyType(b) != BodyType::Dynamic || next() % 3 != 0) continue;
                const float f = pick({1.0f, kMaxMagnitude});
                const float at = pick({0.0f, kMaxCoordinate});
                try {
                    world.applyForce(b, {f, f}, {at, -at});
                } catch (const Error&) {
                }
                try {
                    world.applyTorque(b, pick({kMaxMagnitude, -kMaxMagnitude}));
                } catch (const Error&) {
                }
                try {
                    world.applyLinearImpulse(b, {kMaxMagnitude, 0.0f}, {0.0f, 0.0f});
                } catch (const Error&) {
                }
            }
            world.step(pick({kMinTimeStep, kDt, kMaxTimeStep}),
                       static_cast<int>(pick({0.0f, 8.0f, 1000.0f})),
                       static_cast<int>(pick({0.0f, 3.0f, 1000.0f})));
            ASSERT_EQ(world.lastStepStats().discardedBodyCount, 0)
                << "world " << w << " step " << s;
            ASSERT_EQ(world.lastStepStats().letGoJointCount, 0) << "world " << w << " step " << s;
            for (BodyId b : bodies) {
                ASSERT_TRUE(finite(world.bodyPosition(b)) && finite(world.bodyLinearVelocity(b)));
            }
        }
        ++worlds;
    }
    EXPECT_EQ(worlds, 400);
}

// --- states the engine produces are states the API accepts
// ----------------------------------------

// A body that fell to x = 100,089 m could not be put back where it was, nor have a joint or a
// mouse joint made there. The engine now keeps every body origin within +-kMaxCoordinate,
// holding a body that reaches the edge there and saying so.
TEST(EngineStates, ABodyIsHeldAtTheEdgeOfTheWorldAndReported) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {kMaxCoordinate - 50.0f, 0.0f};
    bd.linearVelocity = {100.0f, 0.0f};
    BodyId b = world.createBody(bd);
    world.createShape(b, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.5f});
    int held = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (const WorldEdgeEvent& e : world.worldEdgeEvents()) {
            EXPECT_EQ(e.body, b);
            EXPECT_GT(e.reached.x, kMaxCoordinate);
            ++held;
        }
        EXPECT_EQ(static_cast<int>(world.worldEdgeEvents().size()),
                  world.lastStepStats().edgeBodyCount);
        ASSERT_LE(world.bodyPosition(b).x, kMaxCoordinate);
    }
    EXPECT_GT(held, 0);
    EXPECT_EQ(world.bodyPosition(b).x, kMaxCoordinate);
    EXPECT_EQ(world.bodyLinearVelocity(b).x, 0.0f);  // stopped outwards
    EXPECT_LT(world.bodyLinearVelocity(b).y, 0.0f);  // still falling
    // Everything the engine reports can be given back to it.
    EXPECT_NO_THROW(world.setBodyTransform(b, world.bodyPosition(b), world.bodyAngle(b)));
    EXPECT_NO_THROW(world.setBodyLinearVelocity(b, world.bodyLinearVelocity(b)));
    BodyId other = world.createBody(BodyDef{});
    EXPECT_NO_THROW(
        world.createJoint(RevoluteJointDef::atWorldAnchor(other, b, world.bodyPosition(b))));
    MouseJointDef md;
    md.body = b;
    md.target = world.bodyPosition(b);
    EXPECT_NO_THROW(world.createMouseJoint(md));
}

TEST(EngineStates, EveryBodyStateOfEveryScenePassesBackThroughTheApi) {
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        for (PositionSolver solver : kSolvers) {
            scenes::SceneOptions options;
            options.solver = solver;
            scenes::Scene scene = scenes::buildScene(info, options);
            World& world = *scene.world;
            for (int i = 0; i < 300; ++i) {
                if (scene.beforeStep) scene.beforeStep(scene, i);
                world.step(kDt);
                if (i % 50 != 49) continue;
                for (BodyId b : world.bodyIds()) {
                    world.setBodyTransform(b, world.bodyPosition(b), world.bodyAngle(b));
                    if (world.bodyType(b) != BodyType::Static) {
                        world.setBodyLinearVelocity(b, world.bodyLinearVelocity(b));
                        world.setBodyAngularVelocity(b, world.bodyAngularVelocity(b));
                    }
                }
            }
        }
    }
}

// --- defs ---------------------------------------------------------------------------------------

TEST(Defs, AWorldAnchorWithLocalAnchorsIsRefused) {
    World world{oneSubstepDef()};
    BodyId a = world.createBody(BodyDef{});
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    BodyId b = world.createBody(bd);
    RevoluteJointDef def = RevoluteJointDef::atWorldAnchor(a, b, {1.0f, 2.0f});
    def.localAnchorA = {0.5f, 0.0f};
    expectRefused(world, [&] { world.createJoint(def); },
                  {"def.worldAnchor (1, 2)", "def.localAnchorA (0.5, 0)", "set one or the other"});
    def = RevoluteJointDef::atWorldAnchor(a, b, {1.0f, 2.0f});
    def.localAnchorB = {0.0f, -1.0f};
    expectRefused(world, [&] { world.createJoint(def); }, {"def.localAnchorB"});
    def = RevoluteJointDef::atWorldAnchor(a, b, {1.0f, 2.0f});
    def.referenceAngle = 0.3f;
    expectRefused(world, [&] { world.createJoint(def); }, {"def.referenceAngle"});
    def = RevoluteJointDef::atWorldAnchor(a, b, {1.0f, 2.0f});
    JointId j = world.createJoint(def);
    EXPECT_EQ(world.jointAnchorA(j), (Vec2{1.0f, 2.0f}));
}

TEST(Defs, UserDataCanBeReadAndChanged) {
    World world{oneSubstepDef()};
    BodyDef bd;
    bd.userData = 11;
    BodyId a = world.createBody(bd);
    bd.type = BodyType::Dynamic;
    bd.userData = 12;
    BodyId b = world.createBody(bd);
    ShapeDef sd;
    sd.userData = 0xFFFFFFFFFFFFFFFFull;
    ShapeId s = world.createShape(b, sd, Circle{});
    RevoluteJointDef jd = RevoluteJointDef::atWorldAnchor(a, b, {});
    jd.userData = 14;
    JointId j = world.createJoint(jd);
    EXPECT_EQ(world.bodyUserData(a), 11u);
    EXPECT_EQ(world.bodyUserData(b), 12u);
    EXPECT_EQ(world.shapeUserData(s), 0xFFFFFFFFFFFFFFFFull);
    EXPECT_EQ(world.jointUserData(j), 14u);
    world.setBodyUserData(a, 21);
    world.setShapeUserData(s, 23);
    world.setJointUserData(j, 24);
    EXPECT_EQ(world.bodyUserData(a), 21u);
    EXPECT_EQ(world.shapeUserData(s), 23u);
    EXPECT_EQ(world.jointUserData(j), 24u);
    // The hash covers it, and a stale id is refused.
    const std::uint64_t before = world.stateHash();
    world.setBodyUserData(a, 22);
    EXPECT_NE(world.stateHash(), before);
    world.destroyBody(b);
    EXPECT_THROW(world.shapeUserData(s), Error);
    EXPECT_THROW(world.setJointUserData(j, 1), Error);
}
