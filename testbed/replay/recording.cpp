// Recording scene runs for the browser replay, drawn through World::debugDraw. Each run steps its
// own copy of the scene, so the four solvers start from identical worlds and differ only by what
// their joints do.
#include "replay/recording.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scenes/metrics.h"
#include "scenes/parts.h"

namespace pivot::replay {

namespace {

// The testbed's defaults (scenes::RunSettings), which recording.h promises.
constexpr float kHz = 60.0f;
constexpr int kVelocityIterations = kBox2D241VelocityIterations;  // 8
constexpr int kPositionIterations = kBox2D241PositionIterations;  // 3

// A body's outlines in its own frame, as World::debugDrawBody draws them at the identity.
class OutlineCapture final : public DebugDraw {
public:
    std::vector<Outline> outlines;

    void drawPolygon(const Vec2*, int, DebugColor) override {}
    void drawSolidPolygon(const Vec2* vertices, int count, float radius, DebugColor) override {
        add(ShapeType::Polygon, scenes::polygonOutline(vertices, count, radius));
    }
    void drawSolidCircle(Vec2 center, float radius, Vec2, DebugColor) override {
        Outline outline;
        outline.type = ShapeType::Circle;
        outline.center = center;
        outline.radius = radius;
        outlines.push_back(std::move(outline));
    }
    void drawSolidCapsule(Vec2 center1, Vec2 center2, float radius, DebugColor) override {
        // Drawn as its outline, as a rounded polygon.
        add(ShapeType::Polygon,
            scenes::polygonOutline(scenes::capsuleAsPolygon({center1, center2, radius})));
    }
    void drawSegment(Vec2 p1, Vec2 p2, DebugColor) override {
        // A chain's segments too: the replay shows where shapes are, not which side is solid.
        add(ShapeType::Segment, {p1, p2});
    }
    void drawPoint(Vec2, float, DebugColor) override {}

private:
    void add(ShapeType type, std::vector<Vec2> vertices) {
        Outline outline;
        outline.type = type;
        outline.vertices = std::move(vertices);
        outlines.push_back(std::move(outline));
    }
};

std::vector<Outline> outlinesOf(const World& world, BodyId body) {
    OutlineCapture capture;
    world.debugDrawBody(body, Transform{}, capture);
    return std::move(capture.outlines);
}

// The joints' anchors and separations, as World::debugDraw reports them.
class JointCapture final : public DebugDraw {
public:
    std::vector<float> anchors;
    std::vector<float> separations;
    bool links = false;

    void drawPolygon(const Vec2*, int, DebugColor) override {}
    void drawSolidPolygon(const Vec2*, int, float, DebugColor) override {}
    void drawSolidCircle(Vec2, float, Vec2, DebugColor) override {}
    void drawSolidCapsule(Vec2, Vec2, float, DebugColor) override {}
    void drawSegment(Vec2, Vec2, DebugColor) override {}
    void drawPoint(Vec2, float, DebugColor) override {}
    void drawJoint(JointId, JointType type, Vec2 a, Vec2 b, float separation, DebugColor) override {
        anchors.insert(anchors.end(), {a.x, a.y, b.x, b.y});
        separations.push_back(separation);
        links = links || type != JointType::Revolute;
    }
};

// Follows the bodies of one world from frame to frame. Bodies are matched by slot and then by
// the whole id, whose generation keeps a reused slot from passing for the body it held before.
class RunRecorder {
public:
    explicit RunRecorder(Run& run) : run_(run) {}

    void recordFrame(const World& world, int frame) {
        for (BodyId body : world.bodyIds()) {
            Track& track = trackOf(world, body, frame);
            Transform t = world.bodyTransform(body);
            track.poses.push_back(t.p.x);
            track.poses.push_back(t.p.y);
            track.poses.push_back(t.q.angle());
        }
        JointCapture joints;
        DebugDrawOptions options;
        options.shapes = false;
        world.debugDraw(joints, options);
        float maxSeparation = 0.0f;
        for (float separation : joints.separations) {
            if (!(separation <= maxSeparation)) maxSeparation = separation;  // NaN wins
        }
        run_.hasLinks = run_.hasLinks || joints.links;
        run_.jointAnchors.push_back(std::move(joints.anchors));
        run_.maxSeparation.push_back(maxSeparation);
        run_.jointSeparations.push_back(std::move(joints.separations));
    }

private:
    Track& trackOf(const World& world, BodyId body, int frame) {
        auto slot = static_cast<std::size_t>(body.index);
        if (slot >= bySlot_.size()) bySlot_.resize(slot + 1, kNoTrack);
        std::size_t& index = bySlot_[slot];
        if (index != kNoTrack && ids_[index] == body) return run_.tracks[index];
        index = run_.tracks.size();
        ids_.push_back(body);
        Track track;
        track.outlines = outlinesOf(world, body);
        track.isStatic = world.bodyType(body) == BodyType::Static;
        track.firstFrame = frame;
        run_.tracks.push_back(std::move(track));
        return run_.tracks.back();
    }

    static constexpr std::size_t kNoTrack = static_cast<std::size_t>(-1);
    Run& run_;
    std::vector<BodyId> ids_;          // parallel to run_.tracks
    std::vector<std::size_t> bySlot_;  // body slot -> its newest track, or kNoTrack
};

}  // namespace

Recording recordScene(const scenes::SceneInfo& info, int steps, int stepsPerFrame) {
    if (steps < 0 || stepsPerFrame < 1) {
        throw std::invalid_argument("recordScene: steps (" + std::to_string(steps) +
                                    ") must be >= 0 and stepsPerFrame (" +
                                    std::to_string(stepsPerFrame) + ") >= 1");
    }
    Recording recording;
    recording.scene = info.name;
    recording.description = info.description;
    recording.frameInterval = static_cast<float>(stepsPerFrame) / kHz;
    recording.frameCount = steps / stepsPerFrame + 1;

    for (int s = 0; s < kPositionSolverCount; ++s) {
        auto solver = static_cast<PositionSolver>(s);
        scenes::SceneOptions options;
        options.solver = solver;
        options.hz = kHz;
        scenes::Scene scene = scenes::buildScene(info, options);
        World& world = *scene.world;

        Run run;
        run.label = positionSolverName(solver);
        RunRecorder recorder(run);
        recorder.recordFrame(world, 0);
        // A run that blows up stops there and repeats its last state: stepping a world full of
        // NaNs or runaway speeds shows nothing more and only costs time.
        bool stopped = false;
        for (int i = 0; i < steps; ++i) {
            if (!stopped) {
                if (scene.beforeStep) scene.beforeStep(scene, i);
                world.step(1.0f / kHz, kVelocityIterations, kPositionIterations);
                stopped = scenes::isBlownUp(scene);
            }
            if ((i + 1) % stepsPerFrame == 0) recorder.recordFrame(world, (i + 1) / stepsPerFrame);
        }
        recording.runs.push_back(std::move(run));
    }
    return recording;
}

}  // namespace pivot::replay
