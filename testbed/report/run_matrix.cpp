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

SnapshotFrame captureFrame(const World& world, const std::string& caption) {
    SnapshotFrame frame;
    frame.caption = caption;
    for (BodyId body : world.bodyIds()) {
        Transform xf = world.bodyTransform(body);
        bool isStatic = world.bodyType(body) == BodyType::Static;
        for (ShapeId shape : world.bodyShapes(body)) {
            if (world.shapeType(shape) == ShapeType::Circle) {
                Circle c = world.shapeCircle(shape);
                frame.circles.push_back(
                    {transformPoint(xf, c.center), c.radius, world.bodyAngle(body), isStatic});
            } else if (world.shapeType(shape) == ShapeType::Segment ||
                       world.shapeType(shape) == ShapeType::ChainSegment) {
                const Segment s = world.shapeType(shape) == ShapeType::Segment
                                      ? world.shapeSegment(shape)
                                      : world.shapeChainSegment(shape).segment;
                SnapshotFrame::PolygonShape outline;  // two points: drawn as a line
                outline.isStatic = isStatic;
                outline.vertices = {transformPoint(xf, s.point1), transformPoint(xf, s.point2)};
                frame.polygons.push_back(outline);
            } else {
                Polygon p = world.shapeType(shape) == ShapeType::Capsule
                                ? scenes::capsuleAsPolygon(world.shapeCapsule(shape))
                                : world.shapePolygon(shape);
                SnapshotFrame::PolygonShape outline;
                outline.isStatic = isStatic;
                for (Vec2 v : scenes::polygonOutline(p)) {
                    outline.vertices.push_back(transformPoint(xf, v));
                }
                frame.polygons.push_back(outline);
            }
        }
    }
    bool links = false;
    for (JointId joint : world.jointIds()) {
        frame.joints.push_back({world.jointAnchorA(joint), world.jointAnchorB(joint)});
        frame.separations.push_back(world.jointSeparation(joint));
        links = links || world.jointType(joint) != JointType::Revolute;
    }
    if (!links) frame.separations.clear();  // every separation is the anchors' gap
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
