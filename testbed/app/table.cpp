#include "app/table.h"

#include <cstdio>

namespace pivot::testbed {

namespace {

std::string blowUpText(const scenes::RunMetrics& m) {
    return m.blewUp ? "yes@" + std::to_string(m.steps) : "no";
}

std::string format(const char* spec, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, spec, value);
    return buffer;
}

// "-" when a metric does not apply to the scene, "never" when a recovery did not happen.
std::string optional(const char* spec, double value) {
    if (value == scenes::RunMetrics::kNotApplicable) return "-";
    if (value == scenes::RunMetrics::kNever) return "never";
    return format(spec, value);
}

}  // namespace

void printTable(std::ostream& out, const std::vector<TableRow>& rows) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-17s %-15s %-9s %4s %9s %9s %9s %10s %9s %8s %9s %7s %6s %6s %5s %8s\n",
                  "scene", "solver", "contact", "bias", "max sep", "rms sep", "final sep",
                  "drift J", "limit rad", "recover", "jitter", "blew up", "t clmp", "r clmp", "ngs",
                  "us/step");
    out << line;
    for (const TableRow& r : rows) {
        const scenes::RunMetrics& m = r.metrics;
        std::snprintf(
            line, sizeof line,
            "%-17s %-15s %-9s %4.2f %9.2e %9.2e %9.2e %10.4g %9.2e %8s %9s %7s %6ld "
            "%6ld %5.2f %8.1f\n",
            r.scene.c_str(), r.solver.c_str(), r.contact.c_str(), static_cast<double>(r.bias),
            m.maxSeparation, m.rmsSeparation, m.finalSeparation, m.energyDrift(),
            m.maxLimitViolation, optional("%.2fs", m.recoverySeconds).c_str(),
            optional("%.2e", m.jitter).c_str(), blowUpText(m).c_str(), m.translationClamps,
            m.rotationClamps, m.meanPositionIterations, m.microsecondsPerStep);
        out << line;
    }
}

void writeCsv(std::ostream& out, const std::vector<TableRow>& rows) {
    out << "scene,solver,contact,bias,steps,max_sep_m,rms_sep_m,final_sep_m,energy_start_j,energy_"
           "end_j,"
           "energy_drift_j,blew_up,translation_clamps,rotation_clamps,ngs_iterations_per_step,"
           "us_per_step\n";
    for (const TableRow& r : rows) {
        const scenes::RunMetrics& m = r.metrics;
        out << r.scene << ',' << r.solver << ',' << r.contact << ',' << format("%.3g", r.bias)
            << ',' << m.steps << ',' << format("%.6e", m.maxSeparation) << ','
            << format("%.6e", m.rmsSeparation) << ',' << format("%.6e", m.finalSeparation) << ','
            << format("%.9g", m.energyStart) << ',' << format("%.9g", m.energyEnd) << ','
            << format("%.9g", m.energyDrift()) << ',' << (m.blewUp ? 1 : 0) << ','
            << m.translationClamps << ',' << m.rotationClamps << ','
            << format("%.4f", m.meanPositionIterations) << ','
            << format("%.3f", m.microsecondsPerStep) << '\n';
    }
}

}  // namespace pivot::testbed
