// pivot-testbed's command line.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::testbed {

enum class Command { Table, Reference, Report, Study, Defaults };

struct CliOptions {
    Command command = Command::Table;
    std::optional<std::string> scene;          ///< unset: every scene
    std::optional<PositionSolver> solver;      ///< unset: every solver
    std::optional<float> bias;                 ///< unset: each solver's default
    std::optional<ContactCorrection> contact;  ///< unset: both
    int steps = 600;
    float hz = 60.0f;
    int velocityIterations = kBox2D241VelocityIterations;
    int positionIterations = kBox2D241PositionIterations;
    int substeps = 1;  ///< WorldDef::substepCount
    /// Continuous collision on or off in every scene; unset: as each scene has it.
    std::optional<bool> continuous;
    /// Its policy where it is on (WorldDef::continuousCollision).
    ContinuousCollision continuousCollision = ContinuousCollision::Substeps;
    std::optional<std::string> csvPath;
    std::optional<std::string> htmlPath;  ///< write the browser replay here
    std::string docsDir = "docs";         ///< report, study: where their pages go
    /// report: regenerate into a scratch folder and compare with docsDir, timings masked;
    /// study: regenerate FullNGS on mass_ratio and compare with its committed runs.
    bool check = false;
    /// report, study: threads running the trials. Timings are taken from one-thread runs;
    /// --check masks them and runs on every hardware thread unless told.
    int jobs = 0;  ///< 0: one, or with --check every hardware thread
    bool help = false;
    bool list = false;
};

/// "baumgarte" or "ngs".
const char* contactCorrectionName(ContactCorrection correction);

/// A command line that cannot be run; the message says why (and lists valid names).
class CliError : public std::runtime_error {
public:
    explicit CliError(const std::string& message) : std::runtime_error(message) {}
};

CliOptions parseCli(const std::vector<std::string>& args);
std::string usage();

}  // namespace pivot::testbed
