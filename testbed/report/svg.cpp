// SVG figures for the generated report: axes with nice ticks, line and scatter plots, snapshot
// strips of scenes, and the small XML checker the tests use to prove the output parses.
//
// Every coordinate goes through one formatter with a fixed number of decimals, so the output is
// deterministic, compact and can never contain "nan" or "inf" whatever the input holds.
#include "report/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pivot::report {

namespace {

// ---------------------------------------------------------------------------------------------
// Numbers and colours

// Pixel coordinates are clamped to this magnitude (px) so that an absurd input (a far-away body
// in a small view) still prints a short number instead of a 300-digit one.
constexpr double kMaxPixel = 1.0e7;

// Linear axis values are clamped to this magnitude so that the range (max - min) stays finite.
constexpr double kMaxLinearValue = 1.0e300;

// Rough advance of one character per pixel of font size, for sizing margins to their labels.
constexpr double kCharWidthPerFontSize = 0.6;

// Okabe-Ito's colour-blind safe set (yellow moved last: it is faint on white), then Paul Tol's
// muted extras. Past the end the colours repeat with a dash pattern so series stay distinct.
constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                    "#E69F00", "#56B4E9", "#000000", "#882255",
                                    "#44AA99", "#999933", "#AA4499", "#F0E442"};
constexpr int kPaletteSize = static_cast<int>(sizeof kPalette / sizeof kPalette[0]);
constexpr const char* kDashes[] = {"6 3", "2 2", "8 3 2 3"};
constexpr int kDashCount = static_cast<int>(sizeof kDashes / sizeof kDashes[0]);

const char* colourOf(int index) {
    return kPalette[index % kPaletteSize];
}

/// The dash attribute for the index-th series: none on the first pass through the palette.
std::string dashAttribute(int index) {
    int cycle = index / kPaletteSize;
    if (cycle == 0) return "";
    return " stroke-dasharray=\"" + std::string(kDashes[(cycle - 1) % kDashCount]) + "\"";
}

/// A coordinate with two decimals; non-finite values print as 0 so the document stays valid.
std::string num(double value) {
    if (!std::isfinite(value)) value = 0.0;
    value = std::clamp(value, -kMaxPixel, kMaxPixel);
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.2f", value);
    std::string text = buffer;
    if (text == "-0.00") text = "0.00";
    return text;
}

std::string integer(int value) {
    return std::to_string(value);
}

/// Removes trailing zeros (and a trailing point) from a fixed or mantissa string: "0.50" -> "0.5".
std::string trimZeros(std::string text) {
    if (text.find('.') == std::string::npos) return text;
    while (!text.empty() && text.back() == '0') text.pop_back();
    if (!text.empty() && text.back() == '.') text.pop_back();
    if (text == "-0") text = "0";
    return text;
}

/// A compact scientific label: 2.5e-4, 1e6.
std::string scientific(double value, int mantissaDecimals) {
    if (value == 0.0) return "0";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*e", std::clamp(mantissaDecimals, 0, 15), value);
    std::string text = buffer;
    std::size_t e = text.find('e');
    if (e == std::string::npos) return text;
    int exponent = std::atoi(text.c_str() + e + 1);
    return trimZeros(text.substr(0, e)) + "e" + std::to_string(exponent);
}

/// UTF-8 code points, not bytes, so that accented names do not get twice the room.
std::size_t codePoints(const std::string& text) {
    std::size_t points = 0;
    for (unsigned char c : text) {
        if ((c & 0xC0) != 0x80) ++points;
    }
    return points;
}

/// Width in pixels of a text at a font size, close enough to reserve margins.
double textWidth(const std::string& text, double fontSize) {
    return static_cast<double>(codePoints(text)) * fontSize * kCharWidthPerFontSize;
}

/// Shortens a text to at most maxPoints code points, ending in "...", never splitting a code
/// point (a split multi-byte sequence would not be valid UTF-8).
std::string shorten(const std::string& text, std::size_t maxPoints) {
    std::size_t points = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;
        if (points == maxPoints) {
            std::size_t keep = i;
            // Walk back over three more code points to make room for the ellipsis.
            for (int dropped = 0; dropped < 3 && keep > 0;) {
                --keep;
                if ((static_cast<unsigned char>(text[keep]) & 0xC0) != 0x80) ++dropped;
            }
            return text.substr(0, keep) + "...";
        }
        ++points;
    }
    return text;
}

// ---------------------------------------------------------------------------------------------
// Axes

/// One axis: its range and ticks in axis units, which are the values themselves or, on a log
/// axis, their base-10 logarithms (so 10^-324 and 10^308 both map without overflow).
struct Axis {
    bool log = false;
    double lo = 0.0;
    double hi = 1.0;
    std::vector<double> ticks;
    std::vector<std::string> labels;
    std::vector<double> minorTicks;

    /// Axis units of a finite value; on a log axis values <= 0 sit on the lower edge.
    double unitOf(double value) const {
        if (log) return value > 0.0 ? std::max(std::log10(value), lo) : lo;
        return std::clamp(value, -kMaxLinearValue, kMaxLinearValue);
    }
    /// 0 at the lower edge, 1 at the upper one.
    double fraction(double value) const { return (unitOf(value) - lo) / (hi - lo); }
};

/// Collects the range of the values an axis has to show.
struct Range {
    bool any = false;
    double min = 0.0;
    double max = 0.0;
    void add(double value) {
        if (!std::isfinite(value)) return;
        if (!any) {
            min = max = value;
            any = true;
        } else {
            min = std::min(min, value);
            max = std::max(max, value);
        }
    }
};

// At most this many ticks on a linear axis; the step sequence 1, 2, 2.5, 5 grows by at most a
// factor of two, so the first step that fits gives between about 4 and 8 ticks.
constexpr double kMaxTicks = 8.0;

// A linear range narrower than this fraction of its magnitude is treated as a single value: the
// ticks could not be told apart in double precision.
constexpr double kRelativeFlatness = 1.0e-9;

/// A linear axis over `range`, widened by `pad` times its span on each side first.
Axis linearAxis(Range range, double pad = 0.0) {
    Axis axis;
    double lo = 0.0;
    double hi = 1.0;
    if (range.any) {
        lo = std::clamp(range.min, -kMaxLinearValue, kMaxLinearValue);
        hi = std::clamp(range.max, -kMaxLinearValue, kMaxLinearValue);
        double margin = pad * (hi - lo);
        lo = std::max(lo - margin, -kMaxLinearValue);
        hi = std::min(hi + margin, kMaxLinearValue);
        double magnitude = std::max(std::fabs(lo), std::fabs(hi));
        // Spans below kTinySpan would put the tick step among denormals, where pow and log10
        // lose their precision; such values are all but zero anyway.
        constexpr double kTinySpan = 1.0e-250;
        if (hi - lo <= kRelativeFlatness * magnitude || hi - lo < kTinySpan) {
            // One value (or nearly): widen it so the line sits in the middle of a real range.
            double centre = 0.5 * (lo + hi);
            double halfWidth = std::fabs(centre) > kTinySpan ? 0.1 * std::fabs(centre) : 1.0;
            lo = centre - halfWidth;
            hi = centre + halfWidth;
        }
    }
    double span = hi - lo;
    constexpr double kMultipliers[] = {1.0, 2.0, 2.5, 5.0};
    int exponent = static_cast<int>(std::floor(std::log10(span / 10.0)));
    double step = 1.0;
    double kLo = 0.0;
    double kHi = 1.0;
    int decimalsBonus = 0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        double multiplier = kMultipliers[attempt % 4];
        int e = exponent + attempt / 4;
        step = multiplier * std::pow(10.0, e);
        // The small tolerance keeps a value like 0.30000000000000004 from adding a tick.
        kLo = std::floor(lo / step + 1.0e-9);
        kHi = std::ceil(hi / step - 1.0e-9);
        if (kHi - kLo + 1.0 <= kMaxTicks) {
            exponent = e;
            decimalsBonus = multiplier == 2.5 ? 1 : 0;
            break;
        }
    }
    axis.lo = kLo * step;
    axis.hi = kHi * step;
    if (!(axis.hi > axis.lo)) axis.hi = axis.lo + step;

    double largest = std::max(std::fabs(axis.lo), std::fabs(axis.hi));
    bool useScientific = largest >= 1.0e5 || step < 1.0e-3;
    for (double k = kLo; k <= kHi; k += 1.0) {
        double value = k * step;
        axis.ticks.push_back(value);
        std::string label;
        if (k == 0.0) {
            label = "0";
        } else if (useScientific) {
            // Enough mantissa digits to tell this tick from its neighbours.
            int valueExponent = static_cast<int>(std::floor(std::log10(std::fabs(value))));
            label = scientific(value, valueExponent - exponent + decimalsBonus);
        } else {
            char buffer[64];
            int decimals = std::max(0, -exponent + decimalsBonus);
            std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
            label = trimZeros(buffer);
        }
        axis.labels.push_back(label);
    }
    return axis;
}

// A log axis has at most this many decade ticks; wider ones label every n-th decade, n taken
// from a short list of round strides.
constexpr double kMaxDecadeTicks = 8.0;

/// A log10 axis over the positive values of `range` (decade ticks 1e-6, 1e-5, ...), widened by
/// `pad` times its span in decades on each side first.
Axis logAxis(Range positive, double pad = 0.0) {
    Axis axis;
    axis.log = true;
    double lo = 0.0;
    double hi = 1.0;
    if (positive.any) {
        double low = std::log10(positive.min);
        double high = std::log10(positive.max);
        double margin = pad * (high - low);
        lo = std::floor(low - margin);
        hi = std::ceil(high + margin);
        // A single decade value such as exactly 1e-3: centre it in a two-decade range.
        if (hi <= lo) {
            lo -= 1.0;
            hi += 1.0;
        }
    }
    double stride = 1.0;
    for (double candidate : {1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0}) {
        stride = candidate;
        if (std::ceil(hi / stride) - std::floor(lo / stride) + 1.0 <= kMaxDecadeTicks) break;
    }
    lo = std::floor(lo / stride) * stride;
    hi = std::ceil(hi / stride) * stride;
    axis.lo = lo;
    axis.hi = hi;
    // Plain numbers read better for 0.001 ... 10000; outside that every label is scientific so
    // one axis never mixes the two styles.
    bool plain = lo >= -3.0 && hi <= 4.0;
    for (double k = lo; k <= hi; k += stride) {
        axis.ticks.push_back(k);
        if (plain) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%.*f", k < 0.0 ? static_cast<int>(-k) : 0,
                          std::pow(10.0, k));
            axis.labels.push_back(buffer);
        } else {
            axis.labels.push_back("1e" + std::to_string(static_cast<long long>(k)));
        }
        // Unlabelled ticks at 2..9 times each decade, when decades are few enough to show them.
        if (stride == 1.0 && hi - lo <= 8.0 && k < hi) {
            for (int m = 2; m <= 9; ++m) axis.minorTicks.push_back(k + std::log10(m));
        }
    }
    return axis;
}

Axis makeAxis(bool log, const Range& all, const Range& positive, double pad) {
    return log ? logAxis(positive, pad) : linearAxis(all, pad);
}

// ---------------------------------------------------------------------------------------------
// Plot frame: the part shared by the line and the scatter plot

struct LegendEntry {
    std::string name;
    int colour = 0;
    bool line = true;  // a line sample (line plot) or a dot (scatter plot)
};

constexpr double kTitleFont = 15.0;
constexpr double kLabelFont = 12.0;
constexpr double kTickFont = 11.0;
constexpr double kLegendFont = 11.0;
constexpr double kLegendRow = 16.0;     // px between legend entries
constexpr double kLegendSample = 22.0;  // px of line sample before the name
constexpr double kTickLength = 5.0;

/// Where the plot area lies in the document, and how values map into it.
struct Frame {
    double left = 0.0;
    double top = 0.0;
    double width = 1.0;
    double height = 1.0;
    Axis x;
    Axis y;

    double px(double value) const { return left + x.fraction(value) * width; }
    double py(double value) const { return top + (1.0 - y.fraction(value)) * height; }
};

struct Layout {
    Frame frame;
    double legendLeft = 0.0;
    double legendColumnWidth = 0.0;
    int legendRows = 0;
    std::size_t legendNameChars = 0;
};

std::string openSvg(int width, int height) {
    std::string w = integer(width);
    std::string h = integer(height);
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
           "\" viewBox=\"0 0 " + w + " " + h + "\" font-family=\"sans-serif\">\n<rect x=\"0\" " +
           "y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"#ffffff\"/>\n";
}

std::string textElement(const std::string& cssClass, double x, double y, const std::string& text,
                        const std::string& extra = "") {
    return "<text class=\"" + cssClass + "\" x=\"" + num(x) + "\" y=\"" + num(y) + "\"" + extra +
           ">" + escapeXml(text) + "</text>\n";
}

double widestLabel(const Axis& axis) {
    double widest = 0.0;
    for (const std::string& label : axis.labels) {
        widest = std::max(widest, textWidth(label, kTickFont));
    }
    return widest;
}

/// Places the plot area between the title, the tick labels, the axis labels and the legend.
Layout layOut(int width, int height, bool hasTitle, bool hasXLabel, bool hasYLabel, Axis x, Axis y,
              const std::vector<LegendEntry>& legend) {
    Layout layout;
    double top = hasTitle ? 34.0 : 14.0;
    double bottom = 8.0 + kTickLength + kTickFont + (hasXLabel ? 8.0 + kLabelFont + 4.0 : 4.0);
    double left = 10.0 + widestLabel(y) + kTickLength + (hasYLabel ? kLabelFont + 10.0 : 0.0);
    // The last x label is centred on the right edge: leave room for its right half.
    double right = 10.0 + (x.labels.empty() ? 0.0 : 0.5 * textWidth(x.labels.back(), kTickFont));

    double plotHeight = std::max(20.0, height - top - bottom);
    if (!legend.empty()) {
        std::size_t widestName = 0;
        for (const LegendEntry& entry : legend) {
            widestName = std::max(widestName, codePoints(entry.name));
        }
        layout.legendRows = std::max(1, static_cast<int>(plotHeight / kLegendRow));
        int columns = static_cast<int>((legend.size() + layout.legendRows - 1) /
                                       static_cast<std::size_t>(layout.legendRows));
        // The legend may take at most 40% of the width; longer names are shortened to fit.
        double maxColumn = std::max(60.0, 0.4 * width / columns);
        double column = kLegendSample + 14.0 + textWidth(std::string(widestName, 'n'), kLegendFont);
        layout.legendColumnWidth = std::min(column, maxColumn);
        layout.legendNameChars = widestName;
        if (column > maxColumn) {
            layout.legendNameChars = static_cast<std::size_t>(
                (maxColumn - kLegendSample - 14.0) / (kLegendFont * kCharWidthPerFontSize));
        }
        right = std::max(right, 12.0 + columns * layout.legendColumnWidth);
    }
    Frame& frame = layout.frame;
    frame.left = left;
    frame.top = top;
    frame.width = std::max(20.0, width - left - right);
    frame.height = plotHeight;
    frame.x = std::move(x);
    frame.y = std::move(y);
    layout.legendLeft = frame.left + frame.width + 12.0;
    return layout;
}

/// Title, grid, ticks with labels, frame and axis labels.
std::string drawAxes(const Layout& layout, int width, const std::string& title,
                     const std::string& xLabel, const std::string& yLabel) {
    const Frame& f = layout.frame;
    std::string out;
    if (!title.empty()) {
        out += textElement(
            "title", 0.5 * width, 22.0, title,
            " text-anchor=\"middle\" font-size=\"" + num(kTitleFont) + "\" font-weight=\"bold\"");
    }
    double right = f.left + f.width;
    double bottom = f.top + f.height;

    out += "<g class=\"grid\" stroke=\"#e6e6e6\" stroke-width=\"1\">\n";
    for (double t : f.x.ticks) {
        double x = f.left + (t - f.x.lo) / (f.x.hi - f.x.lo) * f.width;
        out += "<line x1=\"" + num(x) + "\" y1=\"" + num(f.top) + "\" x2=\"" + num(x) + "\" y2=\"" +
               num(bottom) + "\"/>\n";
    }
    for (double t : f.y.ticks) {
        double y = bottom - (t - f.y.lo) / (f.y.hi - f.y.lo) * f.height;
        out += "<line x1=\"" + num(f.left) + "\" y1=\"" + num(y) + "\" x2=\"" + num(right) +
               "\" y2=\"" + num(y) + "\"/>\n";
    }
    out += "</g>\n";

    out += "<g class=\"x-ticks\" font-size=\"" + num(kTickFont) +
           "\" text-anchor=\"middle\" fill=\"#333333\">\n";
    for (std::size_t i = 0; i < f.x.ticks.size(); ++i) {
        double x = f.left + (f.x.ticks[i] - f.x.lo) / (f.x.hi - f.x.lo) * f.width;
        out += "<line x1=\"" + num(x) + "\" y1=\"" + num(bottom) + "\" x2=\"" + num(x) +
               "\" y2=\"" + num(bottom + kTickLength) + "\" stroke=\"#333333\"/>\n";
        out += "<text x=\"" + num(x) + "\" y=\"" + num(bottom + kTickLength + kTickFont + 2.0) +
               "\">" + escapeXml(f.x.labels[i]) + "</text>\n";
    }
    for (double t : f.x.minorTicks) {
        double x = f.left + (t - f.x.lo) / (f.x.hi - f.x.lo) * f.width;
        out += "<line x1=\"" + num(x) + "\" y1=\"" + num(bottom) + "\" x2=\"" + num(x) +
               "\" y2=\"" + num(bottom + 0.6 * kTickLength) + "\" stroke=\"#333333\"/>\n";
    }
    out += "</g>\n";

    out += "<g class=\"y-ticks\" font-size=\"" + num(kTickFont) +
           "\" text-anchor=\"end\" fill=\"#333333\">\n";
    for (std::size_t i = 0; i < f.y.ticks.size(); ++i) {
        double y = bottom - (f.y.ticks[i] - f.y.lo) / (f.y.hi - f.y.lo) * f.height;
        out += "<line x1=\"" + num(f.left - kTickLength) + "\" y1=\"" + num(y) + "\" x2=\"" +
               num(f.left) + "\" y2=\"" + num(y) + "\" stroke=\"#333333\"/>\n";
        out += "<text x=\"" + num(f.left - kTickLength - 3.0) + "\" y=\"" +
               num(y + 0.35 * kTickFont) + "\">" + escapeXml(f.y.labels[i]) + "</text>\n";
    }
    for (double t : f.y.minorTicks) {
        double y = bottom - (t - f.y.lo) / (f.y.hi - f.y.lo) * f.height;
        out += "<line x1=\"" + num(f.left - 0.6 * kTickLength) + "\" y1=\"" + num(y) + "\" x2=\"" +
               num(f.left) + "\" y2=\"" + num(y) + "\" stroke=\"#333333\"/>\n";
    }
    out += "</g>\n";

    out += "<rect class=\"plot-frame\" x=\"" + num(f.left) + "\" y=\"" + num(f.top) +
           "\" width=\"" + num(f.width) + "\" height=\"" + num(f.height) +
           "\" fill=\"none\" stroke=\"#333333\"/>\n";
    if (!xLabel.empty()) {
        out += textElement("x-label", f.left + 0.5 * f.width,
                           bottom + kTickLength + kTickFont + 8.0 + kLabelFont, xLabel,
                           " text-anchor=\"middle\" font-size=\"" + num(kLabelFont) + "\"");
    }
    if (!yLabel.empty()) {
        double x = 6.0 + kLabelFont;
        double y = f.top + 0.5 * f.height;
        out += textElement("y-label", x, y, yLabel,
                           " text-anchor=\"middle\" font-size=\"" + num(kLabelFont) +
                               "\" transform=\"rotate(-90 " + num(x) + " " + num(y) + ")\"");
    }
    return out;
}

std::string drawLegend(const Layout& layout, const std::vector<LegendEntry>& legend) {
    if (legend.empty()) return "";
    std::string out =
        "<g class=\"legend\" font-size=\"" + num(kLegendFont) + "\" fill=\"#222222\">\n";
    for (std::size_t i = 0; i < legend.size(); ++i) {
        const LegendEntry& entry = legend[i];
        std::size_t column = i / static_cast<std::size_t>(layout.legendRows);
        std::size_t row = i % static_cast<std::size_t>(layout.legendRows);
        double x = layout.legendLeft + static_cast<double>(column) * layout.legendColumnWidth;
        double y = layout.frame.top + 8.0 + static_cast<double>(row) * kLegendRow;
        const char* colour = colourOf(entry.colour);
        if (entry.line) {
            out += "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" +
                   num(x + kLegendSample - 4.0) + "\" y2=\"" + num(y) + "\" stroke=\"" + colour +
                   "\" stroke-width=\"2\"" + dashAttribute(entry.colour) + "/>\n";
        } else {
            out += "<circle cx=\"" + num(x + 0.5 * (kLegendSample - 4.0)) + "\" cy=\"" + num(y) +
                   "\" r=\"3.5\" fill=\"" + colour + "\"/>\n";
        }
        std::string name = shorten(entry.name, std::max<std::size_t>(4, layout.legendNameChars));
        out += "<text x=\"" + num(x + kLegendSample) + "\" y=\"" + num(y + 0.35 * kLegendFont) +
               "\">" + escapeXml(name) + "</text>\n";
    }
    out += "</g>\n";
    return out;
}

// Documents smaller than this (px) leave no room for a plot; the renderers enlarge them.
constexpr int kMinPlotWidth = 160;
constexpr int kMinPlotHeight = 120;

bool finitePoint(double x, double y) {
    return std::isfinite(x) && std::isfinite(y);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Line plot

std::string renderLinePlot(const LinePlot& plot, int width, int height) {
    width = std::max(width, kMinPlotWidth);
    height = std::max(height, kMinPlotHeight);

    Range xs;
    Range ys;
    Range positiveYs;
    for (const Series& s : plot.series) {
        for (const auto& [x, y] : s.points) {
            if (!finitePoint(x, y)) continue;
            xs.add(x);
            ys.add(y);
            if (y > 0.0) positiveYs.add(y);
        }
    }
    std::vector<LegendEntry> legend;
    for (std::size_t i = 0; i < plot.series.size(); ++i) {
        legend.push_back({plot.series[i].name, static_cast<int>(i), true});
    }
    Layout layout =
        layOut(width, height, !plot.title.empty(), !plot.xLabel.empty(), !plot.yLabel.empty(),
               linearAxis(xs), makeAxis(plot.logY, ys, positiveYs, 0.0), legend);
    const Frame& f = layout.frame;

    std::string out = openSvg(width, height);
    out += drawAxes(layout, width, plot.title, plot.xLabel, plot.yLabel);
    out +=
        "<g class=\"series\" fill=\"none\" stroke-width=\"1.6\" stroke-linejoin=\"round\" "
        "stroke-linecap=\"round\">\n";
    for (std::size_t i = 0; i < plot.series.size(); ++i) {
        const Series& s = plot.series[i];
        int index = static_cast<int>(i);
        const char* colour = colourOf(index);
        // Each run of finite points becomes one polyline; a lone point also gets a dot, since a
        // one-point polyline draws nothing.
        std::string points;
        int runLength = 0;
        double lastX = 0.0;
        double lastY = 0.0;
        auto flush = [&]() {
            if (runLength == 0) return;
            out += "<polyline points=\"" + points + "\" stroke=\"" + colour + "\"" +
                   dashAttribute(index) + "/>\n";
            if (runLength == 1) {
                out += "<circle cx=\"" + num(lastX) + "\" cy=\"" + num(lastY) +
                       "\" r=\"2.5\" fill=\"" + colour + "\" stroke=\"none\"/>\n";
            }
            points.clear();
            runLength = 0;
        };
        for (const auto& [x, y] : s.points) {
            if (!finitePoint(x, y)) {
                flush();
                continue;
            }
            lastX = f.px(x);
            lastY = f.py(y);
            if (runLength > 0) points += ' ';
            points += num(lastX) + "," + num(lastY);
            ++runLength;
        }
        flush();
    }
    out += "</g>\n";
    out += drawLegend(layout, legend);
    out += "</svg>\n";
    return out;
}

// ---------------------------------------------------------------------------------------------
// Scatter plot

// A scatter plot's axes reach this fraction of the data's span beyond it, so that points at the
// extremes are not cut in half by the frame (a line plot's curves may touch it).
constexpr double kScatterPad = 0.04;

std::string renderScatterPlot(const ScatterPlot& plot, int width, int height) {
    width = std::max(width, kMinPlotWidth);
    height = std::max(height, kMinPlotHeight);

    Range xs;
    Range ys;
    Range positiveXs;
    Range positiveYs;
    std::vector<std::string> groups;  // in order of first appearance
    std::vector<int> groupOf;
    for (const ScatterPoint& p : plot.points) {
        auto found = std::find(groups.begin(), groups.end(), p.group);
        groupOf.push_back(static_cast<int>(found - groups.begin()));
        if (found == groups.end()) groups.push_back(p.group);
        if (!finitePoint(p.x, p.y)) continue;
        xs.add(p.x);
        ys.add(p.y);
        if (p.x > 0.0) positiveXs.add(p.x);
        if (p.y > 0.0) positiveYs.add(p.y);
    }
    std::vector<LegendEntry> legend;
    for (std::size_t i = 0; i < groups.size(); ++i) {
        // An unnamed group (all points of an ungrouped plot) needs no legend entry.
        if (!groups[i].empty()) legend.push_back({groups[i], static_cast<int>(i), false});
    }
    Layout layout = layOut(width, height, !plot.title.empty(), !plot.xLabel.empty(),
                           !plot.yLabel.empty(), makeAxis(plot.logX, xs, positiveXs, kScatterPad),
                           makeAxis(plot.logY, ys, positiveYs, kScatterPad), legend);
    const Frame& f = layout.frame;

    std::string out = openSvg(width, height);
    out += drawAxes(layout, width, plot.title, plot.xLabel, plot.yLabel);
    out += "<g class=\"points\" stroke=\"#ffffff\" stroke-width=\"0.8\">\n";
    for (std::size_t i = 0; i < plot.points.size(); ++i) {
        const ScatterPoint& p = plot.points[i];
        if (!finitePoint(p.x, p.y)) continue;
        out += "<circle cx=\"" + num(f.px(p.x)) + "\" cy=\"" + num(f.py(p.y)) +
               "\" r=\"4\" fill=\"" + colourOf(groupOf[i]) + "\"/>\n";
    }
    out += "</g>\n";
    out += "<g class=\"point-labels\" font-size=\"10\" fill=\"#333333\">\n";
    for (const ScatterPoint& p : plot.points) {
        if (p.label.empty() || !finitePoint(p.x, p.y)) continue;
        out += "<text x=\"" + num(f.px(p.x) + 6.0) + "\" y=\"" + num(f.py(p.y) - 5.0) + "\">" +
               escapeXml(p.label) + "</text>\n";
    }
    out += "</g>\n";
    out += drawLegend(layout, legend);
    out += "</svg>\n";
    return out;
}

// ---------------------------------------------------------------------------------------------
// Snapshot strip

namespace {

// A joint whose anchors are further apart than this (m) gets a red line between them. A fifth
// of the linear slop: joints are solved well below the slop, so a gap this size is real.
constexpr double kJointHair = 1.0e-3;

// Blank space around the union of the frames' contents, as a fraction of its larger side.
constexpr double kWorldMargin = 0.06;

constexpr double kStripGap = 12.0;      // px between panels and around the strip
constexpr double kStripTitle = 30.0;    // px for the title row
constexpr double kStripCaption = 20.0;  // px for the captions under the panels

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

bool drawable(const SnapshotFrame::CircleShape& c) {
    return finite(c.center) && std::isfinite(c.radius);
}

bool drawable(const SnapshotFrame::PolygonShape& p) {
    if (p.vertices.empty()) return false;
    return std::all_of(p.vertices.begin(), p.vertices.end(), [](Vec2 v) { return finite(v); });
}

/// World (m, y up) to panel pixels (y down), one scale for every panel.
struct WorldView {
    double centreX = 0.0;
    double centreY = 0.0;
    double scale = 1.0;  // px per m
    double panelWidth = 1.0;
    double panelHeight = 1.0;

    double px(double x) const { return 0.5 * panelWidth + (x - centreX) * scale; }
    double py(double y) const { return 0.5 * panelHeight - (y - centreY) * scale; }
};

WorldView fitView(const std::vector<SnapshotFrame>& frames, std::pair<Vec2, Vec2> view,
                  double panelWidth, double panelHeight) {
    double minX = 0.0;
    double minY = 0.0;
    double maxX = 0.0;
    double maxY = 0.0;
    bool useView = view.second.x > view.first.x && view.second.y > view.first.y &&
                   finite(view.first) && finite(view.second);
    if (useView) {
        minX = view.first.x;
        minY = view.first.y;
        maxX = view.second.x;
        maxY = view.second.y;
    } else {
        Range xs;
        Range ys;
        for (const SnapshotFrame& frame : frames) {
            for (const auto& c : frame.circles) {
                if (!drawable(c)) continue;
                double r = std::fabs(static_cast<double>(c.radius));
                xs.add(c.center.x - r);
                xs.add(c.center.x + r);
                ys.add(c.center.y - r);
                ys.add(c.center.y + r);
            }
            for (const auto& p : frame.polygons) {
                if (!drawable(p)) continue;
                for (Vec2 v : p.vertices) {
                    xs.add(v.x);
                    ys.add(v.y);
                }
            }
            for (const auto& [a, b] : frame.joints) {
                for (Vec2 v : {a, b}) {
                    if (!finite(v)) continue;
                    xs.add(v.x);
                    ys.add(v.y);
                }
            }
        }
        if (xs.any) {
            minX = xs.min;
            maxX = xs.max;
            minY = ys.min;
            maxY = ys.max;
        }
        double side = std::max(maxX - minX, maxY - minY);
        if (side > 1.0e-9) {
            double margin = kWorldMargin * side;
            minX -= margin;
            maxX += margin;
            minY -= margin;
            maxY += margin;
        } else {
            // Nothing, or everything at one point: show a metre either side of it.
            minX -= 1.0;
            maxX += 1.0;
            minY -= 1.0;
            maxY += 1.0;
        }
    }
    WorldView w;
    w.panelWidth = panelWidth;
    w.panelHeight = panelHeight;
    w.centreX = 0.5 * (minX + maxX);
    w.centreY = 0.5 * (minY + maxY);
    double scaleX = panelWidth / (maxX - minX);
    double scaleY = panelHeight / (maxY - minY);
    w.scale = std::min(scaleX, scaleY);
    if (!std::isfinite(w.scale) || w.scale <= 0.0) w.scale = 1.0;
    return w;
}

std::string drawFrameContents(const SnapshotFrame& frame, const WorldView& w) {
    std::string out;
    for (const auto& p : frame.polygons) {
        if (!drawable(p)) continue;
        std::string d;
        for (std::size_t i = 0; i < p.vertices.size(); ++i) {
            d += (i == 0 ? "M" : " L") + num(w.px(p.vertices[i].x)) + "," +
                 num(w.py(p.vertices[i].y));
        }
        d += " Z";
        out += "<path class=\"" + std::string(p.isStatic ? "static" : "dynamic") + "\" d=\"" + d +
               "\"/>\n";
    }
    for (const auto& c : frame.circles) {
        if (!drawable(c)) continue;
        double r = std::fabs(static_cast<double>(c.radius)) * w.scale;
        double x = w.px(c.center.x);
        double y = w.py(c.center.y);
        out += "<circle class=\"" + std::string(c.isStatic ? "static" : "dynamic") + "\" cx=\"" +
               num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(r) + "\"/>\n";
        if (std::isfinite(c.angle)) {
            double angle = static_cast<double>(c.angle);
            // Minus sin: the world's y is up, the document's down.
            out += "<line class=\"radius\" x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" +
                   num(x + r * std::cos(angle)) + "\" y2=\"" + num(y - r * std::sin(angle)) +
                   "\"/>\n";
        }
    }
    for (std::size_t k = 0; k < frame.joints.size(); ++k) {
        const auto& [a, b] = frame.joints[k];
        if (!finite(a) || !finite(b)) continue;
        double gap = std::hypot(static_cast<double>(b.x) - a.x, static_cast<double>(b.y) - a.y);
        const bool link = k < frame.separations.size();
        if (link && gap > kJointHair) {
            // A rod or rope between the anchors, drawn under them.
            out += "<line x1=\"" + num(w.px(a.x)) + "\" y1=\"" + num(w.py(a.y)) + "\" x2=\"" +
                   num(w.px(b.x)) + "\" y2=\"" + num(w.py(b.y)) +
                   "\" stroke=\"#7f8c8d\" stroke-width=\"1.2\"/>\n";
        }
        out += "<circle class=\"anchor\" cx=\"" + num(w.px(a.x)) + "\" cy=\"" + num(w.py(a.y)) +
               "\" r=\"2.2\"/>\n";
        out += "<circle class=\"anchor\" cx=\"" + num(w.px(b.x)) + "\" cy=\"" + num(w.py(b.y)) +
               "\" r=\"2.2\"/>\n";
        if (link) gap = frame.separations[k];
        if (gap > kJointHair) {
            // Drawn over the dots with round caps, so even a gap far below a pixel shows red.
            out += "<line class=\"separation\" x1=\"" + num(w.px(a.x)) + "\" y1=\"" +
                   num(w.py(a.y)) + "\" x2=\"" + num(w.px(b.x)) + "\" y2=\"" + num(w.py(b.y)) +
                   "\"/>\n";
        }
    }
    return out;
}

}  // namespace

std::string renderSnapshotStrip(const std::string& title, const std::vector<SnapshotFrame>& frames,
                                std::pair<Vec2, Vec2> view, int frameWidth, int frameHeight) {
    frameWidth = std::max(frameWidth, 40);
    frameHeight = std::max(frameHeight, 40);
    double count = static_cast<double>(std::max<std::size_t>(frames.size(), 1));
    int width = static_cast<int>(std::ceil(count * frameWidth + (count + 1.0) * kStripGap));
    int height = static_cast<int>(std::ceil(kStripTitle + frameHeight + kStripCaption + kStripGap));
    WorldView w = fitView(frames, view, frameWidth, frameHeight);

    std::string out = openSvg(width, height);
    // Styles as presentation attributes on groups would need one group per class; a style sheet
    // keeps each shape element short.
    out +=
        "<defs>\n<style>"
        ".static{fill:#c9c9c9;stroke:#6b6b6b;stroke-width:1}"
        ".dynamic{fill:#a6cbe8;stroke:#1f5a8a;stroke-width:1}"
        ".radius{stroke:#1f3550;stroke-width:1}"
        ".anchor{fill:#222222}"
        ".separation{stroke:#e3120b;stroke-width:1.8;stroke-linecap:round}"
        "</style>\n<clipPath id=\"pivot-panel-clip\"><rect x=\"0\" y=\"0\" width=\"" +
        integer(frameWidth) + "\" height=\"" + integer(frameHeight) + "\"/></clipPath>\n</defs>\n";
    if (!title.empty()) {
        out += textElement(
            "title", 0.5 * width, 21.0, title,
            " text-anchor=\"middle\" font-size=\"" + num(kTitleFont) + "\" font-weight=\"bold\"");
    }
    for (std::size_t i = 0; i < frames.size(); ++i) {
        double left = kStripGap + static_cast<double>(i) * (frameWidth + kStripGap);
        out += "<g class=\"panel\" transform=\"translate(" + num(left) + " " + num(kStripTitle) +
               ")\">\n";
        out += "<rect x=\"0\" y=\"0\" width=\"" + integer(frameWidth) + "\" height=\"" +
               integer(frameHeight) + "\" fill=\"#fcfcfc\" stroke=\"#888888\"/>\n";
        out += "<g clip-path=\"url(#pivot-panel-clip)\">\n";
        out += drawFrameContents(frames[i], w);
        out += "</g>\n";
        out += textElement("caption", 0.5 * frameWidth, frameHeight + 15.0, frames[i].caption,
                           " text-anchor=\"middle\" font-size=\"12\"");
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

// ---------------------------------------------------------------------------------------------
// XML

std::string escapeXml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            case '\t':
            case '\n':
            case '\r': out += c; break;
            default:
                // Other control characters are not allowed anywhere in XML 1.0, not even
                // escaped: dropping them keeps the document valid.
                if (static_cast<unsigned char>(c) >= 0x20) out += c;
        }
    }
    return out;
}

namespace {

/// A recursive-descent reader of the XML subset the figures use; it stops at the first problem
/// and remembers what and where.
class XmlChecker {
public:
    explicit XmlChecker(const std::string& document) : doc_(document) {}

    bool check() {
        if (startsWith("<?xml") && pos_ + 5 < doc_.size() &&
            (isSpace(doc_[pos_ + 5]) || doc_[pos_ + 5] == '?')) {
            if (!declaration()) return false;
        }
        if (!misc()) return false;
        if (pos_ >= doc_.size()) return fail(pos_, "no root element");
        if (doc_[pos_] != '<') return fail(pos_, "text before the root element");
        if (!element()) return false;
        if (!misc()) return false;
        if (pos_ < doc_.size()) {
            if (doc_[pos_] == '<' && pos_ + 1 < doc_.size() && isNameStart(doc_[pos_ + 1])) {
                return fail(pos_, "a second root element");
            }
            return fail(pos_, "content after the root element");
        }
        return true;
    }

    const std::string& problem() const { return problem_; }

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    static bool isNameStart(char c) {
        auto u = static_cast<unsigned char>(c);
        return (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == '_' || u == ':' ||
               u >= 0x80;
    }
    static bool isNameChar(char c) {
        return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
    }

    bool fail(std::size_t at, const std::string& what) {
        problem_ = "offset " + std::to_string(at) + ": " + what;
        return false;
    }

    bool startsWith(const char* text) const {
        return pos_ <= doc_.size() &&
               doc_.compare(pos_, std::char_traits<char>::length(text), text) == 0;
    }

    bool skipSpace() {
        std::size_t start = pos_;
        while (pos_ < doc_.size() && isSpace(doc_[pos_])) ++pos_;
        return pos_ > start;
    }

    /// Characters XML 1.0 forbids outright: control characters other than tab and line breaks.
    bool checkChar(std::size_t at) {
        auto u = static_cast<unsigned char>(doc_[at]);
        if (u < 0x20 && !isSpace(doc_[at])) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X", u);
            return fail(at, std::string("control character ") + code + " is not allowed");
        }
        return true;
    }

    bool name(std::string* out) {
        std::size_t start = pos_;
        if (pos_ >= doc_.size() || !isNameStart(doc_[pos_])) return false;
        while (pos_ < doc_.size() && isNameChar(doc_[pos_])) ++pos_;
        *out = doc_.substr(start, pos_ - start);
        return true;
    }

    /// Whitespace and comments, before or after the root element.
    bool misc() {
        for (;;) {
            skipSpace();
            if (startsWith("<!--")) {
                if (!comment()) return false;
            } else if (startsWith("<?")) {
                return fail(pos_,
                            "processing instructions (and an XML declaration that is not "
                            "at the very start) are not supported");
            } else if (startsWith("<!")) {
                return fail(pos_, "DOCTYPE and other declarations are not supported");
            } else {
                return true;
            }
        }
    }

    bool comment() {
        std::size_t start = pos_;
        pos_ += 4;
        for (; pos_ < doc_.size(); ++pos_) {
            if (startsWith("--")) {
                if (pos_ + 2 < doc_.size() && doc_[pos_ + 2] == '>') {
                    pos_ += 3;
                    return true;
                }
                return fail(pos_, "'--' inside a comment");
            }
            if (!checkChar(pos_)) return false;
        }
        return fail(start, "unterminated comment");
    }

    bool declaration() {
        std::size_t start = pos_;
        pos_ += 5;
        std::vector<std::string> names;
        for (;;) {
            bool spaced = skipSpace();
            if (startsWith("?>")) {
                pos_ += 2;
                break;
            }
            if (pos_ >= doc_.size()) return fail(start, "unterminated XML declaration");
            if (!spaced) return fail(pos_, "expected whitespace or '?>' in the XML declaration");
            if (!attribute(&names)) return false;
        }
        if (names.empty() || names.front() != "version") {
            return fail(start, "the XML declaration must begin with version=\"...\"");
        }
        return true;
    }

    /// name = "value" or name = 'value', with a duplicate check against the element's others.
    bool attribute(std::vector<std::string>* seen) {
        std::size_t start = pos_;
        std::string attributeName;
        if (!name(&attributeName)) return fail(pos_, "expected an attribute name");
        if (std::find(seen->begin(), seen->end(), attributeName) != seen->end()) {
            return fail(start, "duplicate attribute '" + attributeName + "'");
        }
        seen->push_back(attributeName);
        skipSpace();
        if (pos_ >= doc_.size() || doc_[pos_] != '=') {
            return fail(pos_, "attribute '" + attributeName + "' has no '=' and value");
        }
        ++pos_;
        skipSpace();
        if (pos_ >= doc_.size() || (doc_[pos_] != '"' && doc_[pos_] != '\'')) {
            return fail(pos_, "the value of attribute '" + attributeName + "' is not quoted");
        }
        char quote = doc_[pos_++];
        while (pos_ < doc_.size() && doc_[pos_] != quote) {
            if (doc_[pos_] == '<') return fail(pos_, "'<' inside an attribute value");
            if (doc_[pos_] == '&') {
                if (!reference()) return false;
                continue;
            }
            if (!checkChar(pos_)) return false;
            ++pos_;
        }
        if (pos_ >= doc_.size()) {
            return fail(start, "unterminated value of attribute '" + attributeName + "'");
        }
        ++pos_;
        return true;
    }

    /// &amp; &lt; &gt; &quot; &apos; &#123; &#x1F; and nothing else.
    bool reference() {
        std::size_t start = pos_;
        std::size_t end = doc_.find(';', pos_);
        // Real references are short; a far-away ';' means this '&' is bare.
        if (end == std::string::npos || end - pos_ > 12) {
            return fail(start, "'&' that does not start an entity reference");
        }
        std::string body = doc_.substr(pos_ + 1, end - pos_ - 1);
        pos_ = end + 1;
        if (body == "amp" || body == "lt" || body == "gt" || body == "quot" || body == "apos") {
            return true;
        }
        if (body.size() >= 2 && body[0] == '#') {
            bool hex = body[1] == 'x';
            std::string digits = body.substr(hex ? 2 : 1);
            const char* allowed = hex ? "0123456789abcdefABCDEF" : "0123456789";
            if (!digits.empty() && digits.size() <= 8 &&
                digits.find_first_not_of(allowed) == std::string::npos) {
                unsigned long code = std::strtoul(digits.c_str(), nullptr, hex ? 16 : 10);
                bool legal =
                    code == 0x9 || code == 0xA || code == 0xD || (code >= 0x20 && code <= 0xD7FF) ||
                    (code >= 0xE000 && code <= 0xFFFD) || (code >= 0x10000 && code <= 0x10FFFF);
                if (legal) return true;
                return fail(start, "character reference &" + body + "; is not a legal character");
            }
            return fail(start, "malformed character reference &" + body + ";");
        }
        return fail(start, "unknown entity &" + body + ";");
    }

    /// A start tag from '<'; sets *closed when it is self-closing.
    bool startTag(std::string* tagName, bool* closed) {
        std::size_t start = pos_;
        ++pos_;
        if (!name(tagName)) return fail(pos_, "expected an element name after '<'");
        std::vector<std::string> seen;
        for (;;) {
            bool spaced = skipSpace();
            if (pos_ >= doc_.size()) return fail(start, "unterminated start tag <" + *tagName);
            if (doc_[pos_] == '>') {
                ++pos_;
                *closed = false;
                return true;
            }
            if (startsWith("/>")) {
                pos_ += 2;
                *closed = true;
                return true;
            }
            if (!spaced || !isNameStart(doc_[pos_])) {
                return fail(pos_, "unexpected '" + std::string(1, doc_[pos_]) + "' in start tag <" +
                                      *tagName);
            }
            if (!attribute(&seen)) return false;
        }
    }

    /// The root element and everything inside it, with an explicit stack of open elements so
    /// deep nesting cannot overflow the call stack.
    bool element() {
        struct Open {
            std::string name;
            std::size_t at;
        };
        std::vector<Open> open;
        for (;;) {
            if (pos_ >= doc_.size()) {
                return fail(pos_, "<" + open.back().name + "> opened at offset " +
                                      std::to_string(open.back().at) + " is never closed");
            }
            char c = doc_[pos_];
            if (c == '<') {
                std::size_t at = pos_;
                if (startsWith("<!--")) {
                    if (!comment()) return false;
                } else if (startsWith("<![CDATA[")) {
                    std::size_t end = doc_.find("]]>", pos_);
                    if (end == std::string::npos) return fail(at, "unterminated CDATA section");
                    for (std::size_t i = pos_; i < end; ++i) {
                        if (!checkChar(i)) return false;
                    }
                    pos_ = end + 3;
                } else if (startsWith("</")) {
                    pos_ += 2;
                    std::string closing;
                    if (!name(&closing)) return fail(pos_, "expected an element name after '</'");
                    skipSpace();
                    if (pos_ >= doc_.size() || doc_[pos_] != '>') {
                        return fail(pos_, "expected '>' to end </" + closing);
                    }
                    ++pos_;
                    if (open.empty() || open.back().name != closing) {
                        return fail(at, open.empty()
                                            ? "end tag </" + closing + "> without a start"
                                            : "end tag </" + closing + "> does not match <" +
                                                  open.back().name + "> opened at offset " +
                                                  std::to_string(open.back().at));
                    }
                    open.pop_back();
                } else if (startsWith("<?")) {
                    return fail(at, "processing instructions are not supported");
                } else if (startsWith("<!")) {
                    return fail(at, "declarations are not allowed inside an element");
                } else {
                    std::string tagName;
                    bool closed = false;
                    if (!startTag(&tagName, &closed)) return false;
                    if (!closed) open.push_back({tagName, at});
                }
                if (open.empty()) return true;
            } else if (c == '&') {
                if (!reference()) return false;
            } else if (startsWith("]]>")) {
                return fail(pos_, "']]>' in text");
            } else {
                if (open.empty()) return fail(pos_, "text outside the root element");
                if (!checkChar(pos_)) return false;
                ++pos_;
            }
        }
    }

    const std::string& doc_;
    std::size_t pos_ = 0;
    std::string problem_;
};

}  // namespace

bool isWellFormedXml(const std::string& document, std::string* problem) {
    XmlChecker checker(document);
    bool ok = checker.check();
    if (!ok && problem != nullptr) *problem = checker.problem();
    return ok;
}

}  // namespace pivot::report
