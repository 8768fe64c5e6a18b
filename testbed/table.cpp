#include "table.h"

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

}  // namespace

void printTable(std::ostream& out, const std::vector<TableRow>& rows) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-12s %-16s %-9s %5s %10s %10s %10s %12s %9s %9s %9s %8s %9s\n", "scene",
                  "solver", "contact", "bias", "max sep", "rms sep", "final sep", "drift J",
                  "blew up", "t clamps", "r clamps", "ngs its", "us/step");
    out << line;
    for (const TableRow& r : rows) {
        const scenes::RunMetrics& m = r.metrics;
        std::snprintf(line, sizeof line,
                      "%-12s %-16s %-9s %5.2f %10.3e %10.3e %10.3e %12.4g %9s %9ld %9ld %8.2f "
                      "%9.1f\n",
                      r.scene.c_str(), r.solver.c_str(), r.contact.c_str(),
                      static_cast<double>(r.bias), m.maxSeparation, m.rmsSeparation,
                      m.finalSeparation, m.energyDrift(), blowUpText(m).c_str(),
                      m.translationClamps, m.rotationClamps, m.meanPositionIterations,
                      m.microsecondsPerStep);
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
