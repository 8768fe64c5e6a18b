#include "app/cli.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scenes/scene.h"

namespace pivot::testbed {

namespace {

std::string sceneNames() {
    std::string names;
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        names += names.empty() ? "" : ", ";
        names += info.name;
    }
    return names;
}

std::string solverNames() {
    std::string names;
    for (int i = 0; i < kPositionSolverCount; ++i) {
        names += names.empty() ? "" : ", ";
        names += positionSolverName(static_cast<PositionSolver>(i));
    }
    return names;
}

std::string contactNames() {
    return "baumgarte, ngs, soft";
}

long parseInteger(const std::string& option, const std::string& text, long lo, long hi) {
    errno = 0;
    char* end = nullptr;
    long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < lo || value > hi) {
        throw CliError(option + " needs an integer in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "], got '" + text + "'");
    }
    return value;
}

float parseNumber(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    float value = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
        throw CliError(option + " needs a finite number, got '" + text + "'");
    }
    return value;
}

}  // namespace

const char* contactCorrectionName(ContactCorrection correction) {
    switch (correction) {
        case ContactCorrection::Baumgarte: return "baumgarte";
        case ContactCorrection::NGS: return "ngs";
        case ContactCorrection::Soft: return "soft";
    }
    return "invalid";
}

std::string usage() {
    std::ostringstream out;
    out << "usage: pivot-testbed [options]\n"
           "       pivot-testbed reference [--csv FILE]\n"
           "       pivot-testbed report [--docs DIR] [--steps N] [--jobs N] [--check]\n"
           "       pivot-testbed study [--docs DIR] [--jobs N] [--check]\n"
           "       pivot-testbed defaults\n"
           "\n"
           "Runs pivot2d's test scenes headless and prints, for each run, how far the joints\n"
           "came apart, the energy drift, whether the run blew up, and the cost per step.\n"
           "With no options: every scene with every position solver and both contact\n"
           "corrections, in one table.\n"
           "\n"
           "reference: builds each reference scene in pivot2d and in Box2D 2.4.1 and prints\n"
           "how closely FullNGS follows Box2D's revolute joint, then every position solver\n"
           "beside Box2D (its continuous collision off, and on) over 600 steps (needs a build\n"
           "with Box2D: Debian's libbox2d-dev).\n"
           "\n"
           "report: runs every scene with every position solver (each 9 times, perturbed), a\n"
           "bias sweep for baumgarte and pseudo_velocity on the bridges and the weld beam, a\n"
           "position-iteration sweep, a substep study, the contact corrections on the stacks and\n"
           "mixed islands, and writes DIR/results.md with\n"
           "SVG plots in DIR/results/, and the measured observations of the seed note into\n"
           "DIR/position-correction.md (DIR defaults to docs: run it from the repository root).\n"
           "With --check it writes nothing: it regenerates the report in a scratch folder and\n"
           "fails if anything but a timing differs from DIR's (what CI runs). --jobs N runs\n"
           "its trials on N threads (default: 1, whose timings the report quotes; with --check,\n"
           "every hardware thread).\n"
           "\n"
           "study: the Pareto fronts of joint error against cost on chain, ball_chain and\n"
           "mass_ratio, every strategy at every split of substeps, velocity and position\n"
           "iterations, each 9 times perturbed (about 10^4 runs, minutes): writes DIR/pareto.md,\n"
           "and the figures and every run's CSV in DIR/results/. With --check it writes nothing:\n"
           "it regenerates FullNGS on mass_ratio and fails if a run differs from the committed\n"
           "CSV, timings aside (what CI runs).\n"
           "\n"
           "defaults: how WorldDef's defaults were chosen: candidate splits of substeps and\n"
           "iterations on bridge_crate and rope_load (9 perturbed runs each), timed against\n"
           "Box2D 2.4.1's 1 x 8/3; prints the table and the split the rule picks (a minute).\n"
           "\n"
           "options:\n"
           "  --scene NAME      run only this scene: "
        << sceneNames()
        << "\n"
           "  --solver NAME     give every joint this position solver: "
        << solverNames()
        << "\n"
           "  --contact NAME    contact position correction: "
        << contactNames()
        << "\n"
           "  --bias F          bias factor in [0, 1] for every joint (default: 0.2 for\n"
           "                    baumgarte and pseudo_velocity, 1.0 for the NGS solvers)\n"
           "  --steps N         steps per run (default 600, i.e. 10 s at 60 Hz)\n"
           "  --hz F            steps per second (default 60)\n"
           "  --vel-iters N     velocity iterations per step (default 8)\n"
           "  --pos-iters N     position iterations per step (default 3)\n"
           "  --substeps N      substeps per step, in [1, 64] (default 1); the iteration\n"
           "                    counts apply in each substep\n"
           "  --continuous on|off|substeps|fast  continuous collision in every scene\n"
           "                    (default: as each scene has it: on, but off in chain,\n"
           "                    chain_drag, far_chain, ragdoll, ragdoll_motorized and car);\n"
           "                    substeps or fast: on, Box2D 2.4.1's policy (the default) or\n"
           "                    Box2D v3's (WorldDef::continuousCollision)\n"
           "  --csv FILE        also write the table to FILE as CSV\n"
           "  --html FILE       write a self-contained page replaying the runs in a browser\n"
           "                    (the --scene, or pendulum_drag, chain_drag, bridge_heavy and\n"
           "                    ragdoll), one canvas per position solver, then exit\n"
           "  --list            list the scenes with a line on each, and exit\n"
           "  --help            show this text\n"
           "\n"
           "columns: max/rms/final sep = joint separation |anchorB - anchorA| in m (max and\n"
           "RMS over all joints and steps, max over joints after the last step); drift =\n"
           "change of kinetic + potential energy in J; blew up = non-finite state or a body\n"
           "faster than 1e4 m/s; t/r clamps = body-steps whose move was limited by the\n"
           "2 m translation or quarter-turn rotation clamp; ngs its = NGS position sweeps\n"
           "actually run per step (early exit); us/step = mean wall time of World::step.\n"
           "Energy counts bodies a scene adds from the moment they appear; the tumbler is\n"
           "driven, so its drift includes the drive's work.\n";
    return out.str();
}

CliOptions parseCli(const std::vector<std::string>& args) {
    CliOptions options;
    std::size_t first = 0;
    if (!args.empty() && args[0] == "reference") {
        options.command = Command::Reference;
        first = 1;
    } else if (!args.empty() && args[0] == "report") {
        options.command = Command::Report;
        first = 1;
    } else if (!args.empty() && args[0] == "study") {
        options.command = Command::Study;
        first = 1;
    } else if (!args.empty() && args[0] == "defaults") {
        options.command = Command::Defaults;
        first = 1;
    }
    for (std::size_t i = first; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw CliError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--help" || arg == "-h") {
            options.help = true;
        } else if (arg == "--scene") {
            const std::string& name = value();
            if (!scenes::findScene(name)) {
                throw CliError("unknown scene '" + name + "'; valid scenes: " + sceneNames());
            }
            options.scene = name;
        } else if (arg == "--solver") {
            const std::string& name = value();
            options.solver = parsePositionSolver(name);
            if (!options.solver) {
                throw CliError("unknown solver '" + name + "'; valid solvers: " + solverNames());
            }
        } else if (arg == "--contact") {
            const std::string& name = value();
            if (name == "baumgarte") {
                options.contact = ContactCorrection::Baumgarte;
            } else if (name == "ngs") {
                options.contact = ContactCorrection::NGS;
            } else if (name == "soft") {
                options.contact = ContactCorrection::Soft;
            } else {
                throw CliError("unknown contact correction '" + name +
                               "'; valid: " + contactNames());
            }
        } else if (arg == "--list") {
            options.list = true;
        } else if (arg == "--bias") {
            float bias = parseNumber(arg, value());
            if (bias < 0.0f || bias > 1.0f) throw CliError("--bias must be in [0, 1]");
            options.bias = bias;
        } else if (arg == "--steps") {
            options.steps = static_cast<int>(parseInteger(arg, value(), 1, 100000000));
        } else if (arg == "--hz") {
            options.hz = parseNumber(arg, value());
            if (options.hz <= 0.0f) throw CliError("--hz must be > 0");
        } else if (arg == "--vel-iters") {
            options.velocityIterations =
                static_cast<int>(parseInteger(arg, value(), 0, kMaxIterations));
        } else if (arg == "--pos-iters") {
            options.positionIterations =
                static_cast<int>(parseInteger(arg, value(), 0, kMaxIterations));
        } else if (arg == "--substeps") {
            options.substeps = static_cast<int>(parseInteger(arg, value(), 1, kMaxSubsteps));
        } else if (arg == "--continuous") {
            const std::string v = value();
            if (v == "on" || v == "off") {
                options.continuous = v == "on";
            } else if (v == "substeps" || v == "fast") {
                options.continuous = true;
                options.continuousCollision =
                    v == "fast" ? ContinuousCollision::FastBodies : ContinuousCollision::Substeps;
            } else {
                throw CliError("--continuous takes on, off, substeps or fast");
            }
        } else if (arg == "--csv") {
            options.csvPath = value();
        } else if (arg == "--docs") {
            options.docsDir = value();
        } else if (arg == "--jobs") {
            if (options.command != Command::Report && options.command != Command::Study) {
                throw CliError("--jobs goes with report or study");
            }
            options.jobs = static_cast<int>(parseInteger(arg, value(), 1, 64));
        } else if (arg == "--check") {
            if (options.command != Command::Report && options.command != Command::Study) {
                throw CliError("--check goes with report or study");
            }
            options.check = true;
        } else if (arg == "--html") {
            options.htmlPath = value();
        } else {
            throw CliError("unknown option '" + arg + "' (see --help)");
        }
    }
    return options;
}

}  // namespace pivot::testbed
