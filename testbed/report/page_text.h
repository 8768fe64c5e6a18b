// What the report's pages share: numbers printed with a printf spec, the line naming the machine
// and the day, and writing a page or figure to disk.
#pragma once

#include <filesystem>
#include <string>

namespace pivot::report {

/// `v` printed with `spec` ("%.3g", "%.2e").
std::string num(const char* spec, double v);
/// `v` to three significant figures.
inline std::string g3(double v) {
    return num("%.3g", v);
}

/// The processor's model and its hardware threads ("unknown CPU" where /proc/cpuinfo is not).
std::string machineName();
/// Today's date, UTC, as YYYY-MM-DD.
std::string todayUtc();

/// Writes `text` to `path`; false, with `problem` saying why, when it cannot.
bool writeFile(const std::filesystem::path& path, const std::string& text, std::string& problem);
/// The file's bytes ("" when it cannot be read).
std::string readFile(const std::filesystem::path& path);

}  // namespace pivot::report
