// The browser replay's C++ side: what recordScene records, and what the page it renders
// carries. The page's drawing is tested in headless Chromium (tests/browser/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "replay/html_replay.h"
#include "replay/recording.h"

using namespace pivot;
using namespace pivot::replay;

namespace {

Recording record(const char* scene, int steps, int stepsPerFrame) {
    const scenes::SceneInfo* info = scenes::findScene(scene);
    EXPECT_NE(info, nullptr) << scene;
    return recordScene(*info, steps, stepsPerFrame);
}

int framesOf(const Track& track) {
    return static_cast<int>(track.poses.size() / 3);
}

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++n;
    }
    return n;
}

// The text of the page's JSON block, up to the first "</" after it (where an HTML parser would
// end the element).
std::string jsonBlock(const std::string& html) {
    const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
    std::size_t begin = html.find(open);
    if (begin == std::string::npos) return "";
    begin += open.size();
    return html.substr(begin, html.find("</", begin) - begin);
}

// A one-run recording with hand-picked numbers, to check the exact encoding.
Recording tinyRecording() {
    Recording r;
    r.scene = "tiny";
    r.description = "hand made";
    r.frameInterval = 1.0f / 30.0f;
    r.frameCount = 2;
    replay::Run run;
    run.label = "full_ngs";
    Track track;
    Outline box;
    box.type = ShapeType::Polygon;
    box.vertices = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
    track.outlines.push_back(box);
    track.poses = {1.0f, 2.0f, 0.5f, 1.5f, 2.0f, 0.5f};
    run.tracks.push_back(track);
    run.jointAnchors = {{1.0f, 2.0f, 1.0f, 2.0f}, {1.5f, 2.0f, 1.5002f, 1.999f}};
    run.maxSeparation = {0.0f, 1.25e-7f};
    r.runs.push_back(run);
    return r;
}

}  // namespace

TEST(ReplayRecording, OneRunPerSolverInEnumOrder) {
    Recording r = record("chain", 20, 2);
    EXPECT_EQ(r.scene, "chain");
    EXPECT_EQ(r.description, scenes::findScene("chain")->description);
    EXPECT_FLOAT_EQ(r.frameInterval, 2.0f / 60.0f);
    ASSERT_EQ(r.runs.size(), static_cast<std::size_t>(kPositionSolverCount));
    for (int s = 0; s < kPositionSolverCount; ++s) {
        const replay::Run& run = r.runs[static_cast<std::size_t>(s)];
        EXPECT_EQ(run.label, positionSolverName(static_cast<PositionSolver>(s)));
        EXPECT_EQ(run.tracks.size(), 31u);  // the ground and 30 links
        ASSERT_EQ(run.jointAnchors.size(), 11u);
        ASSERT_EQ(run.maxSeparation.size(), 11u);
        for (const std::vector<float>& anchors : run.jointAnchors) EXPECT_EQ(anchors.size(), 120u);
    }
}

TEST(ReplayRecording, FrameCountIsStepsOverStepsPerFramePlusOne) {
    struct Case {
        int steps;
        int stepsPerFrame;
        int frames;
    };
    for (Case c : {Case{0, 1, 1}, Case{9, 3, 4}, Case{10, 3, 4}, Case{600, 2, 301}}) {
        Recording r = record("pendulum", c.steps, c.stepsPerFrame);
        EXPECT_EQ(r.frameCount, c.frames) << c.steps << " / " << c.stepsPerFrame;
        for (const replay::Run& run : r.runs) {
            EXPECT_EQ(static_cast<int>(run.maxSeparation.size()), c.frames);
            EXPECT_EQ(static_cast<int>(run.jointAnchors.size()), c.frames);
            for (const Track& track : run.tracks) {
                EXPECT_EQ(track.firstFrame + framesOf(track), c.frames);
            }
        }
    }
}

TEST(ReplayRecording, RejectsStepsPerFrameBelowOne) {
    EXPECT_THROW(record("pendulum", 10, 0), std::invalid_argument);
    EXPECT_THROW(record("pendulum", -1, 1), std::invalid_argument);
}

TEST(ReplayRecording, StaticBodiesAreFlaggedAndOutlinedInTheirOwnFrame) {
    Recording chain = record("chain", 4, 2);
    for (const replay::Run& run : chain.runs) {
        ASSERT_FALSE(run.tracks.empty());
        const Track& ground = run.tracks[0];
        EXPECT_TRUE(ground.isStatic);
        ASSERT_EQ(ground.outlines.size(), 1u);
        EXPECT_EQ(ground.outlines[0].type, ShapeType::Polygon);
        EXPECT_EQ(ground.outlines[0].vertices.size(), 4u);
        for (std::size_t i = 1; i < run.tracks.size(); ++i) {
            const Track& link = run.tracks[i];
            EXPECT_FALSE(link.isStatic);
            ASSERT_EQ(link.outlines.size(), 1u);
            ASSERT_EQ(link.outlines[0].vertices.size(), 4u);
            // A 1.2 x 0.25 m box centred on the body origin, whatever the body's pose.
            for (Vec2 v : link.outlines[0].vertices) {
                EXPECT_FLOAT_EQ(std::fabs(v.x), 0.6f);
                EXPECT_FLOAT_EQ(std::fabs(v.y), 0.125f);
            }
        }
    }
    // The pendulum's pivot is a static body with no shape; its ball is a circle.
    Recording pendulum = record("pendulum", 2, 1);
    const replay::Run& run = pendulum.runs[0];
    ASSERT_EQ(run.tracks.size(), 2u);
    EXPECT_TRUE(run.tracks[0].isStatic);
    EXPECT_TRUE(run.tracks[0].outlines.empty());
    EXPECT_FALSE(run.tracks[1].isStatic);
    ASSERT_EQ(run.tracks[1].outlines.size(), 1u);
    EXPECT_EQ(run.tracks[1].outlines[0].type, ShapeType::Circle);
    EXPECT_FLOAT_EQ(run.tracks[1].outlines[0].radius, 0.5f);
}

// bridge_heavy drops its box before step 120, so the first frame that has it is the one taken
// after the step that follows: frame 120 / stepsPerFrame + 1.
TEST(ReplayRecording, BodiesAddedMidRunStartAtTheirFrame) {
    struct Case {
        int stepsPerFrame;
        int firstFrame;
    };
    for (Case c : {Case{1, 121}, Case{2, 61}, Case{3, 41}}) {
        Recording r = record("bridge_heavy", 130, c.stepsPerFrame);
        for (const replay::Run& run : r.runs) {
            ASSERT_EQ(run.tracks.size(), 32u);  // ground, 30 planks, the box
            for (std::size_t i = 0; i + 1 < run.tracks.size(); ++i) {
                EXPECT_EQ(run.tracks[i].firstFrame, 0);
            }
            const Track& box = run.tracks.back();
            EXPECT_EQ(box.firstFrame, c.firstFrame) << run.label << " every " << c.stepsPerFrame;
            EXPECT_EQ(box.firstFrame + framesOf(box), r.frameCount);
            EXPECT_FALSE(box.isStatic);
            ASSERT_FALSE(box.poses.empty());
            // Released 5 m above the deck at y = 5; it has fallen a little by its first frame.
            EXPECT_NEAR(box.poses[1], 10.0f, 0.1f);
        }
    }
}

TEST(ReplayRecording, PosesAnchorsAndSeparationsAreFinite) {
    for (const char* scene : {"chain", "bridge_heavy", "pendulum"}) {
        Recording r = record(scene, 180, 3);
        for (const replay::Run& run : r.runs) {
            for (const Track& track : run.tracks) {
                for (float v : track.poses) ASSERT_TRUE(std::isfinite(v)) << scene;
            }
            for (const std::vector<float>& anchors : run.jointAnchors) {
                for (float v : anchors) ASSERT_TRUE(std::isfinite(v)) << scene;
            }
            for (float s : run.maxSeparation) {
                ASSERT_TRUE(std::isfinite(s)) << scene;
                EXPECT_GE(s, 0.0f);
            }
            // Joints are made at world anchors: together before the first step.
            EXPECT_LT(run.maxSeparation[0], 1e-5f) << scene << " " << run.label;
        }
    }
}

TEST(ReplayRecording, EveryRunStartsFromTheSameWorldAndFollowsIt) {
    Recording r = record("chain", 60, 2);
    const replay::Run& first = r.runs[0];
    for (const replay::Run& run : r.runs) {
        ASSERT_EQ(run.tracks.size(), first.tracks.size());
        for (std::size_t i = 0; i < run.tracks.size(); ++i) {
            for (int k = 0; k < 3; ++k) EXPECT_EQ(run.tracks[i].poses[k], first.tracks[i].poses[k]);
        }
    }
    // The last frame of full_ngs is the world after 60 steps of the scene, pose for pose.
    scenes::SceneOptions options;
    options.solver = PositionSolver::FullNGS;
    scenes::Scene scene = scenes::buildScene(*scenes::findScene("chain"), options);
    for (int i = 0; i < 60; ++i) scene.world->step(1.0f / 60.0f, 8, 3);
    const replay::Run& full = r.runs[static_cast<std::size_t>(PositionSolver::FullNGS)];
    std::vector<BodyId> bodies = scene.world->bodyIds();
    ASSERT_EQ(bodies.size(), full.tracks.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const std::vector<float>& poses = full.tracks[i].poses;
        Vec2 p = scene.world->bodyPosition(bodies[i]);
        EXPECT_EQ(poses[poses.size() - 3], p.x);
        EXPECT_EQ(poses[poses.size() - 2], p.y);
    }
    std::vector<JointId> joints = scene.world->jointIds();
    const std::vector<float>& anchors = full.jointAnchors.back();
    ASSERT_EQ(anchors.size(), 4 * joints.size());
    float worst = 0.0f;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        EXPECT_EQ(anchors[4 * j], scene.world->jointAnchorA(joints[j]).x);
        EXPECT_EQ(anchors[4 * j + 3], scene.world->jointAnchorB(joints[j]).y);
        worst = std::max(worst, scene.world->jointSeparation(joints[j]));
    }
    EXPECT_EQ(full.maxSeparation.back(), worst);
}

TEST(ReplayHtml, NamesTheSceneAndEverySolver) {
    Recording r = record("chain", 10, 2);
    std::string html = renderReplayHtml({r});
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("<title>pivot2d replay: chain</title>"), std::string::npos);
    EXPECT_NE(html.find("\"name\":\"chain\""), std::string::npos);
    EXPECT_NE(html.find(r.description), std::string::npos);
    for (int s = 0; s < kPositionSolverCount; ++s) {
        std::string label = positionSolverName(static_cast<PositionSolver>(s));
        EXPECT_NE(html.find("\"label\":\"" + label + "\""), std::string::npos) << label;
    }
}

TEST(ReplayHtml, HasThePlayerAndTheStatusHook) {
    std::string html = renderReplayHtml({record("pendulum", 10, 2)});
    EXPECT_NE(html.find("<pre id=\"status\">frames-drawn: 0; nonblank-pixels: 0</pre>"),
              std::string::npos);
    EXPECT_NE(html.find("<script type=\"application/json\" id=\"replay-data\">"),
              std::string::npos);
    for (const char* part : {"requestAnimationFrame", "getImageData", "'range'",
                             "frames-drawn: ", "nonblank-pixels: ", "Math.log10"}) {
        EXPECT_NE(html.find(part), std::string::npos) << part;
    }
    EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
}

TEST(ReplayHtml, IsSelfContained) {
    std::string html = renderReplayHtml({record("bridge_heavy", 10, 2)});
    for (const char* part : {"http://", "https://", "<link", " src=", "@import", "url("}) {
        EXPECT_EQ(html.find(part), std::string::npos) << part;
    }
    // The data block and the player are the only scripts, and only they contain "</".
    EXPECT_EQ(count(html, "<script"), 2u);
    EXPECT_EQ(count(html, "</script>"), 2u);
}

TEST(ReplayHtml, JsonCannotEndItsScriptElement) {
    Recording r = tinyRecording();
    r.scene = "a</script><script>alert(1)</script>";
    r.description = "<!-- \"quoted\" & back\\slash\n";
    std::string html = renderReplayHtml({r});
    std::string json = jsonBlock(html);
    ASSERT_FALSE(json.empty());
    EXPECT_EQ(json.back(), '}') << "the JSON block was cut short";
    EXPECT_EQ(json.find('<'), std::string::npos);
    EXPECT_NE(json.find("a\\u003c/script\\u003e\\u003cscript\\u003ealert(1)"), std::string::npos);
    EXPECT_NE(json.find("\\u003c!-- \\\"quoted\\\" \\u0026 back\\\\slash\\u000a"),
              std::string::npos);
    EXPECT_EQ(count(html, "</script>"), 2u);
    EXPECT_NE(html.find("<title>pivot2d replay: a&lt;/script&gt;"), std::string::npos);
}

TEST(ReplayHtml, EncodesNumbersCompactlyAndExactly) {
    std::string json = jsonBlock(renderReplayHtml({tinyRecording()}));
    // Poses in mm and mrad, each the change since the frame before.
    EXPECT_NE(json.find("\"poses\":[1000,2000,500,500,0,0]"), std::string::npos) << json;
    // Anchor A delta coded in mm, B - A in tenths of a millimetre.
    EXPECT_NE(json.find("\"joints\":[[1000,2000,0,0],[500,0,2,-10]]"), std::string::npos) << json;
    EXPECT_NE(json.find("\"maxSeparation\":[0,1.25e-7]"), std::string::npos) << json;
    EXPECT_NE(json.find("\"polygon\":[-0.5,-0.25,0.5,-0.25,0.5,0.25,-0.5,0.25]"), std::string::npos)
        << json;
    EXPECT_NE(json.find("\"frameInterval\":0.0333333"), std::string::npos) << json;
    EXPECT_NE(json.find("\"static\":false,\"first\":0"), std::string::npos) << json;
}

TEST(ReplayHtml, WritesNullForValuesThatAreNotFinite) {
    Recording r = tinyRecording();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    r.runs[0].tracks[0].poses = {nan, 2.0f, 0.5f, 1.5f, std::numeric_limits<float>::infinity(),
                                 0.5f};
    r.runs[0].maxSeparation[1] = nan;
    std::string json = jsonBlock(renderReplayHtml({r}));
    // After a null its value's chain restarts from 0, so the next one is whole.
    EXPECT_NE(json.find("\"poses\":[null,2000,500,1500,null,0]"), std::string::npos) << json;
    EXPECT_NE(json.find("\"maxSeparation\":[0,null]"), std::string::npos) << json;
    EXPECT_EQ(json.find("nan"), std::string::npos);
    EXPECT_EQ(json.find("inf"), std::string::npos);
}

TEST(ReplayHtml, RendersAPageWithNoRecordings) {
    std::string html = renderReplayHtml({});
    EXPECT_NE(html.find("\"scenes\":[]"), std::string::npos);
    EXPECT_NE(html.find("<pre id=\"status\">"), std::string::npos);
}

TEST(ReplayFile, UnknownSceneNamesTheValidOnes) {
    std::string path = ::testing::TempDir() + "pivot_replay_unknown.html";
    std::remove(path.c_str());
    std::string problem = writeReplayFile(path, {"pendulum", "nope"});
    EXPECT_NE(problem.find("unknown scene 'nope'"), std::string::npos) << problem;
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        EXPECT_NE(problem.find(info.name), std::string::npos) << info.name;
    }
    EXPECT_FALSE(std::ifstream(path).good()) << "nothing is written when a name is wrong";
    EXPECT_FALSE(writeReplayFile(path, {}).empty());
}

TEST(ReplayFile, WritesThePageOrSaysWhyNot) {
    std::string path = ::testing::TempDir() + "pivot_replay_pendulum.html";
    ASSERT_EQ(writeReplayFile(path, {"pendulum"}), "");
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    EXPECT_EQ(text.str(), renderReplayHtml({record("pendulum", 600, 2)}));
    std::remove(path.c_str());

    std::string problem = writeReplayFile("/nonexistent-dir/replay.html", {"pendulum"});
    EXPECT_NE(problem.find("cannot write /nonexistent-dir/replay.html"), std::string::npos)
        << problem;
}
