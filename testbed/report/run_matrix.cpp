#include "report/run_matrix.h"

#include <cmath>
#include <cstdio>

#include "scenes/parts.h"

namespace pivot::report {

const std::vector<std::string>& iterationSweepScenes() {
    static const std::vector<std::string> scenes = {"chain", "bridge_heavy", "ragdoll"};
    return scenes;
}

const std::vector<float>& sweptBiases() {
    static const std::vector<float> biases = {0.1f, 0.2f, 0.5f, 1.0f};
    return biases;
}

const std::vector<int>& sweptIterations() {
    static const std::vector<int> iterations = {1, 2, 3, 5, 10};
    return iterations;
}

const RunRecord* RunMatrix::find(const std::string& scene, PositionSolver solver, float bias,
                                 int positionIterations) const {
    float wanted = bias < 0.0f ? defaultBiasFactor(solver) : bias;
    for (const RunRecord& r : runs) {
        if (r.scene == scene && r.solver == solver && r.bias == wanted &&
            r.positionIterations == positionIterations) {
            return &r;
        }
    }
    return nullptr;
}

namespace {

// The figures draw what World::debugDraw describes: shapes in a first pass, joints in a second,
// so that a pulley's rope segments are not taken for segment shapes.
class FrameCapture final : public DebugDraw {
public:
    explicit FrameCapture(SnapshotFrame& frame) : frame_(frame) {}

    void drawPolygon(const Vec2*, int, DebugColor) override {}
    void drawSolidPolygon(const Vec2* vertices, int count, float radius,
                          DebugColor color) override {
        addOutline(scenes::polygonOutline(vertices, count, radius), color);
    }
    void drawSolidCircle(Vec2 center, float radius, Vec2 axis, DebugColor color) override {
        frame_.circles.push_back(
            {center, radius, std::atan2(axis.y, axis.x), color == debug_colors::kStatic});
    }
    void drawSolidCapsule(Vec2 center1, Vec2 center2, float radius, DebugColor color) override {
        addOutline(scenes::polygonOutline(scenes::capsuleAsPolygon({center1, center2, radius})),
                   color);
    }
    void drawSegment(Vec2 p1, Vec2 p2, DebugColor color) override {
        if (shapesPass) addOutline({p1, p2}, color);  // two points: drawn as a line
    }
    void drawPoint(Vec2, float, DebugColor) override {}
    void drawJoint(JointId, JointType type, Vec2 anchorA, Vec2 anchorB, float separation,
                   DebugColor) override {
        frame_.joints.push_back({anchorA, anchorB});
        frame_.separations.push_back(separation);
        links_ = links_ || type != JointType::Revolute;
    }
    bool links() const { return links_; }
    bool shapesPass = true;  // the joints' pass draws a pulley's rope with segments: not shapes

private:
    void addOutline(std::vector<Vec2> vertices, DebugColor color) {
        SnapshotFrame::PolygonShape outline;
        outline.isStatic = color == debug_colors::kStatic;
        outline.vertices = std::move(vertices);
        frame_.polygons.push_back(std::move(outline));
    }

    SnapshotFrame& frame_;
    bool links_ = false;
};

}  // namespace

SnapshotFrame captureFrame(const World& world, const std::string& caption) {
    SnapshotFrame frame;
    frame.caption = caption;
    FrameCapture capture(frame);
    DebugDrawOptions shapes;
    shapes.joints = false;
    world.debugDraw(capture, shapes);
    DebugDrawOptions joints;
    joints.shapes = false;
    capture.shapesPass = false;
    world.debugDraw(capture, joints);
    if (!capture.links()) frame.separations.clear();  // every separation is the anchors' gap
    return frame;
}

namespace {

RunRecord runOne(const scenes::SceneInfo& info, PositionSolver solver, float bias,
                 int positionIterations, int steps, bool withSnapshots) {
    scenes::SceneOptions options;
    options.solver = solver;
    options.biasFactor = bias;
    scenes::Scene scene = scenes::buildScene(info, options);
    RunRecord record;
    record.scene = info.name;
    record.solver = solver;
    record.bias = bias;
    record.positionIterations = positionIterations;
    record.jointMaxSeparation.assign(scene.joints.size(), 0.0f);
    record.origin = scene.origin;

    scenes::RunSettings settings;
    settings.steps = steps;
    settings.positionIterations = positionIterations;
    const int snapshotEvery = std::max(1, steps / 5);
    auto snapshot = [&](int stepsDone) {
        char caption[32];
        std::snprintf(caption, sizeof caption, "t = %.1f s", stepsDone / settings.hz);
        record.snapshots.push_back(captureFrame(*scene.world, caption));
    };
    if (withSnapshots) snapshot(0);
    record.metrics = scenes::runScene(scene, settings, [&](int step) {
        float worst = 0.0f;
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            float s = scene.world->jointSeparation(scene.joints[j]);
            if (!(s <= record.jointMaxSeparation[j])) record.jointMaxSeparation[j] = s;
            if (!(s <= worst)) worst = s;
        }
        record.maxSeparation.push_back(worst);
        if (withSnapshots && (step + 1) % snapshotEvery == 0) snapshot(step + 1);
    });
    return record;
}

}  // namespace

RunMatrix runMatrix(int steps, const std::function<void(const std::string&)>& progress) {
    RunMatrix matrix;
    matrix.steps = steps;
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        if (progress) progress(info.name);
        for (int s = 0; s < kPositionSolverCount; ++s) {
            auto solver = static_cast<PositionSolver>(s);
            bool velocityLevel =
                solver == PositionSolver::Baumgarte || solver == PositionSolver::PseudoVelocity;
            std::vector<float> biases = {defaultBiasFactor(solver)};
            if (velocityLevel) biases = sweptBiases();
            for (float bias : biases) {
                matrix.runs.push_back(runOne(info, solver, bias, kDefaultPositionIterations, steps,
                                             solver == PositionSolver::FullNGS));
            }
        }
    }
    for (const std::string& name : iterationSweepScenes()) {
        const scenes::SceneInfo* info = scenes::findScene(name);
        if (!info) continue;
        for (int s = 0; s < kPositionSolverCount; ++s) {
            auto solver = static_cast<PositionSolver>(s);
            for (int iterations : sweptIterations()) {
                if (iterations == kDefaultPositionIterations) continue;  // a main run already
                matrix.runs.push_back(
                    runOne(*info, solver, defaultBiasFactor(solver), iterations, steps, false));
            }
        }
    }
    return matrix;
}

}  // namespace pivot::report
