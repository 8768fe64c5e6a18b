#include "report/raw_runs.h"

#include <sstream>

#include "report/page_text.h"
#include "report/trials.h"

namespace pivot::report {

const char* contactCorrectionName(ContactCorrection contacts) {
    switch (contacts) {
        case ContactCorrection::NGS: return "ngs";
        case ContactCorrection::Baumgarte: return "baumgarte";
        case ContactCorrection::Soft: return "soft";
    }
    return "invalid";
}

void RawRuns::add(const RunConfig& config, const std::vector<scenes::RunMetrics>& trials) {
    std::ostringstream out;
    // Quoted: setup names hold commas ("FullNGS 2/1, key +2").
    const std::string prefix =
        config.scene + ",\"" + config.setup + "\"," + config.solver + ',' +
        contactCorrectionName(config.contacts) + ',' +
        (config.bias < 0.0f ? std::string("default") : num("%g", config.bias)) + ',' +
        std::to_string(config.substeps) + ',' + std::to_string(config.velocityIterations) + ',' +
        std::to_string(config.positionIterations) + ',';
    for (std::size_t t = 0; t < trials.size(); ++t) {
        const scenes::RunMetrics& m = trials[t];
        out << prefix << trialSeed(static_cast<int>(t)) << ',' << m.steps << ','
            << (m.torn() ? 1 : 0) << ',' << (m.blewUp ? 1 : 0) << ','
            << num("%.6g", m.maxSeparation) << ',' << num("%.6g", m.settledSeparation) << ','
            << num("%.6g", m.rmsSeparation) << ',' << num("%.6g", m.maxSideSeparation) << ','
            << num("%.6g", m.energyDrift()) << ',' << m.clampedBodySteps() << ','
            << num("%.4g", m.meanPositionIterations) << ','
            << num("%.4g", m.meanExtraPositionSolves) << ',' << num("%.6g", m.maxLimitViolation)
            << ',' << num("%.6g", m.recoverySeconds) << ',' << num("%.6g", m.jitter) << ','
            << num("%.6g", m.maxPenetration) << ',' << num("%.6g", m.settledPenetration) << ','
            << num("%.6g", m.maxSpeed) << ',' << num("%.6g", m.heightLost) << ','
            << num("%.2f", m.microsecondsPerStep) << '\n';
    }
    rows_ += out.str();
}

std::string RawRuns::csv() const {
    return std::string(
               "scene,setup,solver,contacts,bias,substeps,velocity_iterations,"
               "position_iterations,seed,steps,torn,blew_up,max_separation_m,"
               "settled_separation_m,rms_separation_m,others_max_separation_m,energy_drift_j,"
               "clamped_body_steps,ngs_iterations_per_step,extra_solves_per_step,"
               "limit_violation_rad,recovery_s,jitter_m_s,max_penetration_m,"
               "settled_penetration_m,max_speed_m_s,height_lost_m,") +
           kTimingColumn + "\n" + rows_;
}

}  // namespace pivot::report
