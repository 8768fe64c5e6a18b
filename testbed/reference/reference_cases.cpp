#include "reference/reference_cases.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace pivot::reference {

namespace {
float flushDenormal(float value) {
    return std::fabs(value) < std::numeric_limits<float>::min() ? 0.0f : value;
}
}  // namespace

const std::vector<ReferenceCase>& referenceCases() {
    using scenes::Scene;
    using scenes::SceneOptions;
    static const std::vector<ReferenceCase> cases = {
        {"pendulum_1", false,
         [](Scene& s, const SceneOptions& o) { scenes::buildSpinningPendulum(s, o, 1.0f); },
         [](bool continuous) { return box2d::buildSpinningPendulum(1.0f, continuous); }},
        {"pendulum_10", false,
         [](Scene& s, const SceneOptions& o) { scenes::buildSpinningPendulum(s, o, 10.0f); },
         [](bool continuous) { return box2d::buildSpinningPendulum(10.0f, continuous); }},
        {"pendulum_100", false,
         [](Scene& s, const SceneOptions& o) { scenes::buildSpinningPendulum(s, o, 100.0f); },
         [](bool continuous) { return box2d::buildSpinningPendulum(100.0f, continuous); }},
        {"pendulum_limit", false, scenes::buildLimitedPendulum, box2d::buildLimitedPendulum},
        {"motor_wheel", false, scenes::buildMotorWheel, box2d::buildMotorWheel},
        {"distance_pendulum", false, scenes::buildDistancePendulum, box2d::buildDistancePendulum},
        {"pulley", false, scenes::buildPulley, box2d::buildPulley},
        {"top_down", false, scenes::buildTopDown, box2d::buildTopDown},
        {"motor_drive", false, scenes::buildMotorDrive, box2d::buildMotorDrive},
        {"elevator", false, scenes::buildElevator, box2d::buildElevator},
        {"weld_beam", false, scenes::buildWeldBeam, box2d::buildWeldBeam},
        {"gear_train", false, scenes::buildGearTrain, box2d::buildGearTrain},
        {"car", true, scenes::buildCar, box2d::buildCar, false},  // not bit for bit
        {"double_pendulum", true, scenes::buildDoublePendulum, box2d::buildDoublePendulum},
        {"bridge", true, scenes::buildBridge, box2d::buildBridge},
        {"chain", true, scenes::buildChain, box2d::buildChain},
        {"bridge_heavy", true, scenes::buildBridgeHeavy, box2d::buildBridgeHeavy},
    };
    return cases;
}

int comparedSteps(const ReferenceCase& c) {
    return c.chaotic ? 30 : 600;
}

void PrintTo(const ReferenceCase& c, std::ostream* out) {
    *out << c.name;
}

TrajectoryDifference compareTrajectories(const ReferenceCase& c,
                                         const scenes::SceneOptions& options, int steps,
                                         std::optional<bool> continuous) {
    const float dt = 1.0f / 60.0f;
    scenes::Scene ours = buildPivotCase(c, options);
    if (continuous) ours.world->setContinuousEnabled(*continuous);
    // Box2D's continuous collision on exactly where the pivot2d scene has it on.
    box2d::Box2dScene theirs = c.buildBox2d(ours.world->isContinuousEnabled());
    TrajectoryDifference d;
    for (int s = 0; s < steps; ++s) {
        if (ours.beforeStep) ours.beforeStep(ours, s);
        if (theirs.beforeStep) theirs.beforeStep(theirs, s);
        ours.world->step(dt, 8, 3);
        theirs.world->Step(dt, 8, 3);
        ++d.steps;
        d.impacts += ours.world->lastStepStats().impactCount;
        if (ours.bodies.size() != theirs.bodies.size()) {
            d.bodyCountsMatch = false;
            break;
        }
        bool identical = true;
        for (std::size_t i = 0; i < ours.bodies.size(); ++i) {
            Vec2 p = ours.world->bodyWorldCenter(ours.bodies[i]);
            b2Vec2 q = theirs.bodies[i]->GetWorldCenter();
            float a = ours.world->bodyAngle(ours.bodies[i]);
            float b = theirs.bodies[i]->GetAngle();
            // pivot2d flushes a denormal pose coordinate to 0 at the end of each step (so that
            // the solver never computes with them); Box2D keeps it. Read as pivot2d stores them,
            // the poses compare bit for bit.
            q.x = flushDenormal(q.x);
            q.y = flushDenormal(q.y);
            b = flushDenormal(b);
            identical = identical && p.x == q.x && p.y == q.y && a == b;
            d.position = std::max(d.position, std::hypot(double(p.x) - q.x, double(p.y) - q.y));
            d.angle = std::max(d.angle, std::fabs(double(a) - b));
        }
        if (identical && d.identicalSteps == s) ++d.identicalSteps;
    }
    return d;
}

scenes::Scene buildPivotCase(const ReferenceCase& c, const scenes::SceneOptions& options) {
    scenes::Scene scene;
    scene.name = c.name;
    // Box2D 2.4.1's pipeline (one substep; its broad-phase boxes, not v3's, so that which shapes
    // have contacts, and so the order contacts are made and solved in, is 2.4.1's).
    WorldDef def = WorldDef::box2d241();
    def.gravity = options.gravity;
    def.defaultPositionSolver = options.solver;
    def.contactCorrection = options.contactCorrection;
    scene.world = std::make_unique<World>(def);
    c.buildPivot(scene, options);
    return scene;
}

namespace {
// A prismatic or wheel joint's: how far anchor B is off the axis line, combined with how far the
// translation is beyond the limit.
template <typename SlideJoint>
double slideSeparation(SlideJoint& joint) {
    const b2Vec2 d = joint.GetAnchorB() - joint.GetAnchorA();
    const b2Vec2 axis = joint.GetBodyA()->GetWorldVector(joint.GetLocalAxisA());
    const double across = b2Cross(axis, d);  // d . perp, perp = (-axis.y, axis.x)
    const double x = joint.GetJointTranslation();
    double beyond = 0.0;
    if (joint.IsLimitEnabled()) {
        beyond = std::max({0.0, joint.GetLowerLimit() - x, x - joint.GetUpperLimit()});
    }
    return std::hypot(across, beyond);
}
}  // namespace

// As World::jointSeparation: a pin's anchor gap; how far a distance joint's length is outside
// [min, max].
double box2dSeparation(const b2Joint& joint) {
    const double gap = (joint.GetAnchorB() - joint.GetAnchorA()).Length();
    if (joint.GetType() == e_pulleyJoint) {
        const auto& pulley = static_cast<const b2PulleyJoint&>(joint);
        const double lengthA = (joint.GetAnchorA() - pulley.GetGroundAnchorA()).Length();
        const double lengthB = (joint.GetAnchorB() - pulley.GetGroundAnchorB()).Length();
        return std::fabs(double(pulley.GetLengthA()) +
                         double(pulley.GetRatio()) * pulley.GetLengthB() - lengthA -
                         double(pulley.GetRatio()) * lengthB);
    }
    if (joint.GetType() == e_frictionJoint || joint.GetType() == e_motorJoint) return 0.0;
    if (joint.GetType() == e_prismaticJoint) {
        // Box2D 2.4.1 declares GetBodyA and the limit getters without const.
        return slideSeparation(
            const_cast<b2PrismaticJoint&>(static_cast<const b2PrismaticJoint&>(joint)));
    }
    if (joint.GetType() == e_wheelJoint) {
        return slideSeparation(const_cast<b2WheelJoint&>(static_cast<const b2WheelJoint&>(joint)));
    }
    if (joint.GetType() == e_gearJoint) {
        // |coordinate1 + ratio coordinate2 - constant|. Box2D keeps the constant private; the
        // twins create their gears with both joints at coordinate 0, so it is 0.
        auto& gear = const_cast<b2GearJoint&>(static_cast<const b2GearJoint&>(joint));
        const auto coordinate = [](b2Joint* coupled) -> double {
            if (coupled->GetType() == e_revoluteJoint) {
                return static_cast<b2RevoluteJoint*>(coupled)->GetJointAngle();
            }
            return static_cast<b2PrismaticJoint*>(coupled)->GetJointTranslation();
        };
        return std::fabs(coordinate(gear.GetJoint1()) +
                         double(gear.GetRatio()) * coordinate(gear.GetJoint2()));
    }
    if (joint.GetType() != e_distanceJoint) return gap;
    const auto& distance = static_cast<const b2DistanceJoint&>(joint);
    return std::max({0.0, distance.GetMinLength() - gap, gap - distance.GetMaxLength()});
}

double box2dEnergy(const box2d::Box2dScene& scene) {
    const b2Vec2 g = scene.world->GetGravity();
    double energy = 0.0;
    for (const b2Body* body : scene.bodies) {
        double m = body->GetMass();
        // GetInertia is about the body origin; the energy needs it about the centre of mass.
        double inertia =
            body->GetInertia() - m * b2Dot(body->GetLocalCenter(), body->GetLocalCenter());
        b2Vec2 v = body->GetLinearVelocity();
        double w = body->GetAngularVelocity();
        b2Vec2 c = body->GetWorldCenter();
        energy += 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * inertia * w * w -
                  m * (double(g.x) * c.x + double(g.y) * c.y);
    }
    return energy;
}

scenes::RunMetrics runBox2d(box2d::Box2dScene& scene, const scenes::RunSettings& settings,
                            const std::function<void(int)>& afterStep) {
    using Clock = std::chrono::steady_clock;
    const float dt = 1.0f / settings.hz;
    scenes::RunMetrics m;
    m.energyStart = box2dEnergy(scene);
    double sumSquares = 0.0;
    long samples = 0;
    Clock::duration stepTime{};
    for (int i = 0; i < settings.steps; ++i) {
        if (scene.beforeStep) {
            double before = box2dEnergy(scene);
            scene.beforeStep(scene, i);
            m.energyStart += box2dEnergy(scene) - before;
        }
        Clock::time_point start = Clock::now();
        scene.world->Step(dt, settings.velocityIterations, settings.positionIterations);
        stepTime += Clock::now() - start;
        ++m.steps;

        double worst = 0.0;
        for (const b2Joint* joint : scene.joints) {
            double s = box2dSeparation(*joint);
            if (!(s <= worst)) worst = s;
            sumSquares += s * s;
            ++samples;
        }
        if (!(worst <= m.maxSeparation)) m.maxSeparation = worst;
        m.finalSeparation = worst;
        if (afterStep) afterStep(i);
        bool blownUp = false;
        for (const b2Body* body : scene.bodies) {
            b2Vec2 p = body->GetPosition();
            b2Vec2 v = body->GetLinearVelocity();
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) ||
                !std::isfinite(v.y) || v.Length() > scenes::kRunawaySpeed) {
                blownUp = true;
            }
        }
        if (blownUp) {
            m.blewUp = true;
            break;
        }
    }
    m.energyEnd = box2dEnergy(scene);
    m.rmsSeparation = samples > 0 ? std::sqrt(sumSquares / double(samples)) : 0.0;
    m.microsecondsPerStep =
        m.steps > 0 ? std::chrono::duration<double, std::micro>(stepTime).count() / double(m.steps)
                    : 0.0;
    return m;
}

}  // namespace pivot::reference
