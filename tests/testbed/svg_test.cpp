// The report's SVG figures: every renderer emits well-formed XML for ordinary and degenerate
// input, never prints nan or inf, escapes names, breaks lines at non-finite values and keeps the
// snapshot strip's aspect ratio; the XML checker rejects what it should, with an offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "report/svg.h"

using namespace pivot;
using namespace pivot::report;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::size_t countOf(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + needle.size())) {
        ++count;
    }
    return count;
}

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

/// Well-formed, an <svg> root with the namespace, and no nan or inf anywhere.
void expectValidSvg(const std::string& svg) {
    std::string problem;
    EXPECT_TRUE(isWellFormedXml(svg, &problem)) << problem << "\n" << svg;
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_NE(svg.find("viewBox=\""), std::string::npos);
    std::string text = lower(svg);
    EXPECT_EQ(text.find("nan"), std::string::npos) << svg;
    EXPECT_EQ(text.find("inf"), std::string::npos) << svg;
}

/// The inside of the first <g class="NAME" ...> ... </g> (such groups hold no nested groups).
std::string group(const std::string& svg, const std::string& name) {
    std::size_t start = svg.find("<g class=\"" + name + "\"");
    if (start == std::string::npos) return "";
    std::size_t end = svg.find("</g>", start);
    return svg.substr(start, end - start);
}

/// The texts of the <text> elements in a fragment.
std::vector<std::string> texts(const std::string& fragment) {
    std::vector<std::string> out;
    for (std::size_t at = fragment.find("<text"); at != std::string::npos;
         at = fragment.find("<text", at + 1)) {
        std::size_t open = fragment.find('>', at) + 1;
        out.push_back(fragment.substr(open, fragment.find("</text>", open) - open));
    }
    return out;
}

Series series(const std::string& name, std::vector<std::pair<double, double>> points) {
    return Series{name, std::move(points)};
}

LinePlot fourSeries(bool logY) {
    LinePlot plot;
    plot.title = "Joint separation";
    plot.xLabel = "time (s)";
    plot.yLabel = "separation (m)";
    plot.logY = logY;
    const char* names[] = {"baumgarte", "pseudo_velocity", "ngs", "full_ngs"};
    for (int s = 0; s < 4; ++s) {
        Series line{names[s], {}};
        for (int i = 0; i <= 60; ++i) {
            double t = i / 60.0;
            line.points.emplace_back(t, std::pow(10.0, -2.0 - s) * (1.0 + std::sin(6.0 * t)));
        }
        plot.series.push_back(line);
    }
    return plot;
}

}  // namespace

TEST(SvgLinePlot, OrdinaryPlotIsWellFormedWithOnePolylinePerSeries) {
    for (bool logY : {false, true}) {
        std::string svg = renderLinePlot(fourSeries(logY));
        expectValidSvg(svg);
        EXPECT_EQ(countOf(svg, "<polyline"), 4u);
        EXPECT_NE(svg.find("width=\"720\" height=\"360\" viewBox=\"0 0 720 360\""),
                  std::string::npos);
        EXPECT_NE(svg.find(">Joint separation</text>"), std::string::npos);
        EXPECT_NE(svg.find(">time (s)</text>"), std::string::npos);
        EXPECT_NE(svg.find(">separation (m)</text>"), std::string::npos);
        std::vector<std::string> legend = texts(group(svg, "legend"));
        EXPECT_EQ(legend,
                  (std::vector<std::string>{"baumgarte", "pseudo_velocity", "ngs", "full_ngs"}));
    }
}

TEST(SvgLinePlot, SeriesGetDistinctColours) {
    LinePlot plot;
    for (int s = 0; s < 10; ++s) {
        plot.series.push_back(series("s" + std::to_string(s), {{0.0, s}, {1.0, s + 1.0}}));
    }
    std::string svg = renderLinePlot(plot);
    expectValidSvg(svg);
    std::vector<std::string> colours;
    for (std::size_t at = svg.find("<polyline"); at != std::string::npos;
         at = svg.find("<polyline", at + 1)) {
        std::size_t c = svg.find("stroke=\"", at) + 8;
        colours.push_back(svg.substr(c, svg.find('"', c) - c));
    }
    ASSERT_EQ(colours.size(), 10u);
    std::sort(colours.begin(), colours.end());
    EXPECT_EQ(std::unique(colours.begin(), colours.end()), colours.end());
}

TEST(SvgLinePlot, DegenerateInputsStayWellFormed) {
    std::vector<LinePlot> plots;
    plots.push_back(LinePlot{});  // nothing at all
    plots.push_back(LinePlot{"t", "x", "y", false, {series("empty", {})}});
    plots.push_back(LinePlot{"t", "x", "y", false, {series("one", {{1.0, 2.0}})}});
    plots.push_back(LinePlot{"t", "x", "y", false, {series("flat", {{0, 3}, {1, 3}, {2, 3}})}});
    plots.push_back(LinePlot{"", "", "", false, {series("zero", {{0, 0}, {0, 0}})}});
    plots.push_back(LinePlot{
        "t", "x", "y", false, {series("bad", {{0, kNaN}, {kInf, 1}, {2, -kInf}, {kNaN, kNaN}})}});
    plots.push_back(LinePlot{"t", "x", "y", true, {series("zeros", {{0, 0}, {1, -1}, {2, 1e-5}})}});
    plots.push_back(LinePlot{"t", "x", "y", true, {series("nonpositive", {{0, 0}, {1, -3}})}});
    plots.push_back(LinePlot{"t", "x", "y", true, {series("exact", {{0, 1e-3}, {1, 1e-3}})}});
    plots.push_back(
        LinePlot{"t", "x", "y", false, {series("huge", {{-1e308, -1e308}, {1e308, 1e308}})}});
    plots.push_back(
        LinePlot{"t", "x", "y", true, {series("decades", {{0, 4.9e-324}, {1, 1.7e308}})}});
    plots.push_back(LinePlot{"t", "x", "y", false, {series("tiny", {{0, 1e-300}, {1, 3e-300}})}});
    plots.push_back(
        LinePlot{"t", "x", "y", false, {series("offset", {{0, 1e9}, {1, 1e9 + 1e-4}})}});
    plots.push_back(LinePlot{"t", "x", "y", false, {series("denormal", {{0, 4.9e-324}})}});
    LinePlot many{"many", "x", "y", false, {}};
    for (int s = 0; s < 60; ++s) {
        many.series.push_back(series("series number " + std::to_string(s), {{0, s}, {1, -s}}));
    }
    plots.push_back(many);
    for (const LinePlot& plot : plots) {
        SCOPED_TRACE(plot.series.empty() ? "no series" : plot.series.front().name);
        expectValidSvg(renderLinePlot(plot));
        expectValidSvg(renderLinePlot(plot, 0, -5));  // sizes too small to hold a plot
    }
}

TEST(SvgLinePlot, PolylinesFollowTheRunsOfFiniteValues) {
    LinePlot plot;
    plot.series.push_back(series("a", {{0, 1}, {1, 2}, {2, kNaN}, {3, 4}, {4, 5}}));  // 2 runs
    plot.series.push_back(series("b", {{0, kNaN}, {1, 2}, {2, kInf}, {3, kNaN}, {4, 1}}));  // 2
    plot.series.push_back(series("c", {{0, 1}, {kNaN, 2}, {2, 3}, {3, -kInf}}));            // 2
    plot.series.push_back(series("d", {{0, kNaN}, {1, kInf}}));                             // 0
    plot.series.push_back(series("e", {{0, 1}, {1, 2}, {2, 3}}));                           // 1
    std::string svg = renderLinePlot(plot);
    expectValidSvg(svg);
    EXPECT_EQ(countOf(svg, "<polyline"), 7u);
    // The lone points (b at x=1 and x=4, c at x=0 and x=2) also get a visible dot.
    EXPECT_EQ(countOf(group(svg, "series"), "<circle"), 4u);

    plot.logY = true;  // zeros and negatives are clamped, not dropped: the runs stay the same
    plot.series.push_back(series("f", {{0, 0}, {1, -1}, {2, 1e-3}}));  // 1
    svg = renderLinePlot(plot);
    expectValidSvg(svg);
    EXPECT_EQ(countOf(svg, "<polyline"), 8u);
}

TEST(SvgLinePlot, LegendNamesAreEscaped) {
    LinePlot plot;
    plot.title = "Fish & <chips>";
    plot.series.push_back(series("a & b <c> \"d\" 'e'", {{0, 1}, {1, 2}}));
    std::string svg = renderLinePlot(plot);
    expectValidSvg(svg);
    EXPECT_NE(group(svg, "legend").find("a &amp; b &lt;c&gt; &quot;d&quot; &apos;e&apos;"),
              std::string::npos);
    EXPECT_NE(svg.find("Fish &amp; &lt;chips&gt;"), std::string::npos);
    EXPECT_EQ(svg.find("<c>"), std::string::npos);
    EXPECT_EQ(svg.find("<chips>"), std::string::npos);
}

TEST(SvgLinePlot, LinearTicksAreNiceAndFewEnough) {
    LinePlot plot;
    plot.series.push_back(series("s", {{0, 0}, {1, 10}}));
    std::string svg = renderLinePlot(plot);
    std::vector<std::string> x = texts(group(svg, "x-ticks"));
    std::vector<std::string> y = texts(group(svg, "y-ticks"));
    EXPECT_EQ(x, (std::vector<std::string>{"0", "0.2", "0.4", "0.6", "0.8", "1"}));
    EXPECT_EQ(y, (std::vector<std::string>{"0", "2", "4", "6", "8", "10"}));

    // Ranges of every size give 4 to 8 ticks, and the ticks enclose the data.
    for (double span : {1e-7, 0.003, 0.7, 1.0, 3.3, 9.99, 1234.0, 7e5, 2e12}) {
        LinePlot p;
        p.series.push_back(series("s", {{0, -0.3 * span}, {1, 0.7 * span}}));
        std::vector<std::string> labels = texts(group(renderLinePlot(p), "y-ticks"));
        EXPECT_GE(labels.size(), 4u) << span;
        EXPECT_LE(labels.size(), 8u) << span;
        EXPECT_LE(std::strtod(labels.front().c_str(), nullptr), -0.3 * span) << span;
        EXPECT_GE(std::strtod(labels.back().c_str(), nullptr), 0.7 * span) << span;
    }
}

TEST(SvgLinePlot, SmallAndLargeTicksUseCompactScientificLabels) {
    LinePlot small;
    small.series.push_back(series("s", {{0, 0}, {1, 4e-4}}));
    EXPECT_EQ(texts(group(renderLinePlot(small), "y-ticks")),
              (std::vector<std::string>{"0", "1e-4", "2e-4", "3e-4", "4e-4"}));
    LinePlot large;
    large.series.push_back(series("s", {{0, 0}, {1, 2.5e6}}));
    std::vector<std::string> labels = texts(group(renderLinePlot(large), "y-ticks"));
    EXPECT_NE(std::find(labels.begin(), labels.end(), "2.5e6"), labels.end());
}

TEST(SvgLinePlot, LogAxisHasDecadeTicks) {
    LinePlot plot;
    plot.logY = true;
    plot.series.push_back(series("s", {{0, 3e-6}, {1, 0.0}, {2, 8e-3}}));
    std::string svg = renderLinePlot(plot);
    expectValidSvg(svg);
    EXPECT_EQ(texts(group(svg, "y-ticks")),
              (std::vector<std::string>{"1e-6", "1e-5", "1e-4", "1e-3", "1e-2"}));

    plot.series = {series("s", {{0, 0.05}, {1, 300}})};
    EXPECT_EQ(texts(group(renderLinePlot(plot), "y-ticks")),
              (std::vector<std::string>{"0.01", "0.1", "1", "10", "100", "1000"}));

    // Hundreds of decades: every n-th decade only.
    plot.series = {series("s", {{0, 1e-300}, {1, 1e300}})};
    std::vector<std::string> wide = texts(group(renderLinePlot(plot), "y-ticks"));
    EXPECT_GE(wide.size(), 4u);
    EXPECT_LE(wide.size(), 8u);
}

TEST(SvgScatterPlot, GroupsColoursLabelsAndLogAxes) {
    ScatterPlot plot;
    plot.title = "Cost against error";
    plot.xLabel = "us/step";
    plot.yLabel = "max sep";
    plot.points = {{1.0, 1e-3, "chain", "baumgarte"},
                   {2.0, 1e-4, "chain", "ngs"},
                   {3.0, 1e-5, "bridge", "full & fast"},
                   {kNaN, 1.0, "bridge", "hidden"},
                   {4.0, 1e-2, "pendulum", ""}};
    for (bool log : {false, true}) {
        plot.logX = log;
        plot.logY = log;
        std::string svg = renderScatterPlot(plot);
        expectValidSvg(svg);
        std::vector<std::string> fills;
        std::string points = group(svg, "points");
        for (std::size_t at = points.find("fill=\""); at != std::string::npos;
             at = points.find("fill=\"", at + 1)) {
            fills.push_back(points.substr(at + 6, 7));
        }
        ASSERT_EQ(fills.size(), 4u);    // the point at x = NaN is not drawn
        EXPECT_EQ(fills[0], fills[1]);  // both chain points
        EXPECT_NE(fills[1], fills[2]);
        EXPECT_NE(fills[2], fills[3]);
        EXPECT_NE(fills[0], fills[3]);
        EXPECT_EQ(texts(group(svg, "legend")),
                  (std::vector<std::string>{"chain", "bridge", "pendulum"}));
        EXPECT_EQ(texts(group(svg, "point-labels")),
                  (std::vector<std::string>{"baumgarte", "ngs", "full &amp; fast"}));
    }
}

TEST(SvgScatterPlot, DegenerateInputsStayWellFormed) {
    std::vector<ScatterPlot> plots;
    plots.push_back(ScatterPlot{});
    plots.push_back(ScatterPlot{"t", "x", "y", false, false, {{1, 1, "", ""}}});
    plots.push_back(
        ScatterPlot{"t", "x", "y", true, true, {{0, 0, "g", "zero"}, {-1, 5, "g", ""}}});
    plots.push_back(ScatterPlot{"t", "x", "y", true, false, {{kInf, kNaN, "g", "x"}}});
    plots.push_back(ScatterPlot{"t", "x", "y", false, true, {{2, 2, "a", ""}, {2, 2, "b", ""}}});
    ScatterPlot many{"many", "x", "y", false, false, {}};
    for (int i = 0; i < 40; ++i) many.points.push_back({i * 1.0, i * 2.0, std::to_string(i), ""});
    plots.push_back(many);
    for (const ScatterPlot& plot : plots) expectValidSvg(renderScatterPlot(plot));
}

namespace {

SnapshotFrame boxesAndCircles(float shift) {
    SnapshotFrame frame;
    frame.caption = "t = " + std::to_string(shift) + " s";
    frame.polygons.push_back({{{-5, -0.5f}, {5, -0.5f}, {5, 0}, {-5, 0}}, true});
    frame.polygons.push_back({{{shift, 1}, {shift + 1, 1}, {shift + 1, 2}, {shift, 2}}, false});
    frame.circles.push_back({{shift - 2, 0.5f}, 0.5f, shift, false});
    frame.joints.push_back({{shift, 2}, {shift, 2}});
    return frame;
}

/// The numbers in an attribute value such as a path's d: "M1.00,2.00 L3.00,4.00 Z".
std::vector<double> numbersIn(const std::string& text) {
    std::vector<double> out;
    const char* p = text.c_str();
    while (*p != '\0') {
        if (std::isdigit(static_cast<unsigned char>(*p)) || *p == '-' || *p == '.') {
            char* end = nullptr;
            out.push_back(std::strtod(p, &end));
            p = end;
        } else {
            ++p;
        }
    }
    return out;
}

/// The bounding box width and height of the first path with the given class.
std::pair<double, double> pathSize(const std::string& svg, const std::string& cssClass) {
    std::size_t at = svg.find("<path class=\"" + cssClass + "\" d=\"");
    EXPECT_NE(at, std::string::npos);
    std::size_t start = svg.find("d=\"", at) + 3;
    std::vector<double> v = numbersIn(svg.substr(start, svg.find('"', start) - start));
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) {
        minX = std::min(minX, v[i]);
        maxX = std::max(maxX, v[i]);
        minY = std::min(minY, v[i + 1]);
        maxY = std::max(maxY, v[i + 1]);
    }
    return {maxX - minX, maxY - minY};
}

}  // namespace

TEST(SvgSnapshotStrip, OnePanelPerFrameWithCaptionsAndTitle) {
    std::vector<SnapshotFrame> frames = {boxesAndCircles(0), boxesAndCircles(1),
                                         boxesAndCircles(2)};
    std::string svg = renderSnapshotStrip("Pyramid & friends", frames);
    expectValidSvg(svg);
    EXPECT_EQ(countOf(svg, "<g class=\"panel\""), 3u);
    EXPECT_NE(svg.find(">Pyramid &amp; friends</text>"), std::string::npos);
    for (const SnapshotFrame& f : frames) {
        EXPECT_NE(svg.find(">" + f.caption + "</text>"), std::string::npos);
    }
    EXPECT_EQ(countOf(svg, "<path class=\"static\""), 3u);
    EXPECT_EQ(countOf(svg, "<path class=\"dynamic\""), 3u);
    EXPECT_EQ(countOf(svg, "<circle class=\"dynamic\""), 3u);
    EXPECT_EQ(countOf(svg, "<line class=\"radius\""), 3u);
    EXPECT_EQ(countOf(svg, "<circle class=\"anchor\""), 6u);
    EXPECT_EQ(countOf(svg, "class=\"separation\""), 0u);  // coincident anchors: no red line
}

TEST(SvgSnapshotStrip, SeparatedJointGetsARedLine) {
    SnapshotFrame frame;
    frame.joints.push_back({{0, 0}, {0.5f, 0}});     // well apart
    frame.joints.push_back({{1, 0}, {1, 1.0e-5f}});  // within a hair: no line
    std::string svg = renderSnapshotStrip("", {frame});
    expectValidSvg(svg);
    EXPECT_EQ(countOf(svg, "<line class=\"separation\""), 1u);
    EXPECT_NE(svg.find(".separation{stroke:#e3120b"), std::string::npos);
}

TEST(SvgSnapshotStrip, SquareStaysSquareInAWidePanel) {
    SnapshotFrame frame;
    frame.polygons.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, false});
    frame.polygons.push_back({{{3, 0}, {4, 0}, {4, 0.2f}, {3, 0.2f}}, true});
    for (int width : {240, 400, 100}) {
        std::string svg = renderSnapshotStrip("", {frame}, {}, width, 200);
        expectValidSvg(svg);
        auto [w, h] = pathSize(svg, "dynamic");
        EXPECT_GT(w, 10.0);
        EXPECT_NEAR(w, h, 0.02) << width;
    }
    // Also with an explicit view, which itself is not square.
    std::string svg = renderSnapshotStrip("", {frame}, {{-1, -1}, {5, 2}}, 240, 200);
    auto [w, h] = pathSize(svg, "dynamic");
    EXPECT_NEAR(w, 240.0 / 6.0, 0.02);  // the view's 6 m width fills the 240 px panel
    EXPECT_NEAR(w, h, 0.02);
}

TEST(SvgSnapshotStrip, PanelsShareOneScale) {
    SnapshotFrame small;
    small.polygons.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, false});
    SnapshotFrame large;
    large.polygons.push_back({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, false});
    std::string svg = renderSnapshotStrip("", {small, large});
    std::size_t second =
        svg.find("<path class=\"dynamic\"", svg.find("<path class=\"dynamic\"") + 1);
    ASSERT_NE(second, std::string::npos);
    double smallWidth = pathSize(svg, "dynamic").first;
    double largeWidth = pathSize(svg.substr(second), "dynamic").first;
    EXPECT_NEAR(largeWidth, 4.0 * smallWidth, 0.05);
}

TEST(SvgSnapshotStrip, DegenerateInputsStayWellFormed) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    SnapshotFrame empty;
    SnapshotFrame point;
    point.circles.push_back({{2, 3}, 0.0f, 0.0f, true});
    SnapshotFrame broken;
    broken.caption = "broken <1>";
    broken.circles.push_back({{nan, 0}, 1.0f, 0.0f, false});
    broken.circles.push_back({{0, 0}, inf, nan, false});
    broken.circles.push_back({{0, 0}, -1.0f, nan, false});
    broken.polygons.push_back({{}, false});
    broken.polygons.push_back({{{0, 0}, {inf, 1}, {1, 1}}, false});
    broken.polygons.push_back({{{0, 0}}, true});
    broken.joints.push_back({{nan, 0}, {0, 0}});
    SnapshotFrame far;
    far.polygons.push_back({{{-3e38f, -3e38f}, {3e38f, -3e38f}, {3e38f, 3e38f}}, false});
    far.circles.push_back({{1, 1}, 1e-30f, 1.0f, false});
    std::vector<std::vector<SnapshotFrame>> strips = {
        {}, {empty}, {point}, {broken}, {far}, {empty, point, broken, far}};
    for (const auto& frames : strips) {
        expectValidSvg(renderSnapshotStrip("strip", frames));
        expectValidSvg(renderSnapshotStrip("", frames, {{0, 0}, {1, 1}}, 0, -3));
        expectValidSvg(renderSnapshotStrip("", frames, {{0, 0}, {nan, 1}}));
    }
    EXPECT_EQ(countOf(renderSnapshotStrip("", {empty, point}), "<g class=\"panel\""), 2u);
}

TEST(SvgXml, EscapeXmlEscapesTheFiveSpecialCharacters) {
    EXPECT_EQ(escapeXml("a&b<c>d\"e'f"), "a&amp;b&lt;c&gt;d&quot;e&apos;f");
    EXPECT_EQ(escapeXml("plain text, 2.5 m/s"), "plain text, 2.5 m/s");
    EXPECT_EQ(escapeXml("tab\tline\nbell\a"), "tab\tline\nbell");
    EXPECT_EQ(escapeXml("\xC3\xA9t\xC3\xA9"), "\xC3\xA9t\xC3\xA9");  // UTF-8 passes through
    std::string escaped = "<r a=\"" + escapeXml("x\"<&>'\x01") + "\">" + escapeXml("<&>") + "</r>";
    EXPECT_TRUE(isWellFormedXml(escaped));
}

TEST(SvgXml, AcceptsAHandWrittenSvg) {
    const std::string svg =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- a comment before the root -->\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width='10' height=\"10\">\n"
        "  <g id=\"a\" fill = \"red\">\n"
        "    <rect x=\"0\" y=\"0\" width=\"5\" height=\"5\"/>\n"
        "    <text x=\"1\" y=\"2\">A &amp; B &lt;&gt; &quot;&apos; &#233; &#x2014;</text>\n"
        "    <!-- inside -->\n"
        "    <style><![CDATA[ rect { fill: blue; } a < b ]]></style>\n"
        "  </g >\n"
        "  <circle cx=\"1\" cy=\"1\" r=\"1\" />\n"
        "</svg>\n"
        "<!-- trailing comment -->\n";
    std::string problem;
    EXPECT_TRUE(isWellFormedXml(svg, &problem)) << problem;
    EXPECT_TRUE(isWellFormedXml("<a/>"));
}

TEST(SvgXml, RejectsMalformedDocumentsAndSaysWhere) {
    struct Case {
        const char* what;
        std::string document;
        const char* expected;  // part of the problem text
    };
    std::vector<Case> cases = {
        {"unclosed tag", "<svg><g></svg>", "does not match <g>"},
        {"unclosed root", "<svg><g></g>", "never closed"},
        {"mismatched nesting", "<a><b><c></b></c></a>", "does not match <c>"},
        {"unquoted attribute", "<svg width=10></svg>", "not quoted"},
        {"attribute without value", "<svg hidden></svg>", "no '='"},
        {"duplicate attribute", "<svg x=\"1\" y=\"2\" x=\"3\"/>", "duplicate attribute 'x'"},
        {"bad entity", "<svg>&nbsp;</svg>", "unknown entity &nbsp;"},
        {"bare ampersand", "<svg>fish & chips</svg>", "entity reference"},
        {"bad character reference", "<svg>&#0;</svg>", "not a legal character"},
        {"bad entity in attribute", "<svg a=\"&foo;\"/>", "unknown entity"},
        {"two roots", "<svg/><svg/>", "second root"},
        {"text after the root", "<svg/>trailing", "after the root"},
        {"text before the root", "hello<svg/>", "before the root"},
        {"empty document", "  ", "no root"},
        {"end tag first", "</svg>", "without a start"},
        {"less-than in attribute", "<svg a=\"<\"/>", "'<' inside"},
        {"missing space between attributes", "<svg a=\"1\"b=\"2\"/>", "unexpected 'b'"},
        {"unterminated start tag", "<svg a=\"1\"", "unterminated"},
        {"unterminated comment", "<svg><!-- open </svg>", "unterminated comment"},
        {"double hyphen in comment", "<svg><!-- a -- b --></svg>", "'--'"},
        {"late declaration", "<svg/><?xml version=\"1.0\"?>", "not supported"},
        {"control character", std::string("<svg>a\x01</svg>"), "control character"},
        {"cdata end in text", "<svg>a ]]> b</svg>", "']]>'"},
    };
    for (const Case& c : cases) {
        std::string problem;
        EXPECT_FALSE(isWellFormedXml(c.document, &problem)) << c.what;
        EXPECT_NE(problem.find(c.expected), std::string::npos) << c.what << ": " << problem;
        EXPECT_EQ(problem.rfind("offset ", 0), 0u) << c.what << ": " << problem;
        EXPECT_FALSE(isWellFormedXml(c.document)) << c.what;  // no problem pointer: no crash
    }
    std::string problem;
    isWellFormedXml("<svg><g></h></svg>", &problem);
    EXPECT_EQ(problem.rfind("offset 8:", 0), 0u) << problem;  // where the bad end tag starts
}

TEST(SvgXml, RenderingIsDeterministic) {
    EXPECT_EQ(renderLinePlot(fourSeries(true)), renderLinePlot(fourSeries(true)));
    std::vector<SnapshotFrame> frames = {boxesAndCircles(0.25f)};
    EXPECT_EQ(renderSnapshotStrip("x", frames), renderSnapshotStrip("x", frames));
}
