// The report generator runs, and what it writes is well formed: every SVG parses, every
// Markdown table row has its header's columns, every figure it links exists, no number is
// "nan" or "inf", and the observations block of position-correction.md is filled in.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/report.h"
#include "report/report_check.h"
#include "report/svg.h"

using namespace pivot;
namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

int countColumns(const std::string& row) {
    int bars = 0;
    for (char c : row) bars += c == '|';
    return bars - 1;
}

// Fields of a CSV row; a quoted field may hold commas.
int countCsvFields(const std::string& row) {
    int fields = 1;
    bool quoted = false;
    for (char c : row) {
        if (c == '"') quoted = !quoted;
        fields += c == ',' && !quoted;
    }
    return fields;
}

}  // namespace

TEST(Report, GeneratesWellFormedMarkdownAndSvg) {
    // Per process: two test runs on one machine (two build folders) must not share it.
    const fs::path dir =
        fs::temp_directory_path() / ("pivot-report-test-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream pc(dir / "position-correction.md");
        pc << "# prose before\n\n"
           << report::kObservationsBegin << "\nstale\n"
           << report::kObservationsEnd << "\n\nprose after\n";
    }
    report::ReportSettings settings;
    settings.docsDir = dir.string();
    settings.steps = 60;
    std::ostringstream log;
    ASSERT_EQ(report::generateReport(settings, log), "") << log.str();

    const std::string md = readFile(dir / "results.md");
    ASSERT_FALSE(md.empty());
    EXPECT_NE(md.find("## The seed note's observations"), std::string::npos);
    EXPECT_EQ(md.find("nan"), std::string::npos);
    EXPECT_EQ(md.find("inf |"), std::string::npos);

    // Tables: every row has as many cells as the header above it.
    std::istringstream lines(md);
    std::string line;
    int header = -1, rows = 0, images = 0;
    while (std::getline(lines, line)) {
        if (line.rfind("|", 0) == 0) {
            if (header < 0) header = countColumns(line);
            EXPECT_EQ(countColumns(line), header) << line;
            ++rows;
        } else {
            header = -1;
        }
        std::size_t link = line.find("](results/");
        if (link != std::string::npos) {
            std::string file = line.substr(link + 2, line.find(')', link) - link - 2);
            EXPECT_TRUE(fs::exists(dir / file)) << file;
            ++images;
        }
    }
    EXPECT_GT(rows, 100);
    EXPECT_GT(images, 20);

    int svgs = 0, csvs = 0;
    for (const auto& entry : fs::directory_iterator(dir / "results")) {
        if (entry.path().extension() == ".csv") {
            // Every run's CSV: each row as many fields as the header (quoted fields may hold
            // commas), and every number finite.
            std::istringstream csv(readFile(entry.path()));
            std::string row;
            int fields = -1, count = 0;
            while (std::getline(csv, row)) {
                if (fields < 0) fields = countCsvFields(row);
                EXPECT_EQ(countCsvFields(row), fields) << entry.path() << ": " << row;
                EXPECT_EQ(row.find("nan"), std::string::npos) << entry.path() << ": " << row;
                EXPECT_EQ(row.find("inf"), std::string::npos) << entry.path() << ": " << row;
                ++count;
            }
            EXPECT_GT(count, 1) << entry.path();
            ++csvs;
            continue;
        }
        std::string svg = readFile(entry.path());
        std::string problem;
        EXPECT_TRUE(report::isWellFormedXml(svg, &problem)) << entry.path() << ": " << problem;
        EXPECT_EQ(svg.find("nan"), std::string::npos) << entry.path();
        EXPECT_EQ(svg.find("inf"), std::string::npos) << entry.path();
        ++svgs;
    }
    EXPECT_GT(svgs, 20);
    EXPECT_EQ(csvs, 5);  // runs-{scenes,substeps,contacts,mixing,exact}.csv

    const std::string pc = readFile(dir / "position-correction.md");
    EXPECT_EQ(pc.find("stale"), std::string::npos);
    EXPECT_NE(pc.find("prose before"), std::string::npos);
    EXPECT_NE(pc.find("prose after"), std::string::npos);
    EXPECT_NE(pc.find("### Baumgarte"), std::string::npos);
    EXPECT_NE(pc.find("- Verdict: **"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Report, RefusesADocumentWithoutTheObservationsBlock) {
    const fs::path dir =
        fs::temp_directory_path() / ("pivot-report-test-noblock-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    { std::ofstream(dir / "position-correction.md") << "no markers here\n"; }
    report::ReportSettings settings;
    settings.docsDir = dir.string();
    settings.steps = 30;
    std::ostringstream log;
    EXPECT_NE(report::generateReport(settings, log).find("observations block"), std::string::npos);
    EXPECT_EQ(readFile(dir / "position-correction.md"), "no markers here\n");
    EXPECT_FALSE(fs::exists(dir / "results.md"));  // refused before writing anything
    fs::remove_all(dir);
}

// The report check masks timings and nothing else: a changed microsecond count, or the verdict
// of an observation measured in time alone, compare equal; a changed separation does not.
TEST(ReportCheck, MasksTimingsAndNothingElse) {
    using pivot::report::maskTimings;
    const std::string table =
        "| solver | max sep (m) | us/step |\n| --- | --- | --- |\n| full_ngs | 0.0188 | 14.2 |\n";
    const std::string slower =
        "| solver | max sep (m) | us/step |\n| --- | --- | --- |\n| full_ngs | 0.0188 | 15.9 |\n";
    const std::string apart =
        "| solver | max sep (m) | us/step |\n| --- | --- | --- |\n| full_ngs | 0.0190 | 14.2 |\n";
    EXPECT_EQ(maskTimings(table), maskTimings(slower));
    EXPECT_NE(maskTimings(table), maskTimings(apart));
    const std::string cheapest =
        "### A\n\n- Result: Baumgarte 40.1 us, FullNGS 51.6 us.\n- Verdict: **confirmed**.\n";
    const std::string cheapestFlipped =
        "### A\n\n- Result: Baumgarte 52.1 us, FullNGS 51.6 us.\n- Verdict: **not confirmed**.\n";
    EXPECT_EQ(maskTimings(cheapest), maskTimings(cheapestFlipped));
    const std::string mixed =
        "### B\n\n- Result: 0.02 m with 1 iteration; 12.8 us against 18.6 us.\n- Verdict: "
        "**confirmed**.\n";
    const std::string mixedFlipped =
        "### B\n\n- Result: 0.02 m with 1 iteration; 13.1 us against 18.0 us.\n- Verdict: **not "
        "confirmed**.\n";
    EXPECT_NE(maskTimings(mixed), maskTimings(mixedFlipped));  // that verdict is not a timing's
    EXPECT_EQ(maskTimings("This page took 4 s to generate"),
              maskTimings("This page took 3 s to generate"));
}

// The raw runs' CSVs: the last column, us_per_step, is masked; every other column is compared,
// quoted set-up names with commas included.
TEST(ReportCheck, MasksTheLastColumnOfARunsCsv) {
    using pivot::report::maskCsvTimings;
    const std::string runs =
        "scene,setup,max_separation_m,us_per_step\n"
        "rope,\"FullNGS 2/1, key +2\",0.012,10.6\n";
    const std::string slower =
        "scene,setup,max_separation_m,us_per_step\n"
        "rope,\"FullNGS 2/1, key +2\",0.012,11.9\n";
    const std::string apart =
        "scene,setup,max_separation_m,us_per_step\n"
        "rope,\"FullNGS 2/1, key +2\",0.013,10.6\n";
    EXPECT_EQ(maskCsvTimings(runs), maskCsvTimings(slower));
    EXPECT_NE(maskCsvTimings(runs), maskCsvTimings(apart));
    // Without a timing column nothing is masked.
    const std::string untimed = "scene,max_separation_m\nrope,0.012\n";
    const std::string untimedApart = "scene,max_separation_m\nrope,0.013\n";
    EXPECT_NE(maskCsvTimings(untimed), maskCsvTimings(untimedApart));
}
