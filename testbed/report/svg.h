// SVG figures for the generated report (docs/results.md), drawn by the project's own code:
// line plots, scatter plots and snapshot strips of scenes. Each function returns a complete,
// standalone SVG document (well-formed XML, no external references, no scripts).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "pivot/math.h"

namespace pivot::report {

struct Series {
    std::string name;                               ///< legend text
    std::vector<std::pair<double, double>> points;  ///< (x, y); non-finite y breaks the line
};

struct LinePlot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logY = false;  ///< values <= 0 are clamped to the smallest positive value shown
    std::vector<Series> series;
};

/// Axes with ticks and labels, one coloured polyline per series, and a legend. Each run of
/// finite points is one polyline (a lone point also gets a dot). Sizes below 160 x 120 px are
/// enlarged to that.
std::string renderLinePlot(const LinePlot& plot, int width = 720, int height = 360);

struct ScatterPoint {
    double x = 0.0;
    double y = 0.0;
    std::string group;  ///< points of one group share a colour and a legend entry
    std::string label;  ///< short text drawn next to the point (may be empty)
};

struct ScatterPlot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logX = false;
    bool logY = false;
    std::vector<ScatterPoint> points;
};

/// Points as dots coloured by group (legend of the named groups), labels beside them. Points
/// with a non-finite coordinate are left out; on a log axis values <= 0 sit on its lower edge.
std::string renderScatterPlot(const ScatterPlot& plot, int width = 720, int height = 400);

/// A scene drawn at one moment, in world coordinates (metres, y up).
struct SnapshotFrame {
    std::string caption;  ///< e.g. "t = 2.0 s"
    struct CircleShape {
        Vec2 center;
        float radius = 0.0f;
        float angle = 0.0f;  ///< a radius line is drawn at this angle so rotation shows
        bool isStatic = false;
    };
    struct PolygonShape {
        std::vector<Vec2> vertices;
        bool isStatic = false;
    };
    std::vector<CircleShape> circles;
    std::vector<PolygonShape> polygons;
    std::vector<std::pair<Vec2, Vec2>> joints;  ///< anchor A and anchor B of each joint
    /// Each joint's separation (World::jointSeparation), m, where it is not the gap between its
    /// anchors (a distance joint's anchors are meant to be apart); empty: every joint's
    /// separation is its gap.
    std::vector<float> separations;
};

/// The frames side by side, all at one common scale fitted to the union of their contents
/// (optionally limited to `view`, lower and upper corners, when view.second > view.first).
/// Joints are two dots, with a red line between them when the anchors are over 1 mm apart.
/// Shapes with non-finite coordinates are left out.
std::string renderSnapshotStrip(const std::string& title, const std::vector<SnapshotFrame>& frames,
                                std::pair<Vec2, Vec2> view = {}, int frameWidth = 240,
                                int frameHeight = 200);

/// Escapes &, <, >, " and ' for use in XML text and attributes. Control characters that XML 1.0
/// forbids even as references (all below 0x20 but tab, LF and CR) are dropped.
std::string escapeXml(const std::string& text);

/// A small, strict well-formedness check (balanced and properly nested elements, quoted
/// attributes, known entities only, one root element): enough for tests to prove the
/// generated SVG parses. Not supported (reported as problems): DOCTYPE, processing instructions
/// other than a leading XML declaration. `problem` gets "offset N: what" for the first problem.
bool isWellFormedXml(const std::string& document, std::string* problem = nullptr);

}  // namespace pivot::report
