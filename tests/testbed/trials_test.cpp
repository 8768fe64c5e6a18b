// The report's method: perturbed trials and the statistics taken over them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report/pareto_study.h"
#include "report/trials.h"
#include "scenes/metrics.h"
#include "scenes/perturbation.h"
#include "scenes/scene.h"

using namespace pivot;
using pivot::report::medianMetrics;
using pivot::report::spreadOf;
using scenes::RunMetrics;

TEST(Trials, TheMedianOfAnOddCountIsOneOfTheValuesAndTheRangeItsEnds) {
    const report::Spread s = spreadOf({40.5, 0.1, 45.2, 0.103, 44.0});
    EXPECT_EQ(s.median, 40.5);
    EXPECT_EQ(s.low, 0.1);
    EXPECT_EQ(s.high, 45.2);
    // Even counts take the lower middle value: still a value a run produced, never the mean of
    // a torn run and a held one.
    EXPECT_EQ(spreadOf({0.1, 40.0}).median, 0.1);
    EXPECT_EQ(spreadOf({NAN, 1.0, 2.0}).median, 2.0);  // NaN sorts last
    EXPECT_TRUE(std::isnan(spreadOf({NAN, 1.0, 2.0}).high));
}

TEST(Trials, MedianMetricsCountANeverRecoveryAsTheLongest) {
    std::vector<RunMetrics> trials(3);
    trials[0].recoverySeconds = 1.0;
    trials[1].recoverySeconds = RunMetrics::kNever;
    trials[2].recoverySeconds = RunMetrics::kNever;
    trials[0].blewUp = true;
    trials[0].energyStart = 10.0;
    trials[0].energyEnd = 15.0;  // +5
    trials[1].energyStart = 0.0;
    trials[1].energyEnd = -1.0;  // -1
    trials[2].energyStart = 100.0;
    trials[2].energyEnd = 102.0;  // +2
    const RunMetrics m = medianMetrics(trials);
    EXPECT_EQ(m.recoverySeconds, RunMetrics::kNever);
    EXPECT_FALSE(m.blewUp);                  // one of three
    EXPECT_DOUBLE_EQ(m.energyDrift(), 2.0);  // the drifts' median, not a difference of medians
    trials[1].recoverySeconds = 3.0;
    EXPECT_EQ(medianMetrics(trials).recoverySeconds, 3.0);
}

TEST(Trials, ARunIsTornWhenItEndsApartOrBlowsUp) {
    RunMetrics m;
    m.maxSeparation = 30.0;  // apart once, back together by the end: held
    m.settledSeparation = 0.01;
    EXPECT_FALSE(m.torn());
    m.settledSeparation = 2.0 * scenes::kTornSeparation;
    EXPECT_TRUE(m.torn());
    m.settledSeparation = NAN;
    EXPECT_TRUE(m.torn());
    m.settledSeparation = 0.0;
    m.blewUp = true;
    EXPECT_TRUE(m.torn());
}

TEST(Trials, SeedZeroBuildsTheSceneExactlyAndOtherSeedsPerturbIt) {
    const scenes::SceneInfo& info = *scenes::findScene("double_pendulum");
    auto hashAfter = [&](std::uint32_t seed) {
        scenes::SceneOptions options;
        options.perturbation = seed;
        scenes::Scene scene = scenes::buildScene(info, options);
        for (int i = 0; i < 60; ++i) scene.world->step(1.0f / 60.0f);
        return scene.world->stateHash();
    };
    scenes::Scene plain = scenes::buildScene(info, {});
    for (int i = 0; i < 60; ++i) plain.world->step(1.0f / 60.0f);
    EXPECT_EQ(hashAfter(0), plain.world->stateHash());
    EXPECT_NE(hashAfter(1), hashAfter(0));
    EXPECT_NE(hashAfter(2), hashAfter(1));
    EXPECT_EQ(hashAfter(2), hashAfter(2));  // a seed is a run, repeatable bit for bit

    // Gravity moves by about kPerturbation, never more.
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        const Vec2 g = scenes::perturbedGravity({0.0f, -10.0f}, seed);
        EXPECT_NEAR(length(g), 10.0f, 10.0f * scenes::kPerturbation * 1.01f);
        EXPECT_LE(std::fabs(g.x), 10.0f * scenes::kPerturbation * 1.01f);
    }
}

TEST(Trials, JobsRunEveryIndexOnceOnAnyNumberOfThreads) {
    for (int threads : {1, 2, 4}) {
        std::vector<int> ran(100, 0);
        report::runJobs(ran.size(), threads, [&](std::size_t i) { ++ran[i]; });
        EXPECT_EQ(std::count(ran.begin(), ran.end(), 1), 100) << threads;
    }
    EXPECT_THROW(report::runJobs(10, 2,
                                 [](std::size_t i) {
                                     if (i == 7) throw std::runtime_error("job 7");
                                 }),
                 std::runtime_error);
}

// A configuration is on the front when nothing cheaper has a smaller median error; a tie in cost
// keeps the smaller error, and a NaN error never enters.
TEST(ParetoFront, KeepsWhatNothingCheaperBeats) {
    auto run = [](int substeps, double error) {
        report::ParetoRun r;
        r.substeps = substeps;
        r.velocityIterations = 1;
        r.positionIterations = 0;
        r.median.maxSeparation = error;
        return r;
    };
    const std::vector<report::ParetoRun> runs = {run(4, 0.5), run(1, 1.0), run(2, 2.0),
                                                 run(2, 0.8), run(8, NAN), run(16, 0.1),
                                                 run(8, 0.5)};
    std::vector<const report::ParetoRun*> all;
    for (const report::ParetoRun& r : runs) all.push_back(&r);
    const auto front =
        report::paretoFront(all, [](const report::ParetoRun& r) { return double(r.sweeps()); });
    ASSERT_EQ(front.size(), 4u);
    EXPECT_EQ(front[0]->sweeps(), 1);
    EXPECT_EQ(front[1]->median.maxSeparation, 0.8);
    EXPECT_EQ(front[2]->sweeps(), 4);
    EXPECT_EQ(front[3]->sweeps(), 16);
}
