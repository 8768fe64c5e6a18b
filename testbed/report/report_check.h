// `pivot-testbed report --check`: regenerates the report into a scratch folder and compares it
// with the committed one (docs/results.md, docs/results/*.svg and runs-*.csv, and the
// observations in docs/position-correction.md). Timings differ from run to run and machine to
// machine, so they are masked before comparing: every number with the unit "us", the time the
// page took, the us/step columns, the CSVs' last column (us_per_step), the cost-against-error
// figures (whose x axis is time), the line naming the machine and date, and the verdict of an
// observation measured in time alone. Every other difference, a separation,
// an energy, a verdict, a figure's curve, means the committed report no longer says what the
// code does.
#pragma once

#include <ostream>
#include <string>

namespace pivot::report {

/// The text with its timings masked (see above), for comparing two runs of the report.
std::string maskTimings(const std::string& text);
/// A CSV with its last column masked when the header names it us_per_step.
std::string maskCsvTimings(const std::string& text);

/// Regenerates the report beside `docsDir` and compares. Returns an empty string when they
/// agree, else what differs (the first lines of each differing file); progress goes to `log`.
/// `threads` runs the trials (0: every hardware thread).
std::string checkReport(const std::string& docsDir, int steps, int threads, std::ostream& log);

}  // namespace pivot::report
