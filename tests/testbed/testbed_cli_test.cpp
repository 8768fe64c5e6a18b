// pivot-testbed's command line: valid options parse, invalid ones say what is valid.
#include <gtest/gtest.h>

#include <sstream>

#include "app/cli.h"
#include "app/table.h"

using namespace pivot;
using namespace pivot::testbed;

namespace {
std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseCli(args);
    } catch (const CliError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(TestbedCli, DefaultsRunEverything) {
    CliOptions o = parseCli({});
    EXPECT_FALSE(o.scene);
    EXPECT_FALSE(o.solver);
    EXPECT_FALSE(o.bias);
    EXPECT_EQ(o.steps, 600);
    EXPECT_EQ(o.hz, 60.0f);
    EXPECT_EQ(o.velocityIterations, 8);
    EXPECT_EQ(o.positionIterations, 3);
}

TEST(TestbedCli, ParsesEveryOption) {
    CliOptions o = parseCli({"--scene",     "chain",     "--solver",    "pseudo_velocity",
                             "--contact",   "baumgarte", "--bias",      "0.5",
                             "--steps",     "42",        "--hz",        "120",
                             "--vel-iters", "4",         "--pos-iters", "0",
                             "--csv",       "out.csv",   "--html",      "run.html",
                             "--docs",      "elsewhere"});
    ASSERT_TRUE(o.scene && o.solver && o.contact && o.bias && o.csvPath && o.htmlPath);
    EXPECT_EQ(*o.scene, "chain");
    EXPECT_EQ(*o.solver, PositionSolver::PseudoVelocity);
    EXPECT_EQ(*o.contact, ContactCorrection::Baumgarte);
    EXPECT_EQ(*o.htmlPath, "run.html");
    EXPECT_EQ(o.docsDir, "elsewhere");
    EXPECT_EQ(*o.bias, 0.5f);
    EXPECT_EQ(o.steps, 42);
    EXPECT_EQ(o.hz, 120.0f);
    EXPECT_EQ(o.velocityIterations, 4);
    EXPECT_EQ(o.positionIterations, 0);
    EXPECT_EQ(*o.csvPath, "out.csv");
    EXPECT_TRUE(parseCli({"--help"}).help);
    EXPECT_EQ(parseCli({"reference"}).command, Command::Reference);
    EXPECT_EQ(parseCli({"report", "--steps", "60"}).command, Command::Report);
    EXPECT_EQ(parseCli({}).command, Command::Table);
}

TEST(TestbedCli, UnknownNamesListTheValidOnes) {
    std::string scene = errorOf({"--scene", "bridg"});
    EXPECT_NE(scene.find("unknown scene 'bridg'"), std::string::npos) << scene;
    for (const char* name : {"pendulum", "bridge", "chain", "bridge_heavy", "pyramid", "tumbler"}) {
        EXPECT_NE(scene.find(name), std::string::npos) << scene;
    }
    std::string solver = errorOf({"--solver", "ngs"});
    EXPECT_NE(solver.find("baumgarte, pseudo_velocity, modified_ngs, full_ngs"), std::string::npos)
        << solver;
}

TEST(TestbedCli, BadValuesAreErrors) {
    EXPECT_NE(errorOf({"--steps", "ten"}), "");
    EXPECT_NE(errorOf({"--steps", "0"}), "");
    EXPECT_NE(errorOf({"--hz", "-60"}), "");
    EXPECT_NE(errorOf({"--hz", "nan"}), "");
    EXPECT_NE(errorOf({"--bias", "2"}), "");
    EXPECT_NE(errorOf({"--vel-iters", "-1"}), "");
    EXPECT_NE(errorOf({"--scene"}), "");
    EXPECT_NE(errorOf({"--frobnicate"}), "");
    EXPECT_NE(errorOf({"--contact", "spongy"}).find("baumgarte, ngs, soft"), std::string::npos);
    EXPECT_NE(errorOf({"--substeps", "0"}), "");
    EXPECT_NE(errorOf({"--substeps", "65"}), "");
    EXPECT_EQ(parseCli({"--substeps", "4"}).substeps, 4);
    EXPECT_EQ(parseCli({"--contact", "soft"}).contact, ContactCorrection::Soft);
    EXPECT_NE(errorOf({"--continuous", "sometimes"}).find("on, off, substeps or fast"),
              std::string::npos);
    EXPECT_EQ(parseCli({}).continuousCollision, ContinuousCollision::Substeps);
    const CliOptions fast = parseCli({"--continuous", "fast"});
    EXPECT_EQ(fast.continuous, std::optional<bool>(true));
    EXPECT_EQ(fast.continuousCollision, ContinuousCollision::FastBodies);
    const CliOptions off = parseCli({"--continuous", "off"});
    EXPECT_EQ(off.continuous, std::optional<bool>(false));
    EXPECT_EQ(off.continuousCollision, ContinuousCollision::Substeps);
}

TEST(TestbedCli, HelpExplainsEachOption) {
    std::string text = usage();
    for (const char* option :
         {"--scene", "--solver", "--contact", "--list", "--bias", "--steps", "--hz", "--vel-iters",
          "--substeps", "--pos-iters", "--csv", "--html", "--docs", "--help", "--continuous",
          "fast", "reference", "report"}) {
        EXPECT_NE(text.find(option), std::string::npos) << option;
    }
}

TEST(TestbedTable, CsvHasOneLinePerRunAndAHeader) {
    TableRow row;
    row.scene = "chain";
    row.solver = "full_ngs";
    row.contact = "ngs";
    row.bias = 1.0f;
    row.metrics.steps = 600;
    row.metrics.maxSeparation = 0.25;
    std::ostringstream csv;
    writeCsv(csv, {row, row});
    std::string text = csv.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
    EXPECT_EQ(text.rfind("scene,solver,contact,bias,steps,max_sep_m", 0), 0u);
    EXPECT_NE(text.find("chain,full_ngs,ngs,1,600,2.500000e-01"), std::string::npos) << text;
}
