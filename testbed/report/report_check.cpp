#include "report/report_check.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "report/raw_runs.h"
#include "report/report.h"

namespace pivot::report {

namespace fs = std::filesystem;

namespace {

const char kMask[] = "<timing>";

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> tableCells(const std::string& row) {
    std::vector<std::string> cells;
    std::size_t start = row.find('|');
    while (start != std::string::npos) {
        const std::size_t end = row.find('|', start + 1);
        if (end == std::string::npos) break;
        cells.push_back(row.substr(start + 1, end - start - 1));
        start = end;
    }
    return cells;
}

std::string joinCells(const std::vector<std::string>& cells) {
    std::string row = "|";
    for (const std::string& cell : cells) row += cell + "|";
    return row;
}

bool hasDigit(const std::string& text) {
    return text.find_first_of("0123456789") != std::string::npos;
}

// Numbers with the unit "us" (microseconds), and how long the page took to generate.
std::string maskMicroseconds(const std::string& line) {
    static const std::regex timing(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)? us\b)");
    static const std::regex took(R"(took [0-9.]+ s\b)");
    return std::regex_replace(std::regex_replace(line, timing, std::string(kMask) + " us"), took,
                              std::string("took ") + kMask + " s");
}

}  // namespace

std::string maskTimings(const std::string& text) {
    std::vector<std::string> lines = splitLines(text);
    std::vector<std::size_t> timingColumns;  // of the markdown table being read
    int verdictColumn = -1;
    bool timedObservation = false;  // an observation block whose result is all timings
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string line = maskMicroseconds(lines[i]);
        if (line.find("this run: ") != std::string::npos) {
            line = line.substr(0, line.find("this run: ")) + "this run: " + kMask;
        }
        if (line.rfind("|", 0) == 0) {
            std::vector<std::string> cells = tableCells(line);
            const bool header = i + 1 < lines.size() && lines[i + 1].rfind("| ---", 0) == 0;
            if (header) {
                timingColumns.clear();
                verdictColumn = -1;
                for (std::size_t c = 0; c < cells.size(); ++c) {
                    if (cells[c].find("us/step") != std::string::npos) timingColumns.push_back(c);
                    if (cells[c] == " verdict ") verdictColumn = static_cast<int>(c);
                }
            } else if (cells.size() > 1) {
                for (std::size_t c : timingColumns) {
                    if (c < cells.size()) cells[c] = kMask;
                }
                // A verdict drawn from timings alone: its result has no other number.
                if (verdictColumn > 0) {
                    const std::string& result = cells[static_cast<std::size_t>(verdictColumn - 1)];
                    std::string rest = result;
                    for (std::size_t at; (at = rest.find(kMask)) != std::string::npos;) {
                        rest.erase(at, sizeof kMask - 1);
                    }
                    if (result.find(kMask) != std::string::npos && !hasDigit(rest)) {
                        cells[static_cast<std::size_t>(verdictColumn)] = kMask;
                    }
                }
                line = joinCells(cells);
            }
        } else {
            timingColumns.clear();
            verdictColumn = -1;
        }
        if (line.rfind("### ", 0) == 0) timedObservation = false;
        if (line.rfind("- Result: ", 0) == 0) {
            std::string rest = line.substr(10);
            for (std::size_t at; (at = rest.find(kMask)) != std::string::npos;) {
                rest.erase(at, sizeof kMask - 1);
            }
            timedObservation = line.find(kMask) != std::string::npos && !hasDigit(rest);
        }
        if (timedObservation && line.rfind("- Verdict: ", 0) == 0) {
            line = std::string("- Verdict: ") + kMask;
        }
        out += line + "\n";
    }
    return out;
}

std::string maskCsvTimings(const std::string& text) {
    const std::vector<std::string> lines = splitLines(text);
    if (lines.empty()) return text;
    const std::string& header = lines.front();
    const std::string timing = RawRuns::kTimingColumn;
    // Only a last column can be masked without parsing the quoted fields before it.
    const bool timed = header.size() >= timing.size() &&
                       header.compare(header.size() - timing.size(), timing.size(), timing) == 0;
    std::string out;
    for (const std::string& line : lines) {
        out += timed && &line != &header ? line.substr(0, line.rfind(',') + 1) + kMask : line;
        out += "\n";
    }
    return out;
}

namespace {

bool readFile(const fs::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return true;
}

// The first differing lines of two masked texts, or nothing.
std::string firstDifferences(const std::string& committed, const std::string& regenerated) {
    const std::vector<std::string> a = splitLines(committed), b = splitLines(regenerated);
    std::string out;
    int shown = 0;
    for (std::size_t i = 0; i < std::max(a.size(), b.size()) && shown < 4; ++i) {
        const std::string x = i < a.size() ? a[i] : "(no line)";
        const std::string y = i < b.size() ? b[i] : "(no line)";
        if (x == y) continue;
        out += "  line " + std::to_string(i + 1) + "\n    committed:   " + x.substr(0, 300) +
               "\n    regenerated: " + y.substr(0, 300) + "\n";
        ++shown;
    }
    return out;
}

}  // namespace

std::string checkReport(const std::string& docsDir, int steps, int threads, std::ostream& log) {
    const fs::path docs(docsDir);
    const fs::path scratch =
        fs::temp_directory_path() / ("pivot-report-check-" + std::to_string(::getpid()));
    std::error_code ignored;
    fs::remove_all(scratch, ignored);
    fs::create_directories(scratch);
    // The observations are written into position-correction.md's generated block: start from
    // the committed page so that the prose around it is the same.
    fs::copy_file(docs / "position-correction.md", scratch / "position-correction.md");
    ReportSettings settings;
    settings.docsDir = scratch.string();
    settings.steps = steps;
    settings.threads =
        threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    std::ostringstream quiet;
    const std::string problem = generateReport(settings, quiet);
    if (!problem.empty()) return problem;

    std::vector<fs::path> files = {"results.md", "position-correction.md"};
    std::vector<std::string> stale;
    for (const auto& entry : fs::directory_iterator(docs / "results")) {
        const std::string name = entry.path().filename().string();
        // `pivot-testbed study` makes these; its own check compares them.
        if (name.rfind("pareto-", 0) == 0) continue;
        if (!fs::exists(scratch / "results" / name)) stale.push_back(name);
    }
    for (const auto& entry : fs::directory_iterator(scratch / "results")) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("cost-", 0) == 0) continue;  // x axis: microseconds per step
        files.push_back(fs::path("results") / name);
    }
    std::string report;
    for (const std::string& name : stale) {
        report += "docs/results/" + name + " is not made by the report any more\n";
    }
    for (const fs::path& file : files) {
        std::string committed, regenerated;
        if (!readFile(docs / file, committed)) {
            report += (docs / file).string() + " is missing\n";
            continue;
        }
        readFile(scratch / file, regenerated);
        const bool csv = file.extension() == ".csv";
        const std::string differences =
            csv ? firstDifferences(maskCsvTimings(committed), maskCsvTimings(regenerated))
                : firstDifferences(maskTimings(committed), maskTimings(regenerated));
        if (!differences.empty()) {
            report += (docs / file).string() + " differs from a fresh report:\n" + differences;
        }
    }
    log << "compared " << files.size() << " files of the report (timings masked) with "
        << docs.string() << "\n";
    fs::remove_all(scratch, ignored);
    return report;
}

}  // namespace pivot::report
