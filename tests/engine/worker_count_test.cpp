// Choosing the worker count step by step (src/core/worker_count_chooser.h, WorldDef::
// adaptWorkerCount): the chooser's decisions on made-up step times, and a world that changes its
// count between steps stepping to the same bits as a world on one worker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/worker_count_chooser.h"
#include "pivot/pivot.h"
#include "scenes/parts.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

// Steps the chooser `steps` times, each step taking cost(count) for the count it asked for;
// returns the counts asked for, step by step.
template <typename Cost>
std::vector<int> drive(WorkerCountChooser& chooser, int steps, Cost&& cost) {
    std::vector<int> counts;
    for (int i = 0; i < steps; ++i) {
        const int count = chooser.next();
        counts.push_back(count);
        chooser.record(cost(count, i));
    }
    return counts;
}

int stepsOn(const std::vector<int>& counts, int count) {
    int n = 0;
    for (int c : counts) n += c == count ? 1 : 0;
    return n;
}

constexpr int kRun = WorkerCountChooser::kRun;
constexpr int kMin = WorkerCountChooser::kMinInterval;

}  // namespace

TEST(WorkerCountChooser, KeepsEveryWorkerWhileTheyAreFasterAndAsksLessAndLessOften) {
    WorkerCountChooser chooser(2);
    const std::vector<int> counts =
        drive(chooser, 4000, [](int count, int) { return count == 2 ? 1.0 : 1.8; });
    EXPECT_EQ(chooser.switches(), 0);
    // The first probe follows kMin settled steps and a run timed on two workers; its first step
    // on one worker costs more than kClearLoss times theirs, and ends it.
    for (int i = 0; i < kMin + kRun; ++i) ASSERT_EQ(counts[i], 2) << i;
    EXPECT_EQ(counts[kMin + kRun], 1);
    EXPECT_EQ(counts[kMin + kRun + 1], 2);
    // Each lost probe doubles the interval: 64, 128, 256, 512, 1024, 1024 ... settled steps
    // (plus the probe's 4) fit 6 probes in 4,000 steps; probing every 64 would be 58.
    EXPECT_EQ(chooser.probes(), 6);
    EXPECT_EQ(stepsOn(counts, 1), 6);
}

TEST(WorkerCountChooser, TakesMoreRunsToDecideACloserCall) {
    // One worker 20% slower: not clear after one probe run (within 25%), clear after two.
    WorkerCountChooser chooser(2);
    const std::vector<int> counts =
        drive(chooser, kMin + 5 * kRun, [](int count, int) { return count == 2 ? 1.0 : 1.2; });
    EXPECT_EQ(chooser.probes(), 1);
    EXPECT_EQ(chooser.switches(), 0);
    EXPECT_EQ(stepsOn(counts, 1), 2 * kRun);
}

TEST(WorkerCountChooser, ChangesToTheCallerAloneWhenItIsFasterAndStaysThere) {
    WorkerCountChooser chooser(2);
    const std::vector<int> counts =
        drive(chooser, 2000, [](int count, int) { return count == 2 ? 1.10 : 1.0; });
    EXPECT_EQ(chooser.switches(), 1);
    // 10% is decided after three probe runs, each followed by a run on two workers; then every
    // step runs on one worker but the probes of two.
    const int switched = kMin + 7 * kRun;
    EXPECT_EQ(counts[switched - 1], 2);
    for (int i = switched; i < switched + kMin; ++i) ASSERT_EQ(counts[i], 1) << i;
    EXPECT_GT(stepsOn(counts, 1), 1850);
}

TEST(WorkerCountChooser, ChangesBackWhenTheWholeTeamIsFasterAgain) {
    // A busy machine for 1,000 steps (two workers 10% slower), then an idle one (two workers
    // twice as fast): the chooser is back on two within kMaxInterval steps and a probe.
    WorkerCountChooser chooser(2);
    const std::vector<int> counts = drive(chooser, 3000, [](int count, int step) {
        if (step < 1000) return count == 2 ? 1.10 : 1.0;
        return count == 2 ? 0.5 : 1.0;
    });
    // Between steps 500 and 1,000, one worker but for one probe of two: three runs, each 10%
    // slower, so not decided before the third.
    EXPECT_EQ(stepsOn(std::vector<int>(counts.begin() + 500, counts.begin() + 1000), 1),
              500 - 3 * kRun);
    EXPECT_EQ(chooser.switches(), 2);
    const int limit = 1000 + WorkerCountChooser::kMaxInterval + 8 * kRun;
    for (int i = limit; i + 1 < 3000; ++i) {  // reads counts[i + 1]
        // only one-step probes of one worker from here on
        if (counts[i] == 1) {
            ASSERT_EQ(counts[i - 1], 2) << i;
            ASSERT_EQ(counts[i + 1], 2) << i;
        }
    }
}

TEST(WorkerCountChooser, ATieGoesToTheCallerAlone) {
    // Two workers no faster than one (within kMargin): the caller alone, which leaves the other
    // core to the rest of the program, and stays there.
    WorkerCountChooser tie(2);
    const std::vector<int> counts =
        drive(tie, 3000, [](int count, int) { return count == 2 ? 1.0 : 1.01; });
    EXPECT_EQ(tie.switches(), 1);
    EXPECT_GT(stepsOn(counts, 1), 2800);
}

TEST(WorkerCountChooser, ASteadilyRisingCostNeitherHidesNorMakesADifference) {
    // Each step costs more than the last, whichever the count: the probe costs more than the
    // steps before it and less than the steps after, and the two cancel. So a team 10% faster
    // stays, and a tie is still a tie.
    WorkerCountChooser faster(2);
    drive(faster, 3000,
          [](int count, int step) { return (count == 2 ? 1.0 : 1.1) * (1.0 + 0.01 * step); });
    EXPECT_EQ(faster.switches(), 0);
    WorkerCountChooser tie(2);
    const std::vector<int> counts =
        drive(tie, 3000, [](int, int step) { return 1.0 + 0.01 * step; });
    EXPECT_EQ(tie.switches(), 1);
    EXPECT_GT(stepsOn(counts, 1), 2800);
}

TEST(WorkerCountChooser, AProbeDuringAJumpInCostDecidesNothing) {
    // smash's impact: the step grows by 30% a step for 40 steps, then stays; the caller alone
    // is 20% slower throughout. A probe run taken as the climb starts sits between a cheap run
    // and a dear one and looks faster than their mean: it must not switch.
    const auto impact = [](int count, int step) {
        const int climbed = std::min(std::max(step - 67, 0), 40);
        return (count == 1 ? 1.2 : 1.0) * std::pow(1.3, climbed);
    };
    WorkerCountChooser chooser(2);
    const std::vector<int> counts = drive(chooser, 2000, impact);
    EXPECT_EQ(chooser.switches(), 0);
    EXPECT_GE(chooser.undecided(), 1);  // the probe in the climb
    EXPECT_GE(chooser.probes(), 3);     // and those after it, decided
    EXPECT_EQ(counts[70], 2);
}

TEST(WorkerCountChooser, OneWorkerHasNothingToChoose) {
    WorkerCountChooser chooser(1);
    const std::vector<int> counts = drive(chooser, 500, [](int, int) { return 1.0; });
    EXPECT_EQ(stepsOn(counts, 1), 500);
    EXPECT_EQ(chooser.probes(), 0);
}

namespace {

std::unique_ptr<World> pyramidWorld(int workers, bool adapt) {
    WorldDef def = oneSubstepDef();
    def.workerCount = workers;
    def.adaptWorkerCount = adapt;
    auto world = std::make_unique<World>(def);
    BodyDef groundDef;
    const BodyId ground = world->createBody(groundDef);
    world->createShape(ground, ShapeDef{}, Polygon::box(60.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    scenes::PyramidSpec spec;
    spec.rows = 40;  // 820 boxes, 1,600 contacts: a coloured island, solved by a team
    scenes::addPyramid(*world, spec);
    return world;
}

}  // namespace

TEST(WorkerCount, AWorldProbingOneWorkerStepsToTheSameBitsAsOneOnOneWorker) {
    auto one = pyramidWorld(1, true);
    auto two = pyramidWorld(2, true);
    auto fixed = pyramidWorld(2, false);
    std::vector<int> used;
    for (int step = 0; step < 100; ++step) {
        one->step(1.0f / 60.0f);
        two->step(1.0f / 60.0f);
        fixed->step(1.0f / 60.0f);
        used.push_back(two->lastStepStats().workersUsed);
        EXPECT_EQ(one->lastStepStats().workersUsed, 1);
        EXPECT_EQ(fixed->lastStepStats().workersUsed, 2);
        if (step % 10 == 9) {
            ASSERT_EQ(one->stateHash(), two->stateHash()) << step;
            ASSERT_EQ(one->stateHash(), fixed->stateHash()) << step;
        }
    }
    // Whatever the clock says, the first probe's first step runs on one worker, and the steps
    // before it on two.
    for (int i = 0; i < kMin + kRun; ++i) ASSERT_EQ(used[i], 2) << i;
    EXPECT_EQ(used[kMin + kRun], 1);
}
