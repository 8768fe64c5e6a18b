#include "report/run_matrix.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

#include "scenes/parts.h"

namespace pivot::report {

const std::vector<std::string>& iterationSweepScenes() {
    static const std::vector<std::string> scenes = {"chain", "bridge_heavy", "ragdoll"};
    return scenes;
}

const std::vector<std::string>& biasSweepScenes() {
    static const std::vector<std::string> scenes = {"bridge", "bridge_heavy", "weld_beam"};
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

// One configuration of the matrix.
struct Config {
    const scenes::SceneInfo* info = nullptr;
    PositionSolver solver = PositionSolver::FullNGS;
    float bias = 0.0f;
    int positionIterations = kBox2D241PositionIterations;
    bool withSnapshots = false;
};

// One trial of a configuration: its metrics and time series.
struct Trial {
    scenes::RunMetrics metrics;
    std::vector<float> maxSeparation;
    std::vector<float> jointMaxSeparation;
    std::vector<SnapshotFrame> snapshots;
    Vec2 origin;
    int positionJoints = 0;
};

bool holdsAPosition(JointType type) {
    return type != JointType::Friction && type != JointType::Motor;
}

Trial runTrial(const Config& config, int trial, int steps) {
    scenes::SceneOptions options;
    options.solver = config.solver;
    options.biasFactor = config.bias;
    options.perturbation = trialSeed(trial);
    scenes::Scene scene = scenes::buildScene(*config.info, options);
    Trial out;
    out.jointMaxSeparation.assign(scene.joints.size(), 0.0f);
    out.origin = scene.origin;
    for (JointId joint : scene.joints) {
        out.positionJoints += holdsAPosition(scene.world->jointType(joint)) ? 1 : 0;
    }

    scenes::RunSettings settings;
    settings.steps = steps;
    settings.positionIterations = config.positionIterations;
    const bool withSnapshots = config.withSnapshots && trial == 0;
    const int snapshotEvery = std::max(1, steps / 5);
    auto snapshot = [&](int stepsDone) {
        char caption[32];
        std::snprintf(caption, sizeof caption, "t = %.1f s", stepsDone / settings.hz);
        out.snapshots.push_back(captureFrame(*scene.world, caption));
    };
    if (withSnapshots) snapshot(0);
    out.metrics = scenes::runScene(scene, settings, [&](int step) {
        float worst = 0.0f;
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            float s = scene.world->jointSeparation(scene.joints[j]);
            if (!(s <= out.jointMaxSeparation[j])) out.jointMaxSeparation[j] = s;
            if (!(s <= worst)) worst = s;
        }
        out.maxSeparation.push_back(worst);
        if (withSnapshots && (step + 1) % snapshotEvery == 0) snapshot(step + 1);
    });
    return out;
}

// Element by element, the median over the trials that have the element (a run that blew up
// stops early, and a scene may add joints as it runs).
std::vector<float> medianSeries(const std::vector<Trial>& trials,
                                std::vector<float> Trial::*series) {
    std::size_t length = 0;
    for (const Trial& t : trials) length = std::max(length, (t.*series).size());
    std::vector<float> out(length);
    std::vector<double> values;
    for (std::size_t i = 0; i < length; ++i) {
        values.clear();
        for (const Trial& t : trials) {
            if (i < (t.*series).size()) values.push_back((t.*series)[i]);
        }
        out[i] = static_cast<float>(spreadOf(values).median);
    }
    return out;
}

RunRecord combine(const Config& config, std::vector<Trial>& trials) {
    RunRecord record;
    record.scene = config.info->name;
    record.solver = config.solver;
    record.bias = config.bias;
    record.positionIterations = config.positionIterations;
    for (const Trial& t : trials) record.trials.push_back(t.metrics);
    record.metrics = medianMetrics(record.trials);
    record.maxSeparation = medianSeries(trials, &Trial::maxSeparation);
    record.jointMaxSeparation = medianSeries(trials, &Trial::jointMaxSeparation);
    record.snapshots = std::move(trials.front().snapshots);
    record.origin = trials.front().origin;
    record.positionJoints = trials.front().positionJoints;
    return record;
}

}  // namespace

int RunRecord::torn() const {
    return tornCount(trials);
}

RunMatrix runMatrix(int steps, int threads,
                    const std::function<void(const std::string&)>& progress) {
    std::vector<Config> configs;
    std::vector<std::size_t> sceneStart;  // index of each scene's first configuration
    for (const scenes::SceneInfo& info : scenes::allScenes()) {
        sceneStart.push_back(configs.size());
        for (int s = 0; s < kPositionSolverCount; ++s) {
            auto solver = static_cast<PositionSolver>(s);
            bool velocityLevel =
                solver == PositionSolver::Baumgarte || solver == PositionSolver::PseudoVelocity;
            std::vector<float> biases = {defaultBiasFactor(solver)};
            const bool swept = std::find(biasSweepScenes().begin(), biasSweepScenes().end(),
                                         info.name) != biasSweepScenes().end();
            if (velocityLevel && swept) biases = sweptBiases();
            for (float bias : biases) {
                configs.push_back({&info, solver, bias, kBox2D241PositionIterations,
                                   solver == PositionSolver::FullNGS});
            }
        }
        if (std::find(iterationSweepScenes().begin(), iterationSweepScenes().end(), info.name) ==
            iterationSweepScenes().end()) {
            continue;
        }
        for (int s = 0; s < kPositionSolverCount; ++s) {
            auto solver = static_cast<PositionSolver>(s);
            for (int iterations : sweptIterations()) {
                if (iterations == kBox2D241PositionIterations) continue;  // a main run already
                configs.push_back({&info, solver, defaultBiasFactor(solver), iterations, false});
            }
        }
    }
    sceneStart.push_back(configs.size());

    // Jobs in the order the timings want: a scene at a time, within it trial by trial, every
    // configuration of the scene in each.
    struct Job {
        std::size_t config;
        int trial;
        bool firstOfScene;
    };
    std::vector<Job> jobs;
    for (std::size_t scene = 0; scene + 1 < sceneStart.size(); ++scene) {
        for (int trial = 0; trial < kTrials; ++trial) {
            for (std::size_t c = sceneStart[scene]; c < sceneStart[scene + 1]; ++c) {
                jobs.push_back({c, trial, trial == 0 && c == sceneStart[scene]});
            }
        }
    }
    std::vector<std::vector<Trial>> results(configs.size(), std::vector<Trial>(kTrials));
    std::mutex progressMutex;
    runJobs(jobs.size(), threads, [&](std::size_t i) {
        const Job& job = jobs[i];
        if (job.firstOfScene && progress) {
            std::lock_guard<std::mutex> lock(progressMutex);
            progress(configs[job.config].info->name);
        }
        results[job.config][job.trial] = runTrial(configs[job.config], job.trial, steps);
    });

    RunMatrix matrix;
    matrix.steps = steps;
    for (std::size_t c = 0; c < configs.size(); ++c) {
        matrix.runs.push_back(combine(configs[c], results[c]));
    }
    return matrix;
}

}  // namespace pivot::report
