#include "metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pivot::scenes {

double mechanicalEnergy(const Scene& scene) {
    const World& world = *scene.world;
    const Vec2 g = world.gravity();
    double energy = 0.0;
    for (BodyId id : scene.bodies) {
        double m = world.bodyMass(id);
        double inertia = world.bodyRotationalInertia(id);
        Vec2 v = world.bodyLinearVelocity(id);
        double w = world.bodyAngularVelocity(id);
        Vec2 c = world.bodyWorldCenter(id);
        double kinetic = 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * inertia * w * w;
        double potential = -m * (double(g.x) * c.x + double(g.y) * c.y);
        energy += kinetic + potential;
    }
    return energy;
}

namespace {

template <typename Take>
SeparationSample sampleSeparationOf(const Scene& scene, Take take) {
    SeparationSample sample;
    for (JointId id : scene.joints) {
        if (!take(id)) continue;
        double s = scene.world->jointSeparation(id);
        if (!(s <= sample.max)) sample.max = s;  // NaN wins
        sample.sumSquares += s * s;
        ++sample.count;
    }
    return sample;
}

}  // namespace

SeparationSample sampleSeparation(const Scene& scene) {
    return sampleSeparationOf(scene, [](JointId) { return true; });
}

SeparationSample sampleSeparation(const Scene& scene, PositionSolver solver) {
    return sampleSeparationOf(
        scene, [&](JointId id) { return scene.world->jointPositionSolver(id) == solver; });
}

double limitViolation(const Scene& scene) {
    const World& world = *scene.world;
    double worst = 0.0;
    for (JointId id : scene.joints) {
        // Angle limits: a distance joint's length limit is part of its separation instead.
        if (world.jointType(id) != JointType::Revolute) continue;
        JointLimit limit = world.jointLimit(id);
        if (!limit.enabled) continue;
        double angle = world.jointAngle(id);
        worst = std::max({worst, double(limit.lower) - angle, angle - double(limit.upper)});
    }
    return worst;
}

bool isBlownUp(const Scene& scene) {
    const World& world = *scene.world;
    for (BodyId id : scene.bodies) {
        Vec2 p = world.bodyPosition(id);
        Vec2 v = world.bodyLinearVelocity(id);
        float a = world.bodyAngle(id);
        float w = world.bodyAngularVelocity(id);
        if (!isFinite(p) || !isFinite(v) || !std::isfinite(a) || !std::isfinite(w)) return true;
        if (length(v) > kRunawaySpeed) return true;
    }
    return false;
}

namespace {

// m, the deepest overlap among the world's touching contacts (0 when none overlaps).
double deepestPenetration(const World& world) {
    double deepest = 0.0;
    for (const ContactData& c : world.contacts()) {
        for (int p = 0; p < c.pointCount; ++p)
            deepest = std::max(deepest, -double(c.points[p].separation));
    }
    return deepest;
}

// m, the mass-weighted height of the scene's bodies along the world's gravity.
double centreOfMassHeight(const Scene& scene) {
    const World& world = *scene.world;
    const Vec2 g = world.gravity();
    const double gLength = std::sqrt(double(g.x) * g.x + double(g.y) * g.y);
    if (gLength == 0.0) return 0.0;
    double mass = 0.0, moment = 0.0;
    for (BodyId id : scene.bodies) {
        const double m = world.bodyMass(id);
        const Vec2 c = world.bodyWorldCenter(id);
        mass += m;
        moment -= m * (double(g.x) * c.x + double(g.y) * c.y) / gLength;
    }
    return mass > 0.0 ? moment / mass : 0.0;
}

}  // namespace

RunMetrics runScene(Scene& scene, const RunSettings& settings,
                    const std::function<void(int)>& afterStep) {
    using Clock = std::chrono::steady_clock;
    World& world = *scene.world;
    const float dt = 1.0f / settings.hz;

    RunMetrics m;
    m.energyStart = mechanicalEnergy(scene);
    const double heightStart = centreOfMassHeight(scene);
    double sumSquares = 0.0;
    long samples = 0;
    long positionIterations = 0;
    long extraPositionSolves = 0;
    Clock::duration stepTime{};
    int lastStepApart = -1;  // the last step after which some joint was beyond the slop
    double restSpeedSquares = 0.0;
    long restSamples = 0;
    const int settleFrom =
        settings.steps - static_cast<int>(kSettleSeconds * double(settings.hz) + 0.5);

    for (int i = 0; i < settings.steps; ++i) {
        if (scene.beforeStep) {
            // Bodies a scene adds bring their own energy: count it in the baseline, so the
            // drift measures only what the solver did.
            double before = mechanicalEnergy(scene);
            scene.beforeStep(scene, i);
            m.energyStart += mechanicalEnergy(scene) - before;
        }
        Clock::time_point start = Clock::now();
        world.step(dt, settings.velocityIterations, settings.positionIterations);
        stepTime += Clock::now() - start;
        ++m.steps;

        const StepStats& stats = world.lastStepStats();
        m.translationClamps += stats.translationClamps;
        m.rotationClamps += stats.rotationClamps;
        positionIterations += stats.positionIterations;
        extraPositionSolves += stats.extraPositionSolves;

        SeparationSample s = sampleSeparation(scene);
        if (!(s.max <= m.maxSeparation)) m.maxSeparation = s.max;
        sumSquares += s.sumSquares;
        samples += s.count;
        m.finalSeparation = s.max;
        for (JointId id : scene.sideJoints) {
            const double side = world.jointSeparation(id);
            if (!(side <= m.maxSideSeparation)) m.maxSideSeparation = side;  // NaN wins
        }
        if (i >= settleFrom && !(s.max <= m.settledSeparation)) m.settledSeparation = s.max;
        if (!(s.max <= kLinearSlop)) lastStepApart = i;
        m.maxLimitViolation = std::max(m.maxLimitViolation, limitViolation(scene));
        const double penetration = deepestPenetration(world);
        m.maxPenetration = std::max(m.maxPenetration, penetration);
        if (i >= settleFrom) m.settledPenetration = std::max(m.settledPenetration, penetration);
        for (BodyId id : scene.bodies) {
            m.maxSpeed = std::max(m.maxSpeed, double(length(world.bodyLinearVelocity(id))));
        }
        if (scene.restFromStep >= 0 && i >= scene.restFromStep) {
            for (BodyId id : scene.bodies) {
                restSpeedSquares += lengthSquared(world.bodyLinearVelocity(id));
                ++restSamples;
            }
        }
        if (afterStep) afterStep(i);
        if (isBlownUp(scene)) {
            m.blewUp = true;
            break;
        }
    }
    m.energyEnd = mechanicalEnergy(scene);
    m.heightLost = heightStart - centreOfMassHeight(scene);
    if (scene.disturbanceEndStep >= 0) {
        if (m.blewUp || lastStepApart == m.steps - 1) {
            m.recoverySeconds = RunMetrics::kNever;
        } else {
            int recovered = std::max(lastStepApart + 1, scene.disturbanceEndStep);
            m.recoverySeconds = double(recovered - scene.disturbanceEndStep) / settings.hz;
        }
    }
    if (restSamples > 0) m.jitter = std::sqrt(restSpeedSquares / double(restSamples));
    m.rmsSeparation = samples > 0 ? std::sqrt(sumSquares / double(samples)) : 0.0;
    m.meanPositionIterations = m.steps > 0 ? double(positionIterations) / m.steps : 0.0;
    m.meanExtraPositionSolves = m.steps > 0 ? double(extraPositionSolves) / m.steps : 0.0;
    m.microsecondsPerStep =
        m.steps > 0 ? std::chrono::duration<double, std::micro>(stepTime).count() / double(m.steps)
                    : 0.0;
    return m;
}

}  // namespace pivot::scenes
