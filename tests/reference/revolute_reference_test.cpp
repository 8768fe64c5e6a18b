// pivot2d's FullNGS revolute joint against Box2D 2.4.1's reference revolute joint, which
// corrects positions by full NGS. Same scene, step, iterations and constants in both.
#include <gtest/gtest.h>

#include <cmath>

#include "box2d_scenes.h"
#include "scenes/scene.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Difference {
    double position = 0.0;  // m, largest centre-of-mass distance over bodies and steps
    double angle = 0.0;     // rad, largest angle difference
};

// Steps both worlds together and records the largest difference seen.
Difference compare(scenes::Scene& ours, reference::Box2dScene& theirs, int steps) {
    Difference d;
    for (int s = 0; s < steps; ++s) {
        ours.world->step(kDt, 8, 3);
        theirs.world->Step(kDt, 8, 3);
        for (std::size_t i = 0; i < ours.bodies.size(); ++i) {
            Vec2 c = ours.world->bodyWorldCenter(ours.bodies[i]);
            b2Vec2 r = theirs.bodies[i]->GetWorldCenter();
            d.position = std::max(d.position, std::hypot(double(c.x) - r.x, double(c.y) - r.y));
            d.angle = std::max(d.angle, std::fabs(double(ours.world->bodyAngle(ours.bodies[i])) -
                                                  theirs.bodies[i]->GetAngle()));
        }
    }
    return d;
}

scenes::Scene pivotPendulum(float spin) {
    // The testbed pendulum at a chosen spin: rebuild it with the velocity replaced.
    scenes::Scene scene = scenes::buildScene(*scenes::findScene("pendulum"), {});
    World& world = *scene.world;
    BodyId ball = scene.bodies[0];
    Vec2 pivot = world.jointAnchorA(scene.joints[0]);
    world.setBodyAngularVelocity(ball, spin);
    world.setBodyLinearVelocity(ball, cross(spin, world.bodyWorldCenter(ball) - pivot));
    return scene;
}

}  // namespace

class PendulumAgainstBox2d : public testing::TestWithParam<float> {};

TEST_P(PendulumAgainstBox2d, FullNgsMatchesFor600Steps) {
    scenes::Scene ours = pivotPendulum(GetParam());
    reference::Box2dScene theirs = reference::box2dPendulum(GetParam());
    Difference d = compare(ours, theirs, 600);
    EXPECT_LE(d.position, 1e-4);
    EXPECT_LE(d.angle, 1e-4);
#if defined(__x86_64__)
    // On x86-64 (SSE arithmetic, no fused multiply-add on either side) the two runs perform the
    // same float operations in the same order: the agreement is exact.
    EXPECT_EQ(d.position, 0.0);
    EXPECT_EQ(d.angle, 0.0);
#endif
}

INSTANTIATE_TEST_SUITE_P(Spins, PendulumAgainstBox2d, testing::Values(1.0f, 10.0f, 100.0f),
                         [](const auto& info) {
                             return std::to_string(static_cast<int>(info.param)) + "RadPerSecond";
                         });

TEST(ChainAgainstBox2d, FullNgsMatchesOverTheFirst30Steps) {
    // The chain is chaotic, so agreement is required only at the start: the trajectories part
    // slowly as float round-off (here, in the polygon mass integrals) is amplified.
    scenes::Scene ours = scenes::buildScene(*scenes::findScene("chain"), {});
    reference::Box2dScene theirs = reference::box2dChain();
    Difference d = compare(ours, theirs, 30);
    EXPECT_LE(d.position, 1e-4);
    EXPECT_LE(d.angle, 1e-4);
}
