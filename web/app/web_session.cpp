#include "web_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "scenes/metrics.h"
#include "scenes/parts.h"

namespace pivot::web {

namespace {

constexpr float kStepSeconds = 1.0f / 60.0f;

// Records World::debugDraw's calls as DrawCode commands.
class ListDraw final : public DebugDraw {
public:
    explicit ListDraw(std::vector<float>& out) : out_(out) {}

    void drawPolygon(const Vec2* vertices, int count, DebugColor color) override {
        for (int i = 0; i < count; ++i) drawSegment(vertices[i], vertices[(i + 1) % count], color);
    }
    void drawSolidPolygon(const Vec2* vertices, int count, float radius,
                          DebugColor color) override {
        begin(kPolygon, color);
        out_.push_back(radius);
        out_.push_back(static_cast<float>(count));
        for (int i = 0; i < count; ++i) push(vertices[i]);
    }
    void drawSolidCircle(Vec2 center, float radius, Vec2 axis, DebugColor color) override {
        begin(kCircle, color);
        push(center);
        out_.push_back(radius);
        push(axis);
    }
    void drawSolidCapsule(Vec2 center1, Vec2 center2, float radius, DebugColor color) override {
        begin(kCapsule, color);
        push(center1);
        push(center2);
        out_.push_back(radius);
    }
    void drawSegment(Vec2 p1, Vec2 p2, DebugColor color) override {
        begin(kSegment, color);
        push(p1);
        push(p2);
    }
    void drawPoint(Vec2 p, float size, DebugColor color) override {
        begin(kPoint, color);
        push(p);
        out_.push_back(size);
    }
    void drawJoint(JointId, JointType, Vec2 anchorA, Vec2 anchorB, float separation,
                   DebugColor color) override {
        begin(kJoint, color);
        push(anchorA);
        push(anchorB);
        out_.push_back(separation);
    }

private:
    void begin(DrawCode code, DebugColor color) {
        out_.push_back(static_cast<float>(code));
        out_.push_back(color.r);
        out_.push_back(color.g);
        out_.push_back(color.b);
    }
    void push(Vec2 v) {
        out_.push_back(v.x);
        out_.push_back(v.y);
    }

    std::vector<float>& out_;
};

}  // namespace

bool WebSession::load(int index, const WorldSettings& settings) {
    const auto& scenes = scenes::allScenes();
    if (index < 0 || index >= static_cast<int>(scenes.size())) {
        error_ = "no scene number " + std::to_string(index);
        return false;
    }
    scenes::SceneOptions options;
    options.solver = settings.solver;
    options.biasFactor = settings.bias;
    options.contactCorrection = settings.contacts;
    options.substepCount = settings.substeps;
    // Build into a fresh scene first: a def the engine refuses leaves the running one as it was.
    scenes::Scene built = scenes::buildScene(scenes[static_cast<std::size_t>(index)], options);
    scene_ = std::move(built);
    settings_ = settings;
    sceneIndex_ = index;
    stepIndex_ = 0;
    lastStepMs_ = 0.0;
    hand_.reset();
    error_.clear();
    return true;
}

void WebSession::setSettings(const WorldSettings& settings) {
    if (loaded()) {
        // Checked before anything changes: the world's own setters check each on its own.
        if (settings.velocityIterations < 0 || settings.velocityIterations > kMaxIterations ||
            settings.positionIterations < 0 || settings.positionIterations > kMaxIterations) {
            throw Error("iterations must be in [0, " + std::to_string(kMaxIterations) + "]");
        }
        world().setSubstepCount(settings.substeps);  // refuses, changing nothing, a bad count
        world().setContactCorrection(settings.contacts);
    }
    settings_ = settings;
}

void WebSession::step() {
    if (!scene_.world) return;
    const auto start = std::chrono::steady_clock::now();
    if (settings_.script && scene_.beforeStep) scene_.beforeStep(scene_, stepIndex_);
    // A scripted hand may have been let go by the script's own destroyMouseJoint; ours is
    // tracked separately, so check it is still there.
    if (hand_ && !world().isValid(*hand_)) hand_.reset();
    world().step(kStepSeconds, settings_.velocityIterations, settings_.positionIterations);
    const auto end = std::chrono::steady_clock::now();
    lastStepMs_ = std::chrono::duration<double, std::milli>(end - start).count();
    ++stepIndex_;
}

void WebSession::draw() {
    drawList_.clear();
    if (!scene_.world) return;
    ListDraw list(drawList_);
    world().debugDraw(list);
}

bool WebSession::grab(Vec2 point, float hertz, float forcePerKg) {
    if (!loaded()) {
        error_ = "no scene is loaded";
        return false;
    }
    release();
    const BodyId body = scenes::dynamicBodyAt(world(), point);
    if (!world().isValid(body)) return false;  // nothing to hold there: not an error
    MouseJointDef def;
    def.body = body;
    def.target = point;
    def.maxForce = forcePerKg * world().bodyMass(body);
    def.hertz = hertz;
    def.dampingRatio = 0.7f;
    hand_ = world().createMouseJoint(def);
    return true;
}

void WebSession::moveHand(Vec2 target) {
    if (hand_ && world().isValid(*hand_)) world().setMouseTarget(*hand_, target);
}

void WebSession::release() {
    if (hand_ && world().isValid(*hand_)) world().destroyMouseJoint(*hand_);
    hand_.reset();
}

JointId WebSession::joint(int i) const {
    if (i < 0 || i >= jointCount()) return JointId{};
    return scene_.joints[static_cast<std::size_t>(i)];
}

int WebSession::jointNear(Vec2 point, float radius) const {
    int nearest = -1;
    float best = radius;
    for (int i = 0; i < jointCount(); ++i) {
        const JointId id = joint(i);
        if (!world().isValid(id)) continue;
        for (Vec2 anchor : {world().jointAnchorA(id), world().jointAnchorB(id)}) {
            const float distance = length(anchor - point);
            if (distance <= best) {
                best = distance;
                nearest = i;
            }
        }
    }
    return nearest;
}

float WebSession::largestSeparation(PositionSolver solver) const {
    const scenes::SeparationSample sample = scenes::sampleSeparation(scene_, solver);
    return sample.count > 0 ? static_cast<float>(sample.max) : -1.0f;
}

}  // namespace pivot::web
