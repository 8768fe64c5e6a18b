#include "report/trials.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "report/page_text.h"

namespace pivot::report {

namespace {

// NaN last, so that a run that produced one is never taken for a small value.
bool lessNanLast(double a, double b) {
    if (std::isnan(a)) return false;
    if (std::isnan(b)) return true;
    return a < b;
}

double medianOf(std::vector<double> values) {
    return spreadOf(std::move(values)).median;
}

template <typename Field>
double medianField(const std::vector<scenes::RunMetrics>& trials, Field field) {
    std::vector<double> values;
    for (const scenes::RunMetrics& m : trials) values.push_back(static_cast<double>(m.*field));
    return medianOf(values);
}

}  // namespace

std::string Spread::text(const char* unit) const {
    // A range that prints as one value is one value at the precision shown.
    if (g3(low) == g3(high)) return g3(median) + unit;
    return g3(median) + unit + " [" + g3(low) + "-" + g3(high) + "]";
}

Spread spreadOf(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end(), lessNanLast);
    const std::size_t n = values.size();
    // The lower median for an even count: still a value a run produced.
    return {values[(n - 1) / 2], values.front(), values.back()};
}

Spread spreadOf(const std::vector<scenes::RunMetrics>& trials,
                double (*metric)(const scenes::RunMetrics&)) {
    std::vector<double> values;
    for (const scenes::RunMetrics& m : trials) values.push_back(metric(m));
    return spreadOf(std::move(values));
}

scenes::RunMetrics medianMetrics(const std::vector<scenes::RunMetrics>& trials) {
    using M = scenes::RunMetrics;
    M m;
    if (trials.empty()) return m;
    m.steps = static_cast<int>(medianField(trials, &M::steps));
    m.maxSeparation = medianField(trials, &M::maxSeparation);
    m.rmsSeparation = medianField(trials, &M::rmsSeparation);
    m.finalSeparation = medianField(trials, &M::finalSeparation);
    m.settledSeparation = medianField(trials, &M::settledSeparation);
    m.energyStart = medianField(trials, &M::energyStart);
    // The drift's median, not the difference of two medians.
    m.energyEnd =
        m.energyStart + spreadOf(trials, [](const M& t) { return t.energyDrift(); }).median;
    m.translationClamps = static_cast<long>(medianField(trials, &M::translationClamps));
    m.rotationClamps = static_cast<long>(medianField(trials, &M::rotationClamps));
    m.meanPositionIterations = medianField(trials, &M::meanPositionIterations);
    m.meanExtraPositionSolves = medianField(trials, &M::meanExtraPositionSolves);
    m.microsecondsPerStep = medianField(trials, &M::microsecondsPerStep);
    m.maxLimitViolation = medianField(trials, &M::maxLimitViolation);
    m.jitter = medianField(trials, &M::jitter);  // kNotApplicable in all or none of them
    m.maxPenetration = medianField(trials, &M::maxPenetration);
    m.settledPenetration = medianField(trials, &M::settledPenetration);
    m.maxSpeed = medianField(trials, &M::maxSpeed);
    m.heightLost = medianField(trials, &M::heightLost);
    // A recovery that never came is the longest; a scene without a disturbance has none at all.
    std::vector<double> recovery;
    for (const M& t : trials) {
        recovery.push_back(t.recoverySeconds == M::kNever ? HUGE_VAL : t.recoverySeconds);
    }
    m.recoverySeconds = medianOf(recovery);
    if (m.recoverySeconds == HUGE_VAL) m.recoverySeconds = M::kNever;
    int blown = 0;
    for (const M& t : trials) blown += t.blewUp ? 1 : 0;
    m.blewUp = 2 * blown > static_cast<int>(trials.size());
    return m;
}

int tornCount(const std::vector<scenes::RunMetrics>& trials) {
    int torn = 0;
    for (const scenes::RunMetrics& m : trials) torn += m.torn() ? 1 : 0;
    return torn;
}

std::vector<scenes::RunMetrics> runTrials(const scenes::SceneInfo& info,
                                          const scenes::SceneOptions& options,
                                          const scenes::RunSettings& settings, int threads,
                                          const std::function<void(scenes::Scene&)>& adjust) {
    std::vector<scenes::RunMetrics> trials(kTrials);
    runJobs(kTrials, threads, [&](std::size_t trial) {
        scenes::SceneOptions perturbed = options;
        perturbed.perturbation = trialSeed(static_cast<int>(trial));
        scenes::Scene scene = scenes::buildScene(info, perturbed);
        if (adjust) adjust(scene);
        trials[trial] = scenes::runScene(scene, settings);
    });
    return trials;
}

void runJobs(std::size_t count, int threads, const std::function<void(std::size_t)>& job) {
    if (threads <= 1 || count <= 1) {
        for (std::size_t i = 0; i < count; ++i) job(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto work = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                job(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace pivot::report
