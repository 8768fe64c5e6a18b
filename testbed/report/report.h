// `pivot-testbed report`: runs every scene with every position solver (and the bias and
// iteration sweeps), and writes docs/results.md with its tables and SVG figures under
// docs/results/, and the measured observations into docs/position-correction.md (between the
// markers kObservationsBegin and kObservationsEnd; the prose around them is left alone).
#pragma once

#include <ostream>
#include <string>

namespace pivot::report {

constexpr const char* kObservationsBegin = "<!-- observations:begin (generated) -->";
constexpr const char* kObservationsEnd = "<!-- observations:end -->";

struct ReportSettings {
    std::string docsDir = "docs";  ///< where results.md and results/ go
    int steps = 600;
    /// Threads running the trials. Timings taken with more than one share the machine: the
    /// committed report's are from one.
    int threads = 1;
    /// Also rewrite the observations block of <docsDir>/position-correction.md.
    bool updatePositionCorrection = true;
};

/// Returns an empty string, or what went wrong. Progress lines go to `log`.
std::string generateReport(const ReportSettings& settings, std::ostream& log);

}  // namespace pivot::report
