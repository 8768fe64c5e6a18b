// The browser replay page. Everything the page needs travels inside it: the recordings as one
// JSON block, the player as one inline script, system fonts only, so it opens from disk with no
// network. The page reports what it drew in <pre id="status"> for the headless-browser test.
#include "replay/html_replay.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "scenes/scene.h"

namespace pivot::replay {

namespace {

constexpr int kSteps = 600;
constexpr int kStepsPerFrame = 2;

// Poses and anchor A go as whole millimetres and milliradians (well under a pixel at any scale
// a scene is shown at), each written as its change since the previous frame: a few digits
// instead of "-12.345", which halves the page.
constexpr double kPoseQuanta = 1000.0;  // per m and per rad
// Anchor B goes as its offset from anchor A, in tenths of a millimetre and not delta coded: it
// is almost always 0, and it is the separation the page exists to show.
constexpr double kOffsetQuanta = 10000.0;  // per m
// Beyond this a value comes from a blow-up, and past 2^53 (9e15) the player's doubles would no
// longer add the deltas up exactly; such values are written null.
constexpr double kMaxQuanta = 1.0e15;
constexpr int kOutlineDecimals = 4;
// Separations span 1e-7 m to metres, so they keep significant digits, not decimals.
constexpr int kSeparationDigits = 3;

// JSON has no NaN or infinity; null tells the player to skip that value.
void appendFixed(std::string& out, float value, int decimals) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    char buffer[64];
    auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    if (ec != std::errc{}) {
        out += "null";
        return;
    }
    std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
    if (text.find('.') != std::string_view::npos) {
        while (text.back() == '0') text.remove_suffix(1);
        if (text.back() == '.') text.remove_suffix(1);
    }
    if (text == "-0") text = "0";
    out += text;
}

void appendSignificant(std::string& out, float value, int digits) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    char buffer[64];
    auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
    if (ec != std::errc{}) {
        out += "null";
        return;
    }
    // "1.5e-07" -> "1.5e-7": the padded exponent is valid JSON but costs bytes in every value.
    std::string text(buffer, end);
    std::size_t e = text.find('e');
    if (e != std::string::npos) {
        std::string mantissa = text.substr(0, e);
        char sign = text[e + 1];
        std::size_t digitsAt = text.find_first_not_of('0', e + 2);
        std::string exponent = digitsAt == std::string::npos ? "0" : text.substr(digitsAt);
        text = mantissa + "e" + (sign == '-' ? "-" : "") + exponent;
    }
    out += text;
}

// A JSON string that is also safe inside an HTML <script> element: every '<' (so no "</script"
// or "<!--") and every '>' and '&' become \u escapes, which JSON.parse turns back.
void appendJsonString(std::string& out, std::string_view text) {
    static const char kHex[] = "0123456789abcdef";
    out += '"';
    for (char ch : text) {
        auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20 || c == '<' || c == '>' || c == '&') {
            out += "\\u00";
            out += kHex[c >> 4];
            out += kHex[c & 0xF];
        } else {
            out += ch;
        }
    }
    out += '"';
}

std::string escapeHtml(std::string_view text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += ch;
        }
    }
    return out;
}

// `value` in whole quanta as its difference from `previous`, which it then replaces. A value
// that is not finite is written null and restarts its chain from 0, as the player expects.
void appendDelta(std::string& out, float value, double quanta, long long& previous) {
    double q = std::round(static_cast<double>(value) * quanta);
    if (!std::isfinite(q) || std::fabs(q) > kMaxQuanta) {
        out += "null";
        previous = 0;
        return;
    }
    auto n = static_cast<long long>(q);
    out += std::to_string(n - previous);
    previous = n;
}

void appendQuanta(std::string& out, float value, double quanta) {
    double q = std::round(static_cast<double>(value) * quanta);
    if (!std::isfinite(q) || std::fabs(q) > kMaxQuanta) {
        out += "null";
        return;
    }
    out += std::to_string(static_cast<long long>(q));
}

template <typename T, typename Append>
void appendArray(std::string& out, const std::vector<T>& values, Append append) {
    out += '[';
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) out += ',';
        append(values[i], i);
    }
    out += ']';
}

void appendOutline(std::string& out, const Outline& outline) {
    if (outline.type == ShapeType::Circle) {
        out += "{\"circle\":[";
        appendFixed(out, outline.center.x, kOutlineDecimals);
        out += ',';
        appendFixed(out, outline.center.y, kOutlineDecimals);
        out += ',';
        appendFixed(out, outline.radius, kOutlineDecimals);
        out += "]}";
        return;
    }
    out += "{\"polygon\":[";  // x, y of each vertex in one flat list
    for (std::size_t i = 0; i < outline.vertices.size(); ++i) {
        if (i > 0) out += ',';
        appendFixed(out, outline.vertices[i].x, kOutlineDecimals);
        out += ',';
        appendFixed(out, outline.vertices[i].y, kOutlineDecimals);
    }
    out += "]}";
}

void appendTrack(std::string& out, const Track& track) {
    out += "{\"static\":";
    out += track.isStatic ? "true" : "false";
    out += ",\"first\":" + std::to_string(track.firstFrame) + ",\"shapes\":";
    appendArray(out, track.outlines, [&](const Outline& o, std::size_t) { appendOutline(out, o); });
    out += ",\"poses\":";
    long long previous[3] = {0, 0, 0};  // x, y, angle
    appendArray(out, track.poses,
                [&](float v, std::size_t i) { appendDelta(out, v, kPoseQuanta, previous[i % 3]); });
    out += '}';
}

// `previous` holds anchor A of each joint slot in the frame before, and grows with 0s when a
// frame has more joints: the player keeps the same table.
void appendAnchors(std::string& out, const std::vector<float>& anchors,
                   std::vector<long long>& previous) {
    out += '[';
    for (std::size_t i = 0; i + 3 < anchors.size(); i += 4) {
        std::size_t slot = i / 2;
        if (previous.size() < slot + 2) previous.resize(slot + 2, 0);
        if (i > 0) out += ',';
        appendDelta(out, anchors[i], kPoseQuanta, previous[slot]);
        out += ',';
        appendDelta(out, anchors[i + 1], kPoseQuanta, previous[slot + 1]);
        out += ',';
        appendQuanta(out, anchors[i + 2] - anchors[i], kOffsetQuanta);
        out += ',';
        appendQuanta(out, anchors[i + 3] - anchors[i + 1], kOffsetQuanta);
    }
    out += ']';
}

void appendRun(std::string& out, const Run& run) {
    out += "{\"label\":";
    appendJsonString(out, run.label);
    out += ",\"maxSeparation\":";
    appendArray(out, run.maxSeparation,
                [&](float v, std::size_t) { appendSignificant(out, v, kSeparationDigits); });
    out += ",\"bodies\":";
    appendArray(out, run.tracks, [&](const Track& t, std::size_t) { appendTrack(out, t); });
    out += ",\"joints\":";
    std::vector<long long> previous;
    appendArray(out, run.jointAnchors,
                [&](const std::vector<float>& a, std::size_t) { appendAnchors(out, a, previous); });
    if (run.hasLinks) {
        out += ",\"separations\":";
        appendArray(out, run.jointSeparations, [&](const std::vector<float>& frame, std::size_t) {
            appendArray(out, frame,
                        [&](float v, std::size_t) { appendQuanta(out, v, kOffsetQuanta); });
        });
    }
    out += '}';
}

// The page's data:
//   {"slop": m, "poseQuantum": m, "offsetQuantum": m, "scenes": [{
//     "name", "description", "frameInterval": s, "frameCount",
//     "runs": [{
//       "label", "maxSeparation": [m, per frame],
//       "bodies": [{"static", "first": frame, "poses": [x, y, angle, ...],
//                   "shapes": [{"circle": [x, y, r]} or {"polygon": [x, y, x, y, ...]}]}],
//       "joints": [[ax, ay, bx, by, ...] per frame],
//       "separations": [[s, ...] per frame], only when some joint's anchors are meant to be
//                      apart (a distance joint), each joint's separation in offsetQuantum}]}]}
// Shapes are in m in the body frame. Poses and anchor A (ax, ay) count poseQuantum and are
// delta coded (appendDelta); (bx, by) is anchor B - anchor A in offsetQuantum.
std::string replayJson(const std::vector<Recording>& recordings) {
    std::string out = "{\"slop\":";
    appendSignificant(out, kLinearSlop, 6);
    out += ",\"poseQuantum\":";
    appendSignificant(out, static_cast<float>(1.0 / kPoseQuanta), 6);
    out += ",\"offsetQuantum\":";
    appendSignificant(out, static_cast<float>(1.0 / kOffsetQuanta), 6);
    out += ",\"scenes\":";
    appendArray(out, recordings, [&](const Recording& r, std::size_t) {
        out += "{\"name\":";
        appendJsonString(out, r.scene);
        out += ",\"description\":";
        appendJsonString(out, r.description);
        out += ",\"frameInterval\":";
        appendSignificant(out, r.frameInterval, 6);
        out += ",\"frameCount\":" + std::to_string(r.frameCount) + ",\"runs\":";
        appendArray(out, r.runs, [&](const Run& run, std::size_t) { appendRun(out, run); });
        out += '}';
    });
    out += '}';
    return out;
}

constexpr const char* kStyle = R"CSS(
body { margin: 16px; font: 14px/1.4 system-ui, sans-serif; color: #222; background: #fff; }
header { display: flex; align-items: baseline; gap: 12px; }
h1 { font-size: 18px; margin: 0; }
select { font: inherit; }
.description { margin: 4px 0 10px; color: #555; }
.grid { display: grid; gap: 10px; }
.label { display: flex; gap: 8px; align-items: center; margin-bottom: 2px; }
.label .name { font-weight: 600; }
.label .value { color: #555; font-variant-numeric: tabular-nums; }
.swatch { display: inline-block; width: 16px; height: 4px; }
canvas { display: block; border: 1px solid #ddd; }
.controls { display: flex; gap: 12px; align-items: center; margin: 10px 0 6px; }
.controls button { font: inherit; min-width: 5em; }
.controls input { flex: 1; }
.readout { font-variant-numeric: tabular-nums; min-width: 17em; }
.plot-title { color: #555; margin-bottom: 2px; }
#status { color: #999; font-size: 11px; }
)CSS";

// The player. It builds its own DOM from the data, so the HTML around it stays minimal, and it
// never writes the two characters '<' '/' next to each other, which would end the script early.
constexpr const char* kScript = R"JS(
(function () {
    'use strict';
    var BACKGROUND = [250, 250, 246];
    var BACKGROUND_CSS = 'rgb(250,250,246)';
    var RUN_COLORS = ['#c0392b', '#d68910', '#1e8449', '#2471a3', '#7d3c98', '#5d6d7e'];
    var BODY_FILLS = ['#9ec5e8', '#c9def2'];
    var WARM_UP_FRAMES = 3;
    var STATUS_EVERY = 30;
    var dpr = window.devicePixelRatio || 1;
    var data = JSON.parse(document.getElementById('replay-data').textContent);
    var app = document.getElementById('app');
    data.scenes.forEach(function (scene) { scene.runs.forEach(decodeRun); });
    var statusBox = document.getElementById('status');
    var state = {
        scene: null, views: [], canvases: [], values: [], plotRange: null, frame: 0,
        playing: true, framesDrawn: 0, warm: false, last: null, carry: 0, pending: false,
        token: 0
    };

    function make(tag, parent, className, text) {
        var e = document.createElement(tag);
        if (className) e.className = className;
        if (text !== undefined) e.textContent = text;
        if (parent) parent.appendChild(e);
        return e;
    }
    function num(v) { return typeof v === 'number' && isFinite(v); }
    function formatMetres(v) {
        if (!num(v)) return 'n/a';
        return v === 0 ? '0 m' : v.toExponential(1) + ' m';
    }

    // Undoes the delta coding of poses and of anchor A (described in html_replay.cpp).
    function decodeRun(run) {
        run.bodies.forEach(function (track) {
            var previous = [0, 0, 0];
            track.poses = track.poses.map(function (d, i) {
                if (d === null) { previous[i % 3] = 0; return null; }
                previous[i % 3] += d;
                return previous[i % 3] * data.poseQuantum;
            });
        });
        if (run.separations) {
            run.separations = run.separations.map(function (frame) {
                return frame.map(function (v) { return v === null ? null : v * data.offsetQuantum; });
            });
        }
        var slots = [];
        run.joints = run.joints.map(function (anchors) {
            return anchors.map(function (v, i) {
                if (i % 4 >= 2) return v === null ? null : v * data.offsetQuantum;
                var slot = (i >> 2) * 2 + (i % 4);
                if (v === null) { slots[slot] = 0; return null; }
                slots[slot] = (slots[slot] || 0) + v;
                return slots[slot] * data.poseQuantum;
            });
        });
    }

    // --- geometry -----------------------------------------------------------------------
    function poseAt(track, frame) {
        var k = frame - track.first;
        if (k < 0 || 3 * k + 2 >= track.poses.length) return null;
        var x = track.poses[3 * k], y = track.poses[3 * k + 1], a = track.poses[3 * k + 2];
        if (!num(x) || !num(y) || !num(a)) return null;
        return { x: x, y: y, a: a, c: Math.cos(a), s: Math.sin(a) };
    }
    function toWorld(p, lx, ly) { return [p.x + p.c * lx - p.s * ly, p.y + p.s * lx + p.c * ly]; }

    function emptyBox() { return { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity }; }
    function isEmpty(b) { return !(b.x0 <= b.x1 && b.y0 <= b.y1); }
    function grow(b, x, y, r) {
        if (!num(x) || !num(y)) return;
        r = r || 0;
        b.x0 = Math.min(b.x0, x - r); b.x1 = Math.max(b.x1, x + r);
        b.y0 = Math.min(b.y0, y - r); b.y1 = Math.max(b.y1, y + r);
    }
    function union(a, b) {
        return { x0: Math.min(a.x0, b.x0), y0: Math.min(a.y0, b.y0),
                 x1: Math.max(a.x1, b.x1), y1: Math.max(a.y1, b.y1) };
    }
    function intersect(a, b) {
        return { x0: Math.max(a.x0, b.x0), y0: Math.max(a.y0, b.y0),
                 x1: Math.min(a.x1, b.x1), y1: Math.min(a.y1, b.y1) };
    }
    function expand(b, m) { return { x0: b.x0 - m, y0: b.y0 - m, x1: b.x1 + m, y1: b.y1 + m }; }
    function extent(b) { return Math.max(b.x1 - b.x0, b.y1 - b.y0); }

    function growByBody(box, track, pose) {
        track.shapes.forEach(function (shape) {
            if (shape.circle) {
                var c = toWorld(pose, shape.circle[0], shape.circle[1]);
                grow(box, c[0], c[1], shape.circle[2]);
            } else {
                for (var i = 0; i + 1 < shape.polygon.length; i += 2) {
                    var v = toWorld(pose, shape.polygon[i], shape.polygon[i + 1]);
                    grow(box, v[0], v[1]);
                }
            }
        });
    }

    // What moves (over the whole run, anchors included) and each static body's box.
    function runBoxes(run, frameCount) {
        var moving = emptyBox(), fixed = [];
        run.bodies.forEach(function (track) {
            var box = track.static ? emptyBox() : moving;
            for (var f = track.first; f < frameCount; ++f) {
                var pose = poseAt(track, f);
                if (pose) growByBody(box, track, pose);
            }
            if (track.static && !isEmpty(box)) fixed.push(box);
        });
        run.joints.forEach(function (anchors) {
            for (var i = 0; i + 3 < anchors.length; i += 4) {
                grow(moving, anchors[i], anchors[i + 1]);
                grow(moving, anchors[i] + anchors[i + 2], anchors[i + 1] + anchors[i + 3]);
            }
        });
        return { moving: moving, fixed: fixed };
    }

    // The view is what moves plus a margin. Static bodies near it (the ground under a bridge)
    // stretch it, but only up to the moving range on an axis they already cover, so an 80 m
    // slab does not shrink a 30 m scene; far ones (a distant floor) are left out.
    function frameView(moving, fixed) {
        if (isEmpty(moving)) {
            var all = fixed.reduce(union, emptyBox());
            return isEmpty(all) ? { x0: -10, y0: -10, x1: 10, y1: 10 } : expand(all, 1);
        }
        var size = Math.max(extent(moving), 1);
        var near = expand(moving, 0.25 * size + 2);
        var view = expand(moving, 0.05 * size + 0.3);
        var clip = view;
        fixed.forEach(function (box) {
            var part = intersect(box, near);
            if (isEmpty(part)) return;
            if (part.x0 <= clip.x1 && part.x1 >= clip.x0) {
                part.x0 = Math.max(part.x0, clip.x0); part.x1 = Math.min(part.x1, clip.x1);
            }
            if (part.y0 <= clip.y1 && part.y1 >= clip.y0) {
                part.y0 = Math.max(part.y0, clip.y0); part.y1 = Math.min(part.y1, clip.y1);
            }
            view = union(view, part);
        });
        return view;
    }

    // One view shared by the runs, so they compare at a glance; a run whose bodies flew far
    // beyond the others' (a blow-up) gets its own instead of shrinking everyone else.
    function sceneViews(scene) {
        var boxes = scene.runs.map(function (run) { return runBoxes(run, scene.frameCount); });
        var sizes = boxes.filter(function (b) { return !isEmpty(b.moving); })
            .map(function (b) { return extent(b.moving); })
            .sort(function (a, b) { return a - b; });
        var median = sizes.length ? sizes[Math.floor((sizes.length - 1) / 2)] : 0;
        var outlier = boxes.map(function (b) {
            return !isEmpty(b.moving) && extent(b.moving) > 4 * median + 1;
        });
        var shared = emptyBox(), fixed = [];
        boxes.forEach(function (b, i) {
            if (!outlier[i]) { shared = union(shared, b.moving); fixed = fixed.concat(b.fixed); }
        });
        var sharedView = frameView(shared, fixed);
        return boxes.map(function (b, i) {
            return outlier[i] ? frameView(b.moving, b.fixed) : sharedView;
        });
    }

    // --- page ---------------------------------------------------------------------------
    var header = make('header', app);
    make('h1', header, '', 'pivot2d replay');
    var picker = null;
    if (data.scenes.length > 1) {
        picker = make('select', header);
        picker.setAttribute('aria-label', 'scene');
        data.scenes.forEach(function (s, i) { make('option', picker, '', s.name).value = i; });
        picker.addEventListener('change', function () { selectScene(Number(picker.value)); });
    }
    var sceneName = make('span', header, 'scene-name');
    var description = make('p', app, 'description');
    var grid = make('div', app, 'grid');
    var controls = make('div', app, 'controls');
    var playButton = make('button', controls, '', 'Pause');
    playButton.type = 'button';
    var scrub = make('input', controls);
    scrub.type = 'range';
    scrub.min = '0';
    scrub.step = '1';
    scrub.setAttribute('aria-label', 'frame');
    var readout = make('span', controls, 'readout');
    make('div', app, 'plot-title',
         'largest joint separation of each run (m, log scale) against time (s)');
    var plot = make('canvas', app, 'plot');

    function layout() {
        var scene = state.scene;
        if (!scene) return;
        var cols = Math.max(1, Math.ceil(Math.sqrt(scene.runs.length)));
        var available = Math.max(320, (document.documentElement.clientWidth || 960) - 34);
        var cellWidth = Math.min(640, Math.floor((available - 10 * (cols - 1)) / cols));
        var cellHeight = Math.round(cellWidth * 0.5);
        grid.style.gridTemplateColumns = 'repeat(' + cols + ', ' + (cellWidth + 2) + 'px)';
        state.canvases.forEach(function (c) { sizeCanvas(c, cellWidth, cellHeight); });
        var fullWidth = cols * (cellWidth + 2) + 10 * (cols - 1);
        controls.style.width = fullWidth + 'px';
        sizeCanvas(plot, fullWidth - 2, 190);
    }
    function sizeCanvas(canvas, width, height) {
        canvas.style.width = width + 'px';
        canvas.style.height = height + 'px';
        canvas.width = Math.round(width * dpr);
        canvas.height = Math.round(height * dpr);
    }

    function selectScene(index) {
        var scene = data.scenes[index];
        state.scene = scene;
        sceneName.textContent = picker ? '' : scene.name;
        description.textContent = scene.description;
        document.title = 'pivot2d replay: ' + scene.name;
        grid.textContent = '';
        state.canvases = [];
        state.values = [];
        scene.runs.forEach(function (run, i) {
            var cell = make('div', grid, 'cell');
            var label = make('div', cell, 'label');
            make('span', label, 'swatch').style.background = RUN_COLORS[i % RUN_COLORS.length];
            make('span', label, 'name', run.label);
            state.values.push(make('span', label, 'value'));
            var canvas = make('canvas', cell);
            canvas.setAttribute('aria-label', scene.name + ' with ' + run.label);
            state.canvases.push(canvas);
        });
        state.views = sceneViews(scene);
        state.plotRange = plotRange(scene);
        scrub.max = String(Math.max(0, scene.frameCount - 1));
        layout();
        state.carry = 0;
        setFrame(0);
    }

    // --- drawing ------------------------------------------------------------------------
    function drawRun(index) {
        var scene = state.scene, run = scene.runs[index], canvas = state.canvases[index];
        var view = state.views[index], frame = state.frame;
        var ctx = canvas.getContext('2d');
        var w = canvas.width, h = canvas.height;
        ctx.setTransform(1, 0, 0, 1, 0, 0);
        ctx.fillStyle = BACKGROUND_CSS;
        ctx.fillRect(0, 0, w, h);
        var k = Math.min(w / (view.x1 - view.x0), h / (view.y1 - view.y0));
        var ox = w / 2 - k * (view.x0 + view.x1) / 2, oy = h / 2 + k * (view.y0 + view.y1) / 2;
        function sx(x) { return ox + k * x; }
        function sy(y) { return oy - k * y; }
        ctx.lineWidth = dpr;
        ctx.lineJoin = 'round';

        // Static bodies first, muted, so what moves is drawn over them.
        [true, false].forEach(function (pass) {
            run.bodies.forEach(function (track, t) {
                if (track.static !== pass) return;
                var pose = poseAt(track, frame);
                if (!pose) return;
                ctx.fillStyle = pass ? '#dcdcd6' : BODY_FILLS[t % BODY_FILLS.length];
                ctx.strokeStyle = pass ? '#b4b4ac' : '#2e4a62';
                track.shapes.forEach(function (shape) {
                    ctx.beginPath();
                    if (shape.circle) {
                        var c = toWorld(pose, shape.circle[0], shape.circle[1]);
                        var r = shape.circle[2];
                        ctx.arc(sx(c[0]), sy(c[1]), Math.max(r * k, 1), 0, 2 * Math.PI);
                        ctx.fill();
                        ctx.stroke();
                        // The radius along the body's x axis shows how it turns.
                        ctx.beginPath();
                        ctx.moveTo(sx(c[0]), sy(c[1]));
                        ctx.lineTo(sx(c[0] + r * pose.c), sy(c[1] + r * pose.s));
                        ctx.stroke();
                        return;
                    }
                    var p = shape.polygon;
                    for (var i = 0; i + 1 < p.length; i += 2) {
                        var v = toWorld(pose, p[i], p[i + 1]);
                        if (i === 0) ctx.moveTo(sx(v[0]), sy(v[1]));
                        else ctx.lineTo(sx(v[0]), sy(v[1]));
                    }
                    ctx.closePath();
                    ctx.fill();
                    ctx.stroke();
                });
            });
        });

        // Joints: anchor A a filled dot, anchor B a ring; apart, a red segment joins them and
        // a red circle marks any joint beyond the slop even when the gap is under a pixel. A
        // joint whose anchors are meant to be apart (a distance joint) is a grey line, red only
        // where its separation is not zero.
        var anchors = run.joints[frame] || [];
        var separations = run.separations ? (run.separations[frame] || []) : null;
        for (var j = 0; j + 3 < anchors.length; j += 4) {
            var ax = anchors[j], ay = anchors[j + 1], dx = anchors[j + 2], dy = anchors[j + 3];
            if (!num(ax) || !num(ay) || !num(dx) || !num(dy)) continue;
            var x0 = sx(ax), y0 = sy(ay), x1 = sx(ax + dx), y1 = sy(ay + dy);
            var gap = Math.sqrt(dx * dx + dy * dy);
            if (separations) {
                ctx.strokeStyle = '#7f8c8d';
                ctx.lineWidth = dpr;
                ctx.beginPath();
                ctx.moveTo(x0, y0);
                ctx.lineTo(x1, y1);
                ctx.stroke();
                gap = num(separations[j / 4]) ? separations[j / 4] : 0;
            }
            if (gap !== 0) {
                ctx.strokeStyle = '#e01010';
                ctx.lineWidth = 2 * dpr;
                ctx.beginPath();
                ctx.moveTo(x0, y0);
                ctx.lineTo(x1, y1);
                ctx.stroke();
                if (gap > data.slop) {
                    ctx.lineWidth = dpr;
                    ctx.beginPath();
                    ctx.arc(x1, y1, 6 * dpr, 0, 2 * Math.PI);
                    ctx.stroke();
                }
            }
            ctx.lineWidth = dpr;
            ctx.fillStyle = '#1c2833';
            ctx.beginPath();
            ctx.arc(x0, y0, 2.5 * dpr, 0, 2 * Math.PI);
            ctx.fill();
            ctx.strokeStyle = '#1c2833';
            ctx.fillStyle = '#ffffff';
            ctx.beginPath();
            ctx.arc(x1, y1, 1.8 * dpr, 0, 2 * Math.PI);
            ctx.fill();
            ctx.stroke();
        }
        state.values[index].textContent = anchors.length === 0 ? 'no joints' :
            'largest separation ' + formatMetres(run.maxSeparation[frame]);
    }

    function plotRange(scene) {
        var lo = Infinity, hi = -Infinity;
        scene.runs.forEach(function (run) {
            run.maxSeparation.forEach(function (v) {
                if (num(v) && v > 0) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
            });
        });
        if (!(lo <= hi)) return { lo: -8, hi: -1 };
        var range = { lo: Math.max(-10, Math.floor(Math.log10(lo))),
                      hi: Math.max(Math.ceil(Math.log10(hi)), Math.ceil(Math.log10(data.slop))) };
        if (range.hi <= range.lo) range.hi = range.lo + 1;
        return range;
    }
    function niceStep(span) {
        var p = Math.pow(10, Math.floor(Math.log10(span)));
        var m = span / p;
        return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
    }
    function plotGeometry(scene) {
        var d = dpr;
        return { left: 58 * d, right: plot.width - 140 * d, top: 10 * d,
                 bottom: plot.height - 24 * d,
                 duration: Math.max(scene.frameInterval * (scene.frameCount - 1), 1e-9) };
    }

    function drawPlot() {
        var scene = state.scene, ctx = plot.getContext('2d'), d = dpr;
        var g = plotGeometry(scene), range = state.plotRange;
        function px(t) { return g.left + (g.right - g.left) * t / g.duration; }
        function py(v) {
            var l = Math.min(Math.max(Math.log10(v), range.lo), range.hi);
            return g.top + (g.bottom - g.top) * (range.hi - l) / (range.hi - range.lo);
        }
        ctx.setTransform(1, 0, 0, 1, 0, 0);
        ctx.fillStyle = '#ffffff';
        ctx.fillRect(0, 0, plot.width, plot.height);
        ctx.font = (11 * d) + 'px system-ui, sans-serif';
        ctx.lineWidth = d;

        var decades = range.hi - range.lo, every = Math.max(1, Math.ceil(decades / 8));
        ctx.textAlign = 'right';
        ctx.textBaseline = 'middle';
        for (var e = range.lo; e <= range.hi; e += every) {
            var y = py(Math.pow(10, e));
            ctx.strokeStyle = '#eeeeee';
            ctx.beginPath(); ctx.moveTo(g.left, y); ctx.lineTo(g.right, y); ctx.stroke();
            ctx.fillStyle = '#555555';
            ctx.fillText('1e' + e, g.left - 6 * d, y);
        }
        var tick = niceStep(g.duration / 8);
        ctx.textAlign = 'center';
        ctx.textBaseline = 'top';
        for (var t = 0; t <= g.duration + 1e-9; t += tick) {
            var x = px(t);
            ctx.strokeStyle = '#eeeeee';
            ctx.beginPath(); ctx.moveTo(x, g.top); ctx.lineTo(x, g.bottom); ctx.stroke();
            ctx.fillStyle = '#555555';
            ctx.fillText(String(Math.round(t * 100) / 100), x, g.bottom + 5 * d);
        }
        ctx.strokeStyle = '#999999';
        ctx.strokeRect(g.left, g.top, g.right - g.left, g.bottom - g.top);

        // The joint slop: NGS solvers stop correcting below it.
        var slopY = py(data.slop);
        ctx.setLineDash([4 * d, 4 * d]);
        ctx.strokeStyle = '#888888';
        ctx.beginPath(); ctx.moveTo(g.left, slopY); ctx.lineTo(g.right, slopY); ctx.stroke();
        ctx.setLineDash([]);
        ctx.fillStyle = '#777777';
        ctx.textAlign = 'left';
        ctx.textBaseline = 'bottom';
        ctx.fillText('slop', g.left + 4 * d, slopY - 2 * d);

        ctx.lineWidth = 1.5 * d;
        scene.runs.forEach(function (run, i) {
            ctx.strokeStyle = RUN_COLORS[i % RUN_COLORS.length];
            ctx.beginPath();
            var penDown = false;
            run.maxSeparation.forEach(function (v, f) {
                if (!num(v)) { penDown = false; return; }
                var x = px(f * scene.frameInterval), y = py(v);
                if (penDown) ctx.lineTo(x, y); else ctx.moveTo(x, y);
                penDown = true;
            });
            ctx.stroke();
        });

        ctx.textBaseline = 'middle';
        scene.runs.forEach(function (run, i) {
            var y = g.top + (8 + 16 * i) * d, x = g.right + 14 * d;
            ctx.strokeStyle = RUN_COLORS[i % RUN_COLORS.length];
            ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 18 * d, y); ctx.stroke();
            ctx.fillStyle = '#333333';
            ctx.fillText(run.label, x + 24 * d, y);
        });

        var cursor = px(state.frame * scene.frameInterval);
        ctx.lineWidth = d;
        ctx.strokeStyle = '#000000';
        ctx.beginPath(); ctx.moveTo(cursor, g.top); ctx.lineTo(cursor, g.bottom); ctx.stroke();
    }

    function drawAll() {
        var scene = state.scene;
        for (var i = 0; i < scene.runs.length; ++i) drawRun(i);
        drawPlot();
        var end = (scene.frameCount - 1) * scene.frameInterval;
        readout.textContent = 't = ' + (state.frame * scene.frameInterval).toFixed(2) + ' s of ' +
            end.toFixed(2) + ' s, frame ' + state.frame + ' of ' + (scene.frameCount - 1);
        state.framesDrawn += 1;
        if (state.warm && state.framesDrawn % STATUS_EVERY === 0) updateStatus();
    }

    // The test hook: frames drawn so far, and how many pixels of the first run's canvas differ
    // from the background, which only real drawing can change.
    function updateStatus() {
        var canvas = state.canvases[0], count = 0;
        if (canvas && canvas.width > 0 && canvas.height > 0) {
            var px = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
            for (var i = 0; i < px.length; i += 4) {
                if (px[i] !== BACKGROUND[0] || px[i + 1] !== BACKGROUND[1] ||
                    px[i + 2] !== BACKGROUND[2]) {
                    count += 1;
                }
            }
        }
        statusBox.textContent = 'frames-drawn: ' + state.framesDrawn + '; nonblank-pixels: ' +
            count;
    }

    // --- playback -----------------------------------------------------------------------
    function setFrame(frame) {
        var last = state.scene.frameCount - 1;
        state.frame = Math.max(0, Math.min(last, Math.round(frame)));
        scrub.value = String(state.frame);
        drawAll();
    }
    // Shows the last frame before wrapping round, however many frames a slow tick skipped.
    function advance(frames) {
        var last = state.scene.frameCount - 1;
        if (state.frame >= last) setFrame(0);
        else setFrame(Math.min(last, state.frame + frames));
    }
    // Real-time playback on animation frames: whole frames are taken off the time elapsed.
    function tick(now) {
        state.token += 1;
        state.pending = false;
        if (!state.playing) return;
        if (state.last !== null) {
            state.carry += (now - state.last) / 1000;
            var n = Math.floor(state.carry / state.scene.frameInterval);
            if (n > 0) {
                state.carry -= n * state.scene.frameInterval;
                advance(n);
            }
        }
        state.last = now;
        schedule();
    }
    // Animation frames stop in background tabs and in some headless browsers; a slower timer
    // keeps playback going there. Whichever comes first ticks, the other finds its token stale.
    function schedule() {
        if (state.pending || !state.playing || !state.warm) return;
        state.pending = true;
        var token = state.token;
        window.requestAnimationFrame(function (now) { if (token === state.token) tick(now); });
        window.setTimeout(function () {
            if (token === state.token) tick(window.performance.now());
        }, 100);
    }
    function play() {
        state.playing = true;
        state.last = null;
        state.carry = 0;
        playButton.textContent = 'Pause';
        if (state.frame >= state.scene.frameCount - 1) setFrame(0);
        schedule();
    }
    function pause() {
        state.playing = false;
        playButton.textContent = 'Play';
        if (state.warm) updateStatus();
    }
    // The first frames come from timers: a headless browser (or a background tab) may never
    // deliver animation frames, and the status must not depend on them.
    function warmUp(left) {
        if (left === 0) {
            state.warm = true;
            updateStatus();
            schedule();
            return;
        }
        window.setTimeout(function () {
            if (state.playing) advance(1);
            warmUp(left - 1);
        }, Math.max(16, 1000 * state.scene.frameInterval));
    }

    playButton.addEventListener('click', function () { if (state.playing) pause(); else play(); });
    scrub.addEventListener('input', function () {
        if (state.playing) pause();
        setFrame(Number(scrub.value));
    });
    function seekFromPlot(event) {
        var rect = plot.getBoundingClientRect(), g = plotGeometry(state.scene);
        var x = (event.clientX - rect.left) * dpr;
        var t = (x - g.left) / (g.right - g.left) * g.duration;
        if (state.playing) pause();
        setFrame(t / state.scene.frameInterval);
    }
    plot.addEventListener('mousedown', seekFromPlot);
    plot.addEventListener('mousemove', function (e) { if (e.buttons & 1) seekFromPlot(e); });
    document.addEventListener('keydown', function (e) {
        var tag = e.target && e.target.tagName;
        if (tag === 'INPUT' || tag === 'SELECT' || tag === 'BUTTON' || !state.scene) return;
        if (e.key === ' ') { if (state.playing) pause(); else play(); }
        else if (e.key === 'ArrowRight') { pause(); setFrame(state.frame + 1); }
        else if (e.key === 'ArrowLeft') { pause(); setFrame(state.frame - 1); }
        else return;
        e.preventDefault();
    });
    var resizeTimer = null;
    window.addEventListener('resize', function () {
        window.clearTimeout(resizeTimer);
        resizeTimer = window.setTimeout(function () { layout(); drawAll(); }, 100);
    });

    if (data.scenes.length === 0) {
        description.textContent = 'No recordings.';
        controls.style.display = 'none';
        return;
    }
    // "#scene=chain&frame=150" opens that scene paused at that frame (for screenshots, links).
    function fromHash(name) {
        var m = new RegExp('[#&]' + name + '=([^&]*)').exec(window.location.hash);
        return m ? decodeURIComponent(m[1]) : null;
    }
    var startScene = 0;
    data.scenes.forEach(function (s, i) { if (s.name === fromHash('scene')) startScene = i; });
    if (picker) picker.value = String(startScene);
    selectScene(startScene);
    if (fromHash('frame') !== null && isFinite(Number(fromHash('frame')))) {
        pause();
        setFrame(Number(fromHash('frame')));
    }
    warmUp(WARM_UP_FRAMES);
})();
)JS";

}  // namespace

std::string renderReplayHtml(const std::vector<Recording>& recordings) {
    std::string title = "pivot2d replay";
    for (std::size_t i = 0; i < recordings.size(); ++i) {
        title += (i == 0 ? ": " : ", ") + recordings[i].scene;
    }
    std::string html;
    html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    html += "<title>" + escapeHtml(title) + "</title>\n";
    html += "<style>";
    html += kStyle;
    html += "</style>\n</head>\n<body>\n";
    html += "<noscript>The replay needs JavaScript.</noscript>\n";
    html += "<div id=\"app\"></div>\n";
    html += "<pre id=\"status\">frames-drawn: 0; nonblank-pixels: 0</pre>\n";
    html += "<script type=\"application/json\" id=\"replay-data\">";
    html += replayJson(recordings);
    html += "</script>\n<script>";
    html += kScript;
    html += "</script>\n</body>\n</html>\n";
    return html;
}

std::string writeReplayFile(const std::string& path, const std::vector<std::string>& sceneNames) {
    if (sceneNames.empty()) return "no scenes to replay";
    std::vector<const scenes::SceneInfo*> infos;
    for (const std::string& name : sceneNames) {
        const scenes::SceneInfo* info = scenes::findScene(name);
        if (!info) {
            std::string valid;
            for (const scenes::SceneInfo& s : scenes::allScenes()) {
                valid += (valid.empty() ? "" : ", ") + std::string(s.name);
            }
            return "unknown scene '" + name + "'; valid scenes: " + valid;
        }
        infos.push_back(info);
    }
    std::vector<Recording> recordings;
    for (const scenes::SceneInfo* info : infos) {
        recordings.push_back(recordScene(*info, kSteps, kStepsPerFrame));
    }
    std::ofstream file(path, std::ios::binary);
    if (!file) return "cannot write " + path;
    file << renderReplayHtml(recordings);
    file.close();
    if (!file) return "cannot write " + path;
    return "";
}

}  // namespace pivot::replay
