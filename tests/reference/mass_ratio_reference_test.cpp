// A joint is never let go for being stretched unless the user asked for it, as in Box2D 2.4.1.
// The case that showed it: 20 light links holding a ball 3,000 times heavier
// (scenes::buildMassRatio). Neither engine's full NGS holds that mass ratio, and the chain
// stretches tens of metres in both; pivot2d used to stop solving any joint more than 10 m apart,
// which cut the chain for good where Box2D kept pulling it together.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reference/reference_cases.h"

using namespace pivot;
using namespace pivot::reference;

namespace {

const ReferenceCase kMassRatio{"mass_ratio", true, scenes::buildMassRatio, box2d::buildMassRatio};
constexpr int kSteps = 600;
constexpr float kDt = 1.0f / 60.0f;

scenes::SceneOptions fullNgs() {
    scenes::SceneOptions options;
    options.solver = PositionSolver::FullNGS;
    return options;
}

}  // namespace

TEST(MassRatioAgainstBox2d, NoJointIsLetGoHoweverFarTheChainStretches) {
    scenes::Scene ours = buildPivotCase(kMassRatio, fullNgs());
    box2d::Box2dScene theirs = kMassRatio.buildBox2d(false);
    float oursMax = 0.0f, theirsMax = 0.0f;
    for (int s = 0; s < kSteps; ++s) {
        ours.world->step(kDt, 8, 3);
        theirs.world->Step(kDt, 8, 3);
        ASSERT_EQ(ours.world->lastStepStats().letGoJointCount, 0) << "step " << s;
        for (std::size_t j = 0; j < ours.joints.size(); ++j) {
            ASSERT_FALSE(ours.world->isJointLetGo(ours.joints[j]));
            const float separation = ours.world->jointSeparation(ours.joints[j]);
            ASSERT_TRUE(std::isfinite(separation));
            oursMax = std::max(oursMax, separation);
            const b2Vec2 d = theirs.joints[j]->GetAnchorB() - theirs.joints[j]->GetAnchorA();
            theirsMax = std::max(theirsMax, d.Length());
        }
        EXPECT_TRUE(ours.world->jointLetGoEvents().empty());
    }
    // Both far beyond the 10 m at which the chain used to be cut (44 m and 50 m on x86-64 with
    // GCC 12; the runs part at the first contact, below).
    EXPECT_GT(oursMax, 20.0f);
    EXPECT_GT(theirsMax, 20.0f);
}

TEST(MassRatioAgainstBox2d, IdenticalUntilTheFirstContact) {
#if defined(__x86_64__)
    // Bit for bit while only joints act. At step 130 a link first touches the ball; pivot2d's
    // broad phase keeps a different set of box-overlap pairs from Box2D's (it shrinks stale
    // boxes by its own rule), so the contacts are listed in another order and the chaotic runs
    // part (docs/reference-agreement.md).
    TrajectoryDifference d = compareTrajectories(kMassRatio, fullNgs(), kSteps);
    EXPECT_GE(d.identicalSteps, 129);
#else
    GTEST_SKIP() << "exactness is claimed for x86-64 builds only";
#endif
}

// Letting go beyond a distance is opt-in, per world or per joint, and reported.
TEST(MassRatioAgainstBox2d, ALetGoSeparationCutsTheChainAndSaysSo) {
    scenes::SceneOptions options = fullNgs();
    scenes::Scene ours = buildPivotCase(kMassRatio, options);
    World& world = *ours.world;
    for (JointId j : ours.joints) world.setJointLetGoSeparation(j, 10.0f);
    int letGo = 0;
    for (int s = 0; s < kSteps; ++s) {
        world.step(kDt, 8, 3);
        const std::vector<JointLetGoEvent> events = world.jointLetGoEvents();
        ASSERT_EQ(static_cast<int>(events.size()), world.lastStepStats().letGoJointCount);
        for (const JointLetGoEvent& e : events) {
            EXPECT_EQ(e.reason, JointLetGoReason::Separation);
            EXPECT_GT(e.separation, 10.0f);
            EXPECT_TRUE(world.isJointLetGo(e.joint));
        }
        letGo += static_cast<int>(events.size());
    }
    EXPECT_GE(letGo, 1);
}
