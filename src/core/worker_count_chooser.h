// Chooses, step by step, whether a world steps on all of its pool's workers or on the caller
// alone. Both give the same bits (docs/architecture.md, "Threads"), so the choice is one of
// speed only, and only timing can make it: on an idle machine the whole team is faster on every
// big scene, but while another process keeps a core busy, a member that loses its core in the
// middle of a block holds the others until it gets the core back, and the caller alone can be
// faster (the waits themselves tell nothing: they are as frequent on an idle machine,
// docs/performance.md).
//
// So the chooser asks the clock. Every so often it probes the other count: it times a run of
// kRun steps on the current count, then alternates runs on the other count and on the current
// one, and compares the two counts' mean run. Interleaving cancels a cost that rises or falls
// steadily (a pile growing, bodies falling asleep), but not a jump: when a current run costs
// kUnsteady times the one before the probe run between them (or a kUnsteady-th of it), the probe
// decides nothing and the next one comes after the same interval. (`smash`: a heavy box hits a
// wall of sleeping bricks and the step grows fivefold in six steps; a probe of the caller alone
// made just then looked twice as fast as the team around it, and kept the caller alone
// through the next 64 steps, which the team would have solved 20% faster.) A clear difference
// decides after one probe run; a close one takes up to kMaxProbeRuns, for a step's time varies by
// tens of percent when a worker loses its core for a few milliseconds, and a close call costs
// little while it is being made. A first probe step that alone costs kClearLoss times the current
// count's mean ends the probe at once (one worker on a scene that two solve twice as fast). A
// close call that stays close is a tie, and a tie goes to the caller alone: a team that buys
// less than kMargin is not worth the core it takes from the rest of the program (beside a busy
// core, `smash` and `large_pyramid` were such ties, and kept the team).
//
// A probe that loses puts the next one twice as far away, up to kMaxInterval steps: a machine
// whose best count does not change pays little for being asked, and one that changes (the other
// process ends) is noticed within kMaxInterval steps. A switch brings the next probe back to
// kMinInterval, so that a switch made on a noisy probe is soon undone.
#pragma once

#include <algorithm>

namespace pivot {

class WorkerCountChooser {
public:
    /// For a pool of `workers` (the caller included); with one there is nothing to choose.
    explicit WorkerCountChooser(int workers) : all_(workers), current_(workers) {}

    /// Workers the coming step should run on: all of them, or 1.
    int next() const { return phase_ == Phase::Probe ? other() : current_; }

    /// The duration of the step just taken on next()'s count, in any unit (the same each time).
    void record(double duration) {
        if (all_ == 1) return;
        ++stepsInPhase_;
        switch (phase_) {
            case Phase::Settled:
                if (stepsInPhase_ >= interval_) enter(Phase::Current);
                break;
            case Phase::Current:
                currentTime_ += duration;
                runTime_ += duration;
                if (stepsInPhase_ < kRun) break;
                ++currentRuns_;
                if (probeRuns_ == 0) {
                    lastCurrentRun_ = runTime_;
                    enter(Phase::Probe);
                } else if (runTime_ > kUnsteady * lastCurrentRun_ ||
                           lastCurrentRun_ > kUnsteady * runTime_) {
                    settleUndecided();
                } else {
                    lastCurrentRun_ = runTime_;
                    judge();
                }
                break;
            case Phase::Probe:
                probeTime_ += duration;
                if (probeRuns_ == 0 && stepsInPhase_ == 1 &&
                    duration > kClearLoss * currentTime_ / (currentRuns_ * kRun)) {
                    settle(false);
                    break;
                }
                if (stepsInPhase_ < kRun) break;
                ++probeRuns_;
                enter(Phase::Current);
                break;
        }
    }

    /// Probes decided so far, the switches they led to, and probes left undecided because the
    /// cost jumped (for tests).
    int probes() const { return probes_; }
    int switches() const { return switches_; }
    int undecided() const { return undecided_; }

    /// Steps in a run: a probe's runs, and the current count's runs around them.
    static constexpr int kRun = 3;
    static constexpr int kMaxProbeRuns = 4;
    static constexpr int kMinInterval = 64;
    static constexpr int kMaxInterval = 1024;
    /// After the last probe run, two counts within this fraction of each other are a tie, and a
    /// tie goes to the caller alone: the whole team must earn the cores it takes.
    static constexpr double kMargin = 0.03;
    static constexpr double kClearLoss = 1.5;
    static constexpr double kUnsteady = 1.5;

private:
    enum class Phase { Settled, Current, Probe };

    int other() const { return current_ == all_ ? 1 : all_; }

    void enter(Phase phase) {
        phase_ = phase;
        stepsInPhase_ = 0;
        runTime_ = 0.0;
    }

    // After each run on the current count that follows a probe run: decide, or probe once more.
    void judge() {
        const double ratio = (probeTime_ / probeRuns_) / (currentTime_ / currentRuns_);
        // How far from a tie the ratio must be to decide after this many probe runs.
        static constexpr double kBand[kMaxProbeRuns] = {0.25, 0.12, 0.06, kMargin};
        const double band = kBand[probeRuns_ - 1];
        if (ratio < 1.0 - band) {
            settle(true);
        } else if (ratio > 1.0 + band) {
            settle(false);
        } else if (probeRuns_ == kMaxProbeRuns) {
            // A tie: the caller alone, whichever count is current.
            settle(other() == 1);
        } else {
            enter(Phase::Probe);
        }
    }

    // The cost jumped during the probe: no verdict, and the next probe after the same interval.
    void settleUndecided() {
        ++undecided_;
        endProbe();
    }

    void settle(bool probeWon) {
        ++probes_;
        if (probeWon) {
            current_ = other();
            ++switches_;
            interval_ = kMinInterval;
        } else {
            interval_ = std::min(2 * interval_, kMaxInterval);
        }
        endProbe();
    }

    void endProbe() {
        currentTime_ = probeTime_ = 0.0;
        currentRuns_ = probeRuns_ = 0;
        enter(Phase::Settled);
    }

    int all_;
    int current_;
    Phase phase_ = Phase::Settled;
    int stepsInPhase_ = 0;
    int interval_ = kMinInterval;
    double currentTime_ = 0.0;  // the runs on the current count since the probe began
    double probeTime_ = 0.0;
    int currentRuns_ = 0;
    int probeRuns_ = 0;
    double runTime_ = 0.0;         // the run under way
    double lastCurrentRun_ = 0.0;  // the last whole run on the current count
    int probes_ = 0;
    int switches_ = 0;
    int undecided_ = 0;
};

}  // namespace pivot
