#include "journal.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <istream>
#include <sstream>
#include <stdexcept>
#include "one_substep_def.h"

namespace pivot::fuzz {

namespace {

// Nine significant digits read back as the same float.
std::string num(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(v));
    return buffer;
}
std::string num(Vec2 v) {
    return num(v.x) + " " + num(v.y);
}
std::string num(int v) {
    return std::to_string(v);
}
std::string num(bool v) {
    return v ? "1" : "0";
}
std::string num(const Filter& f) {
    return std::to_string(f.categoryBits) + " " + std::to_string(f.maskBits) + " " +
           std::to_string(f.groupIndex);
}
// A sensor's def ends with the word "sensor" (journals before sensors have none).
std::string shapeDefText(const ShapeDef& def) {
    return num(def.density) + " " + num(def.friction) + " " + num(def.restitution) + " " +
           num(def.filter) + (def.isSensor ? " sensor" : "");
}

}  // namespace

void Journal::begin(World& world, const WorldDef& def) {
    world_ = &world;
    lines_.clear();
    names_.clear();
    created_ = 0;
    lines_.push_back("world " + num(def.gravity) + " " + num(int(def.defaultPositionSolver)) + " " +
                     num(int(def.contactCorrection)) + " " + num(def.contactBiasFactor) + " " +
                     num(def.restitutionThreshold) + " " + num(def.warmStarting) + " " +
                     num(def.enableSleep) + " " + num(def.jointLetGoSeparation));
}

bool Journal::write(const std::string& path) const {
    std::ofstream out(path);
    for (const std::string& line : lines_) out << line << '\n';
    return static_cast<bool>(out);
}

template <typename Id>
std::string Journal::nameOf(char kind, Id id) {
    auto it = names_.find(Key{kind, id.index, id.generation});
    return it == names_.end() ? std::string("?") : it->second;
}

template <typename Id>
std::string Journal::nameNew(char kind, Id id) {
    std::string name = kind + std::to_string(created_++);
    names_[Key{kind, id.index, id.generation}] = name;
    return name;
}

BodyId Journal::createBody(const BodyDef& def) {
    BodyId id = world_->createBody(def);
    lines_.push_back("body " + nameNew('b', id) + " " + num(int(def.type)) + " " +
                     num(def.position) + " " + num(def.angle) + " " + num(def.linearVelocity) +
                     " " + num(def.angularVelocity) + " " + num(def.linearDamping) + " " +
                     num(def.angularDamping) + " " + num(def.gravityScale) + " " +
                     num(def.fixedRotation) + " " + num(def.allowSleep) + " " + num(def.isAwake));
    return id;
}

ShapeId Journal::createShape(BodyId body, const ShapeDef& def, const Circle& circle) {
    ShapeId id = world_->createShape(body, def, circle);
    lines_.push_back("circle " + nameNew('s', id) + " " + nameOf('b', body) + " " +
                     shapeDefText(def) + " " + num(circle.center) + " " + num(circle.radius));
    return id;
}

ShapeId Journal::createShape(BodyId body, const ShapeDef& def, const Polygon& polygon) {
    ShapeId id = world_->createShape(body, def, polygon);
    std::string line = "polygon " + nameNew('s', id) + " " + nameOf('b', body) + " " +
                       shapeDefText(def) + " " + num(polygon.count);
    for (int i = 0; i < polygon.count; ++i) line += " " + num(polygon.vertices[i]);
    if (polygon.radius != 0.0f) line += " " + num(polygon.radius);  // optional: rounded
    lines_.push_back(line);
    return id;
}

ShapeId Journal::createShape(BodyId body, const ShapeDef& def, const Segment& segment) {
    ShapeId id = world_->createShape(body, def, segment);
    lines_.push_back("segment " + nameNew('s', id) + " " + nameOf('b', body) + " " +
                     shapeDefText(def) + " " + num(segment.point1) + " " + num(segment.point2));
    return id;
}

ShapeId Journal::createShape(BodyId body, const ShapeDef& def, const ChainSegment& segment) {
    ShapeId id = world_->createShape(body, def, segment);
    lines_.push_back("chainsegment " + nameNew('s', id) + " " + nameOf('b', body) + " " +
                     shapeDefText(def) + " " + num(segment.ghost1) + " " +
                     num(segment.segment.point1) + " " + num(segment.segment.point2) + " " +
                     num(segment.ghost2));
    return id;
}

ShapeId Journal::createShape(BodyId body, const ShapeDef& def, const Capsule& capsule) {
    ShapeId id = world_->createShape(body, def, capsule);
    lines_.push_back("capsule " + nameNew('s', id) + " " + nameOf('b', body) + " " +
                     shapeDefText(def) + " " + num(capsule.center1) + " " + num(capsule.center2) +
                     " " + num(capsule.radius));
    return id;
}

std::vector<ShapeId> Journal::createChain(BodyId body, const ShapeDef& def, const Chain& chain) {
    std::vector<ShapeId> ids = world_->createChain(body, def, chain);
    // The shapes' names last: how many there are follows from the points and the loop flag.
    std::string line = "chain " + nameOf('b', body) + " " + shapeDefText(def) + " " +
                       num(chain.loop) + " " + num(static_cast<int>(chain.points.size()));
    for (Vec2 p : chain.points) line += " " + num(p);
    for (ShapeId id : ids) line += " " + nameNew('s', id);
    lines_.push_back(line);
    return ids;
}

JointId Journal::createJoint(const RevoluteJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back(
        "joint " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " + nameOf('b', def.bodyB) +
        " " + num(def.worldAnchor.has_value()) + " " + num(def.worldAnchor.value_or(Vec2{})) + " " +
        num(def.localAnchorA) + " " + num(def.localAnchorB) + " " + num(def.referenceAngle) + " " +
        num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
        num(def.biasFactor.value_or(-1.0f)) + " " + num(def.limit.enabled) + " " +
        num(def.limit.lower) + " " + num(def.limit.upper) + " " + num(def.motor.enabled) + " " +
        num(def.motor.speed) + " " + num(def.motor.maxTorque) + " " + num(def.collideConnected) +
        " " + num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const DistanceJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back("distance " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " +
                     nameOf('b', def.bodyB) + " " + num(def.localAnchorA) + " " +
                     num(def.localAnchorB) + " " + num(def.length.has_value()) + " " +
                     num(def.length.value_or(0.0f)) + " " + num(def.limit.enabled) + " " +
                     num(def.limit.min) + " " + num(def.limit.max) + " " + num(def.spring.enabled) +
                     " " + num(def.spring.hertz) + " " + num(def.spring.dampingRatio) + " " +
                     num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
                     num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
                     num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const PulleyJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back("pulley " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " +
                     nameOf('b', def.bodyB) + " " + num(def.groundAnchorA) + " " +
                     num(def.groundAnchorB) + " " + num(def.localAnchorA) + " " +
                     num(def.localAnchorB) + " " + num(def.ratio) + " " +
                     num(def.lengthA.has_value()) + " " + num(def.lengthA.value_or(0.0f)) + " " +
                     num(def.lengthB.has_value()) + " " + num(def.lengthB.value_or(0.0f)) + " " +
                     num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
                     num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
                     num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const GearJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back("gear " + nameNew('j', id) + " " + nameOf('j', def.joint1) + " " +
                     nameOf('j', def.joint2) + " " + num(def.ratio) + " " +
                     num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
                     num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
                     num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const PrismaticJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back("prismatic " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " +
                     nameOf('b', def.bodyB) + " " + num(def.worldAnchor.has_value()) + " " +
                     num(def.worldAnchor.value_or(Vec2{})) + " " + num(def.localAnchorA) + " " +
                     num(def.localAnchorB) + " " + num(def.referenceAngle) + " " +
                     num(def.worldAxis.has_value()) + " " + num(def.worldAxis.value_or(Vec2{})) +
                     " " + num(def.localAxisA) + " " + num(def.limit.enabled) + " " +
                     num(def.limit.lower) + " " + num(def.limit.upper) + " " +
                     num(def.motor.enabled) + " " + num(def.motor.speed) + " " +
                     num(def.motor.maxForce) + " " + num(def.spring.enabled) + " " +
                     num(def.spring.hertz) + " " + num(def.spring.dampingRatio) + " " +
                     num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
                     num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
                     num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const WeldJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back(
        "weld " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " + nameOf('b', def.bodyB) +
        " " + num(def.worldAnchor.has_value()) + " " + num(def.worldAnchor.value_or(Vec2{})) + " " +
        num(def.localAnchorA) + " " + num(def.localAnchorB) + " " + num(def.referenceAngle) + " " +
        num(def.linearSpring.enabled) + " " + num(def.linearSpring.hertz) + " " +
        num(def.linearSpring.dampingRatio) + " " + num(def.angularSpring.enabled) + " " +
        num(def.angularSpring.hertz) + " " + num(def.angularSpring.dampingRatio) + " " +
        num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
        num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
        num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const WheelJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back(
        "wheel " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " + nameOf('b', def.bodyB) +
        " " + num(def.worldAnchor.has_value()) + " " + num(def.worldAnchor.value_or(Vec2{})) + " " +
        num(def.localAnchorA) + " " + num(def.localAnchorB) + " " + num(def.worldAxis.has_value()) +
        " " + num(def.worldAxis.value_or(Vec2{})) + " " + num(def.localAxisA) + " " +
        num(def.spring.enabled) + " " + num(def.spring.hertz) + " " + num(def.spring.dampingRatio) +
        " " + num(def.limit.enabled) + " " + num(def.limit.lower) + " " + num(def.limit.upper) +
        " " + num(def.motor.enabled) + " " + num(def.motor.speed) + " " + num(def.motor.maxTorque) +
        " " + num(def.positionSolver ? int(*def.positionSolver) : -1) + " " +
        num(def.biasFactor.value_or(-1.0f)) + " " + num(def.collideConnected) + " " +
        num(def.letGoSeparation.value_or(-1.0f)));
    return id;
}

JointId Journal::createJoint(const FrictionJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back("friction " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " +
                     nameOf('b', def.bodyB) + " " + num(def.localAnchorA) + " " +
                     num(def.localAnchorB) + " " + num(def.maxForce) + " " + num(def.maxTorque) +
                     " " + num(def.collideConnected));
    return id;
}

JointId Journal::createJoint(const MotorJointDef& def) {
    JointId id = world_->createJoint(def);
    lines_.push_back(
        "motorJoint " + nameNew('j', id) + " " + nameOf('b', def.bodyA) + " " +
        nameOf('b', def.bodyB) + " " + num(def.linearOffset.has_value()) + " " +
        num(def.linearOffset.value_or(Vec2{})) + " " + num(def.angularOffset.has_value()) + " " +
        num(def.angularOffset.value_or(0.0f)) + " " + num(def.maxForce) + " " + num(def.maxTorque) +
        " " + num(def.correctionFactor) + " " + num(def.collideConnected));
    return id;
}

MouseJointId Journal::createMouseJoint(const MouseJointDef& def) {
    MouseJointId id = world_->createMouseJoint(def);
    lines_.push_back("mouse " + nameNew('m', id) + " " + nameOf('b', def.body) + " " +
                     num(def.target) + " " + num(def.maxForce) + " " + num(def.hertz) + " " +
                     num(def.dampingRatio));
    return id;
}

void Journal::destroyBody(BodyId id) {
    std::string name = nameOf('b', id);
    world_->destroyBody(id);
    lines_.push_back("destroyBody " + name);
}
void Journal::destroyShape(ShapeId id) {
    std::string name = nameOf('s', id);
    world_->destroyShape(id);
    lines_.push_back("destroyShape " + name);
}
void Journal::destroyJoint(JointId id) {
    std::string name = nameOf('j', id);
    world_->destroyJoint(id);
    lines_.push_back("destroyJoint " + name);
}
void Journal::destroyMouseJoint(MouseJointId id) {
    std::string name = nameOf('m', id);
    world_->destroyMouseJoint(id);
    lines_.push_back("destroyMouse " + name);
}
void Journal::setBodyTransform(BodyId id, Vec2 position, float angle) {
    world_->setBodyTransform(id, position, angle);
    lines_.push_back("transform " + nameOf('b', id) + " " + num(position) + " " + num(angle));
}
void Journal::setBodyLinearVelocity(BodyId id, Vec2 v) {
    world_->setBodyLinearVelocity(id, v);
    lines_.push_back("velocity " + nameOf('b', id) + " " + num(v));
}
void Journal::setBodyAngularVelocity(BodyId id, float w) {
    world_->setBodyAngularVelocity(id, w);
    lines_.push_back("omega " + nameOf('b', id) + " " + num(w));
}
void Journal::applyForce(BodyId id, Vec2 force, Vec2 point) {
    world_->applyForce(id, force, point);
    lines_.push_back("force " + nameOf('b', id) + " " + num(force) + " " + num(point));
}
void Journal::applyForceToCenter(BodyId id, Vec2 force) {
    world_->applyForceToCenter(id, force);
    lines_.push_back("forceCenter " + nameOf('b', id) + " " + num(force));
}
void Journal::applyTorque(BodyId id, float torque) {
    world_->applyTorque(id, torque);
    lines_.push_back("torque " + nameOf('b', id) + " " + num(torque));
}
void Journal::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point) {
    world_->applyLinearImpulse(id, impulse, point);
    lines_.push_back("impulse " + nameOf('b', id) + " " + num(impulse) + " " + num(point));
}
void Journal::applyAngularImpulse(BodyId id, float impulse) {
    world_->applyAngularImpulse(id, impulse);
    lines_.push_back("angularImpulse " + nameOf('b', id) + " " + num(impulse));
}
void Journal::setBodyAwake(BodyId id, bool awake) {
    world_->setBodyAwake(id, awake);
    lines_.push_back("awake " + nameOf('b', id) + " " + num(awake));
}
void Journal::setBodySleepAllowed(BodyId id, bool allowed) {
    world_->setBodySleepAllowed(id, allowed);
    lines_.push_back("sleepAllowed " + nameOf('b', id) + " " + num(allowed));
}
void Journal::setBodyBullet(BodyId id, bool bullet) {
    world_->setBodyBullet(id, bullet);
    lines_.push_back("bullet " + nameOf('b', id) + " " + num(bullet));
}
void Journal::setBodyContinuous(BodyId id, bool continuous) {
    world_->setBodyContinuous(id, continuous);
    lines_.push_back("bodyContinuous " + nameOf('b', id) + " " + num(continuous));
}
void Journal::setBodyType(BodyId id, BodyType type) {
    world_->setBodyType(id, type);
    lines_.push_back("type " + nameOf('b', id) + " " + num(int(type)));
}
void Journal::setShapeSensor(ShapeId id, bool sensor) {
    world_->setShapeSensor(id, sensor);
    lines_.push_back("shapeSensor " + nameOf('s', id) + " " + num(sensor));
}
void Journal::setShapeFriction(ShapeId id, float friction) {
    world_->setShapeFriction(id, friction);
    lines_.push_back("shapeFriction " + nameOf('s', id) + " " + num(friction));
}
void Journal::setShapeRestitution(ShapeId id, float restitution) {
    world_->setShapeRestitution(id, restitution);
    lines_.push_back("shapeRestitution " + nameOf('s', id) + " " + num(restitution));
}
void Journal::setBodyFixedRotation(BodyId id, bool fixedRotation) {
    world_->setBodyFixedRotation(id, fixedRotation);
    lines_.push_back("fixedRotation " + nameOf('b', id) + " " + num(fixedRotation));
}
void Journal::setBodyLinearDamping(BodyId id, float damping) {
    world_->setBodyLinearDamping(id, damping);
    lines_.push_back("linearDamping " + nameOf('b', id) + " " + num(damping));
}
void Journal::setBodyAngularDamping(BodyId id, float damping) {
    world_->setBodyAngularDamping(id, damping);
    lines_.push_back("angularDamping " + nameOf('b', id) + " " + num(damping));
}
void Journal::setBodyGravityScale(BodyId id, float scale) {
    world_->setBodyGravityScale(id, scale);
    lines_.push_back("gravityScale " + nameOf('b', id) + " " + num(scale));
}
void Journal::setShapeDensity(ShapeId id, float density) {
    world_->setShapeDensity(id, density);
    lines_.push_back("density " + nameOf('s', id) + " " + num(density));
}
void Journal::setShapeFilter(ShapeId id, const Filter& filter) {
    world_->setShapeFilter(id, filter);
    lines_.push_back("filter " + nameOf('s', id) + " " + num(filter));
}
void Journal::setJointLimit(JointId id, const JointLimit& limit) {
    world_->setJointLimit(id, limit);
    lines_.push_back("limit " + nameOf('j', id) + " " + num(limit.enabled) + " " +
                     num(limit.lower) + " " + num(limit.upper));
}
void Journal::setDistanceJointRestLength(JointId id, float length) {
    world_->setDistanceJointRestLength(id, length);
    lines_.push_back("restLength " + nameOf('j', id) + " " + num(length));
}
void Journal::setDistanceJointLimit(JointId id, const LengthLimit& limit) {
    world_->setDistanceJointLimit(id, limit);
    lines_.push_back("lengthLimit " + nameOf('j', id) + " " + num(limit.enabled) + " " +
                     num(limit.min) + " " + num(limit.max));
}
void Journal::setDistanceJointSpring(JointId id, const JointSpring& spring) {
    world_->setDistanceJointSpring(id, spring);
    lines_.push_back("spring " + nameOf('j', id) + " " + num(spring.enabled) + " " +
                     num(spring.hertz) + " " + num(spring.dampingRatio));
}
void Journal::setPrismaticJointLimit(JointId id, const TranslationLimit& limit) {
    world_->setPrismaticJointLimit(id, limit);
    lines_.push_back("translationLimit " + nameOf('j', id) + " " + num(limit.enabled) + " " +
                     num(limit.lower) + " " + num(limit.upper));
}
void Journal::setPrismaticJointMotor(JointId id, const LinearMotor& motor) {
    world_->setPrismaticJointMotor(id, motor);
    lines_.push_back("linearMotor " + nameOf('j', id) + " " + num(motor.enabled) + " " +
                     num(motor.speed) + " " + num(motor.maxForce));
}
void Journal::setPrismaticJointSpring(JointId id, const JointSpring& spring) {
    world_->setPrismaticJointSpring(id, spring);
    lines_.push_back("prismaticSpring " + nameOf('j', id) + " " + num(spring.enabled) + " " +
                     num(spring.hertz) + " " + num(spring.dampingRatio));
}
void Journal::setWeldJointLinearSpring(JointId id, const JointSpring& spring) {
    world_->setWeldJointLinearSpring(id, spring);
    lines_.push_back("weldLinearSpring " + nameOf('j', id) + " " + num(spring.enabled) + " " +
                     num(spring.hertz) + " " + num(spring.dampingRatio));
}
void Journal::setWeldJointAngularSpring(JointId id, const JointSpring& spring) {
    world_->setWeldJointAngularSpring(id, spring);
    lines_.push_back("weldAngularSpring " + nameOf('j', id) + " " + num(spring.enabled) + " " +
                     num(spring.hertz) + " " + num(spring.dampingRatio));
}
void Journal::setWheelJointSpring(JointId id, const JointSpring& spring) {
    world_->setWheelJointSpring(id, spring);
    lines_.push_back("wheelSpring " + nameOf('j', id) + " " + num(spring.enabled) + " " +
                     num(spring.hertz) + " " + num(spring.dampingRatio));
}
void Journal::setGearJointRatio(JointId id, float ratio) {
    world_->setGearJointRatio(id, ratio);
    lines_.push_back("gearRatio " + nameOf('j', id) + " " + num(ratio));
}
void Journal::setWheelJointLimit(JointId id, const TranslationLimit& limit) {
    world_->setWheelJointLimit(id, limit);
    lines_.push_back("wheelLimit " + nameOf('j', id) + " " + num(limit.enabled) + " " +
                     num(limit.lower) + " " + num(limit.upper));
}
void Journal::setJointMaxForce(JointId id, float force) {
    world_->setJointMaxForce(id, force);
    lines_.push_back("maxForce " + nameOf('j', id) + " " + num(force));
}
void Journal::setMotorJointLinearOffset(JointId id, Vec2 offset) {
    world_->setMotorJointLinearOffset(id, offset);
    lines_.push_back("linearOffset " + nameOf('j', id) + " " + num(offset));
}
void Journal::setMotorJointCorrectionFactor(JointId id, float factor) {
    world_->setMotorJointCorrectionFactor(id, factor);
    lines_.push_back("correctionFactor " + nameOf('j', id) + " " + num(factor));
}
void Journal::setJointMotor(JointId id, const JointMotor& motor) {
    world_->setJointMotor(id, motor);
    lines_.push_back("motor " + nameOf('j', id) + " " + num(motor.enabled) + " " +
                     num(motor.speed) + " " + num(motor.maxTorque));
}
void Journal::setJointPositionSolver(JointId id, PositionSolver solver) {
    world_->setJointPositionSolver(id, solver);
    lines_.push_back("solver " + nameOf('j', id) + " " + num(int(solver)));
}
void Journal::setJointBiasFactor(JointId id, std::optional<float> bias) {
    world_->setJointBiasFactor(id, bias);
    lines_.push_back("bias " + nameOf('j', id) + " " + num(bias.value_or(-1.0f)));
}
void Journal::setJointExtraPositionIterations(JointId id, int count) {
    world_->setJointExtraPositionIterations(id, count);
    lines_.push_back("extra " + nameOf('j', id) + " " + num(count));
}
void Journal::setJointSoftness(JointId id, const JointSoftness& softness) {
    world_->setJointSoftness(id, softness);
    lines_.push_back("softness " + nameOf('j', id) + " " + num(softness.hertz) + " " +
                     num(softness.dampingRatio) + " " + num(softness.compliance));
}
void Journal::setJointLetGoSeparation(JointId id, std::optional<float> separation) {
    world_->setJointLetGoSeparation(id, separation);
    lines_.push_back("letgo " + nameOf('j', id) + " " + num(separation.value_or(-1.0f)));
}
void Journal::rearmJoint(JointId id) {
    world_->rearmJoint(id);
    lines_.push_back("rearm " + nameOf('j', id));
}
// User data changes nothing the engine computes; journalled so a replay is the same world.
void Journal::setBodyUserData(BodyId id, std::uint64_t value) {
    world_->setBodyUserData(id, value);
    lines_.push_back("bodydata " + nameOf('b', id) + " " + std::to_string(value));
}
void Journal::setShapeUserData(ShapeId id, std::uint64_t value) {
    world_->setShapeUserData(id, value);
    lines_.push_back("shapedata " + nameOf('s', id) + " " + std::to_string(value));
}
void Journal::setJointUserData(JointId id, std::uint64_t value) {
    world_->setJointUserData(id, value);
    lines_.push_back("jointdata " + nameOf('j', id) + " " + std::to_string(value));
}
void Journal::setMouseTarget(MouseJointId id, Vec2 target) {
    world_->setMouseTarget(id, target);
    lines_.push_back("target " + nameOf('m', id) + " " + num(target));
}
void Journal::setGravity(Vec2 gravity) {
    world_->setGravity(gravity);
    lines_.push_back("gravity " + num(gravity));
}
void Journal::setContactCorrection(ContactCorrection correction) {
    world_->setContactCorrection(correction);
    lines_.push_back("correction " + num(int(correction)));
}
void Journal::setSubstepCount(int count) {
    world_->setSubstepCount(count);
    lines_.push_back("substeps " + num(count));
}
void Journal::setSleepEnabled(bool enabled) {
    world_->setSleepEnabled(enabled);
    lines_.push_back("sleep " + num(enabled));
}
void Journal::setContinuousEnabled(bool enabled) {
    world_->setContinuousEnabled(enabled);
    lines_.push_back("continuous " + num(enabled));
}
void Journal::setContinuousCollision(ContinuousCollision policy) {
    world_->setContinuousCollision(policy);
    lines_.push_back("ccd " + num(static_cast<int>(policy)));
}
void Journal::setHitEventThreshold(float speed) {
    world_->setHitEventThreshold(speed);
    lines_.push_back("hitThreshold " + num(speed));
}
void Journal::setShapeHitEvents(ShapeId id, bool enabled) {
    world_->setShapeHitEventsEnabled(id, enabled);
    lines_.push_back("shapeHitEvents " + nameOf('s', id) + " " + num(enabled));
}
void Journal::setShapePreSolve(ShapeId id, bool enabled) {
    world_->setShapePreSolveEnabled(id, enabled);
    lines_.push_back("shapePreSolve " + nameOf('s', id) + " " + num(enabled));
}
void Journal::setJointBreakForce(JointId id, float force) {
    world_->setJointBreakForce(id, force);
    lines_.push_back("breakForce " + nameOf('j', id) + " " + num(force));
}
void Journal::setJointBreakTorque(JointId id, float torque) {
    world_->setJointBreakTorque(id, torque);
    lines_.push_back("breakTorque " + nameOf('j', id) + " " + num(torque));
}
void Journal::setJointCollideConnected(JointId id, bool collide) {
    world_->setJointCollideConnected(id, collide);
    lines_.push_back("collideConnected " + nameOf('j', id) + " " + num(collide));
}
void Journal::setCallbacks(bool preSolve, bool customFilter) {
    installFuzzCallbacks(*world_, preSolve, customFilter);
    lines_.push_back("callbacks " + num(preSolve) + " " + num(customFilter));
}

// Fixed functions of their arguments, so a replay calls the same ones. Each reads the world and
// checks that it refuses a change from inside the callback: a callback that could change the
// world mid-step would be a bug the fuzz must find.
void installFuzzCallbacks(World& world, bool preSolve, bool customFilter) {
    auto requireRefused = [](World& w, const char* which) {
        bool refused = false;
        try {
            w.setSleepEnabled(w.isSleepEnabled());
        } catch (const Error&) {
            refused = true;
        }
        if (!refused) throw std::logic_error(std::string(which) + " callback changed the world");
    };
    if (preSolve) {
        world.setPreSolveCallback([&world, requireRefused](const ContactData& c) {
            requireRefused(world, "a pre-solve");
            if (!world.isValid(c.shapeA) || !world.isValid(c.shapeB)) {
                throw std::logic_error("a pre-solve callback got a stale shape id");
            }
            return (c.shapeA.index + c.shapeB.index) % 3 != 0;
        });
    } else {
        world.setPreSolveCallback(nullptr);
    }
    if (customFilter) {
        world.setCustomFilterCallback([&world, requireRefused](ShapeId a, ShapeId b) {
            requireRefused(world, "a custom filter");
            return ((a.index ^ b.index) % 5) != 0;
        });
    } else {
        world.setCustomFilterCallback(nullptr);
    }
}

void Journal::step(float dt, int velocityIterations, int positionIterations) {
    world_->step(dt, velocityIterations, positionIterations);
    lines_.push_back("step " + num(dt) + " " + num(velocityIterations) + " " +
                     num(positionIterations));
}

bool worldIsFinite(const World& world, std::string* what) {
    for (BodyId b : world.bodyIds()) {
        Vec2 p = world.bodyPosition(b), v = world.bodyLinearVelocity(b);
        float a = world.bodyAngle(b), w = world.bodyAngularVelocity(b);
        if (!isFinite(p) || !isFinite(v) || !std::isfinite(a) || !std::isfinite(w)) {
            if (what) *what = "body " + std::to_string(b.index) + " p " + num(p) + " v " + num(v);
            return false;
        }
    }
    for (JointId j : world.jointIds()) {
        if (!isFinite(world.jointReactionForce(j)) ||
            !std::isfinite(world.jointReactionTorque(j))) {
            if (what) *what = "joint " + std::to_string(j.index) + " reaction";
            return false;
        }
    }
    return true;
}

bool worldWithinLimits(const World& world, std::string* what) {
    for (BodyId b : world.bodyIds()) {
        const Vec2 p = world.bodyPosition(b), v = world.bodyLinearVelocity(b);
        const float a = world.bodyAngle(b), w = world.bodyAngularVelocity(b);
        if (std::fabs(p.x) > kMaxCoordinate || std::fabs(p.y) > kMaxCoordinate ||
            std::fabs(v.x) > kMaxSpeed || std::fabs(v.y) > kMaxSpeed ||
            std::fabs(w) > kMaxAngularSpeed || std::fabs(a) > kMaxMagnitude) {
            if (what) {
                *what = "body " + std::to_string(b.index) + " p " + num(p) + " v " + num(v) +
                        " a " + num(a) + " w " + num(w);
            }
            return false;
        }
    }
    return true;
}

namespace {

// Reads one journal line's fields in order; any failure marks the line unreadable.
class Fields {
public:
    explicit Fields(const std::string& line) : in_(line) {}
    std::string word() {
        std::string w;
        if (!(in_ >> w)) ok_ = false;
        return w;
    }
    float f() {
        std::string w = word();
        return ok_ ? std::strtof(w.c_str(), nullptr) : 0.0f;
    }
    Vec2 v() {
        float x = f();
        return {x, f()};
    }
    int i() {
        std::string w = word();
        return ok_ ? std::atoi(w.c_str()) : 0;
    }
    bool b() { return i() != 0; }
    /// An integer if one is left on the line, else `otherwise`.
    int optionalInt(int otherwise) {
        std::string w;
        return (in_ >> w) ? std::atoi(w.c_str()) : otherwise;
    }
    /// A number if one is left on the line, else `otherwise`.
    float optionalFloat(float otherwise) {
        std::string w;
        return (in_ >> w) ? std::strtof(w.c_str(), nullptr) : otherwise;
    }
    std::uint64_t u64() {
        std::string w = word();
        return ok_ ? std::strtoull(w.c_str(), nullptr, 10) : 0;
    }
    Filter filter() {
        Filter out;
        out.categoryBits = static_cast<std::uint16_t>(i());
        out.maskBits = static_cast<std::uint16_t>(i());
        out.groupIndex = static_cast<std::int16_t>(i());
        return out;
    }
    ShapeDef shapeDef() {
        ShapeDef def;
        def.density = f();
        def.friction = f();
        def.restitution = f();
        def.filter = filter();
        const std::streampos at = in_.tellg();
        std::string w;
        if (in_ >> w && w == "sensor") {
            def.isSensor = true;
        } else {
            in_.clear();
            in_.seekg(at);
        }
        return def;
    }
    bool ok() const { return ok_; }

private:
    std::istringstream in_;
    bool ok_ = true;
};

}  // namespace

ReplayResult replay(std::istream& in) {
    ReplayResult result;
    std::unique_ptr<World> world;
    std::map<std::string, BodyId> bodies;
    std::map<std::string, ShapeId> shapes;
    std::map<std::string, JointId> joints;
    std::map<std::string, MouseJointId> mice;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        ++result.lines;
        Fields f(line);
        std::string command = f.word();
        if (command == "world") {
            WorldDef def = oneSubstepDef();
            def.gravity = f.v();
            def.defaultPositionSolver = static_cast<PositionSolver>(f.i());
            def.contactCorrection = static_cast<ContactCorrection>(f.i());
            def.contactBiasFactor = f.f();
            def.restitutionThreshold = f.f();
            def.warmStarting = f.b();
            def.enableSleep = f.b();
            def.jointLetGoSeparation = f.optionalFloat(0.0f);  // journals before it had none
            world = std::make_unique<World>(def);
            continue;
        }
        if (!world) world = std::make_unique<World>(oneSubstepDef());
        World& w = *world;
        // Looks a name up; a missing one skips the line.
        bool missing = false;
        auto body = [&](const std::string& name) {
            auto it = bodies.find(name);
            if (it == bodies.end()) missing = true;
            return it == bodies.end() ? BodyId{} : it->second;
        };
        auto shape = [&](const std::string& name) {
            auto it = shapes.find(name);
            if (it == shapes.end()) missing = true;
            return it == shapes.end() ? ShapeId{} : it->second;
        };
        auto joint = [&](const std::string& name) {
            auto it = joints.find(name);
            if (it == joints.end()) missing = true;
            return it == joints.end() ? JointId{} : it->second;
        };
        auto mouse = [&](const std::string& name) {
            auto it = mice.find(name);
            if (it == mice.end()) missing = true;
            return it == mice.end() ? MouseJointId{} : it->second;
        };
        std::function<void()> call;
        if (command == "body") {
            std::string name = f.word();
            BodyDef def;
            def.type = static_cast<BodyType>(f.i());
            def.position = f.v();
            def.angle = f.f();
            def.linearVelocity = f.v();
            def.angularVelocity = f.f();
            def.linearDamping = f.f();
            def.angularDamping = f.f();
            def.gravityScale = f.f();
            def.fixedRotation = f.b();
            def.allowSleep = f.b();
            def.isAwake = f.b();
            call = [&w, &bodies, name, def] { bodies[name] = w.createBody(def); };
        } else if (command == "circle" || command == "polygon" || command == "segment") {
            std::string name = f.word();
            BodyId b = body(f.word());
            ShapeDef def = f.shapeDef();
            if (command == "circle") {
                Circle c;
                c.center = f.v();
                c.radius = f.f();
                call = [&w, &shapes, name, b, def, c] { shapes[name] = w.createShape(b, def, c); };
            } else if (command == "segment") {
                Segment g;
                g.point1 = f.v();
                g.point2 = f.v();
                call = [&w, &shapes, name, b, def, g] { shapes[name] = w.createShape(b, def, g); };
            } else {
                Polygon p;
                p.count = f.i();
                for (int i = 0; i < p.count && i < kMaxPolygonVertices; ++i) p.vertices[i] = f.v();
                p.radius = f.optionalFloat(0.0f);
                call = [&w, &shapes, name, b, def, p] { shapes[name] = w.createShape(b, def, p); };
            }
        } else if (command == "capsule") {
            std::string name = f.word();
            BodyId b = body(f.word());
            ShapeDef def = f.shapeDef();
            Capsule c;
            c.center1 = f.v();
            c.center2 = f.v();
            c.radius = f.f();
            call = [&w, &shapes, name, b, def, c] { shapes[name] = w.createShape(b, def, c); };
        } else if (command == "chainsegment") {
            std::string name = f.word();
            BodyId b = body(f.word());
            ShapeDef def = f.shapeDef();
            ChainSegment g;
            g.ghost1 = f.v();
            g.segment.point1 = f.v();
            g.segment.point2 = f.v();
            g.ghost2 = f.v();
            call = [&w, &shapes, name, b, def, g] { shapes[name] = w.createShape(b, def, g); };
        } else if (command == "chain") {
            BodyId b = body(f.word());
            ShapeDef def = f.shapeDef();
            Chain chain;
            chain.loop = f.b();
            const int count = f.i();
            for (int i = 0; i < count && i < 1000; ++i) chain.points.push_back(f.v());
            std::vector<std::string> names;
            const int made = chain.loop ? count : count - 3;
            for (int i = 0; i < made && i < 1000; ++i) names.push_back(f.word());
            call = [&w, &shapes, names, b, def, chain] {
                const std::vector<ShapeId> ids = w.createChain(b, def, chain);
                for (std::size_t i = 0; i < ids.size() && i < names.size(); ++i) {
                    shapes[names[i]] = ids[i];
                }
            };
        } else if (command == "joint") {
            std::string name = f.word();
            RevoluteJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            bool hasWorld = f.b();
            Vec2 anchor = f.v();
            if (hasWorld) def.worldAnchor = anchor;
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            def.referenceAngle = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.limit.enabled = f.b();
            def.limit.lower = f.f();
            def.limit.upper = f.f();
            def.motor.enabled = f.b();
            def.motor.speed = f.f();
            def.motor.maxTorque = f.f();
            def.collideConnected = f.b();
            const float letGo = f.optionalFloat(-1.0f);
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "distance") {
            std::string name = f.word();
            DistanceJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            const bool hasLength = f.b();
            const float length = f.f();
            if (hasLength) def.length = length;
            def.limit.enabled = f.b();
            def.limit.min = f.f();
            def.limit.max = f.f();
            def.spring.enabled = f.b();
            def.spring.hertz = f.f();
            def.spring.dampingRatio = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "pulley") {
            std::string name = f.word();
            PulleyJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            def.groundAnchorA = f.v();
            def.groundAnchorB = f.v();
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            def.ratio = f.f();
            const bool hasA = f.b();
            const float lengthA = f.f();
            if (hasA) def.lengthA = lengthA;
            const bool hasB = f.b();
            const float lengthB = f.f();
            if (hasB) def.lengthB = lengthB;
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "prismatic") {
            std::string name = f.word();
            PrismaticJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            const bool hasWorldAnchor = f.b();
            const Vec2 anchor = f.v();
            if (hasWorldAnchor) def.worldAnchor = anchor;
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            def.referenceAngle = f.f();
            const bool hasWorldAxis = f.b();
            const Vec2 axis = f.v();
            if (hasWorldAxis) def.worldAxis = axis;
            def.localAxisA = f.v();
            def.limit.enabled = f.b();
            def.limit.lower = f.f();
            def.limit.upper = f.f();
            def.motor.enabled = f.b();
            def.motor.speed = f.f();
            def.motor.maxForce = f.f();
            def.spring.enabled = f.b();
            def.spring.hertz = f.f();
            def.spring.dampingRatio = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "wheel") {
            std::string name = f.word();
            WheelJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            const bool hasWorldAnchor = f.b();
            const Vec2 anchor = f.v();
            if (hasWorldAnchor) def.worldAnchor = anchor;
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            const bool hasWorldAxis = f.b();
            const Vec2 axis = f.v();
            if (hasWorldAxis) def.worldAxis = axis;
            def.localAxisA = f.v();
            def.spring.enabled = f.b();
            def.spring.hertz = f.f();
            def.spring.dampingRatio = f.f();
            def.limit.enabled = f.b();
            def.limit.lower = f.f();
            def.limit.upper = f.f();
            def.motor.enabled = f.b();
            def.motor.speed = f.f();
            def.motor.maxTorque = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "gear") {
            std::string name = f.word();
            GearJointDef def;
            def.joint1 = joint(f.word());
            def.joint2 = joint(f.word());
            def.ratio = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "gearRatio") {
            JointId j = joint(f.word());
            const float ratio = f.f();
            call = [&w, j, ratio] { w.setGearJointRatio(j, ratio); };
        } else if (command == "wheelSpring") {
            JointId j = joint(f.word());
            JointSpring sp;
            sp.enabled = f.b();
            sp.hertz = f.f();
            sp.dampingRatio = f.f();
            call = [&w, j, sp] { w.setWheelJointSpring(j, sp); };
        } else if (command == "wheelLimit") {
            JointId j = joint(f.word());
            TranslationLimit l;
            l.enabled = f.b();
            l.lower = f.f();
            l.upper = f.f();
            call = [&w, j, l] { w.setWheelJointLimit(j, l); };
        } else if (command == "weld") {
            std::string name = f.word();
            WeldJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            const bool hasWorldAnchor = f.b();
            const Vec2 anchor = f.v();
            if (hasWorldAnchor) def.worldAnchor = anchor;
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            def.referenceAngle = f.f();
            def.linearSpring.enabled = f.b();
            def.linearSpring.hertz = f.f();
            def.linearSpring.dampingRatio = f.f();
            def.angularSpring.enabled = f.b();
            def.angularSpring.hertz = f.f();
            def.angularSpring.dampingRatio = f.f();
            int solver = f.i();
            if (solver >= 0) def.positionSolver = static_cast<PositionSolver>(solver);
            float bias = f.f();
            if (bias >= 0.0f) def.biasFactor = bias;
            def.collideConnected = f.b();
            const float letGo = f.f();
            if (letGo >= 0.0f) def.letGoSeparation = letGo;
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "weldLinearSpring" || command == "weldAngularSpring") {
            JointId j = joint(f.word());
            JointSpring sp;
            sp.enabled = f.b();
            sp.hertz = f.f();
            sp.dampingRatio = f.f();
            if (command == "weldLinearSpring") {
                call = [&w, j, sp] { w.setWeldJointLinearSpring(j, sp); };
            } else {
                call = [&w, j, sp] { w.setWeldJointAngularSpring(j, sp); };
            }
        } else if (command == "translationLimit") {
            JointId j = joint(f.word());
            TranslationLimit l;
            l.enabled = f.b();
            l.lower = f.f();
            l.upper = f.f();
            call = [&w, j, l] { w.setPrismaticJointLimit(j, l); };
        } else if (command == "linearMotor") {
            JointId j = joint(f.word());
            LinearMotor m;
            m.enabled = f.b();
            m.speed = f.f();
            m.maxForce = f.f();
            call = [&w, j, m] { w.setPrismaticJointMotor(j, m); };
        } else if (command == "prismaticSpring") {
            JointId j = joint(f.word());
            JointSpring sp;
            sp.enabled = f.b();
            sp.hertz = f.f();
            sp.dampingRatio = f.f();
            call = [&w, j, sp] { w.setPrismaticJointSpring(j, sp); };
        } else if (command == "friction") {
            std::string name = f.word();
            FrictionJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            def.localAnchorA = f.v();
            def.localAnchorB = f.v();
            def.maxForce = f.f();
            def.maxTorque = f.f();
            def.collideConnected = f.b();
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "motorJoint") {
            std::string name = f.word();
            MotorJointDef def;
            def.bodyA = body(f.word());
            def.bodyB = body(f.word());
            const bool hasLinear = f.b();
            const Vec2 linear = f.v();
            if (hasLinear) def.linearOffset = linear;
            const bool hasAngular = f.b();
            const float angular = f.f();
            if (hasAngular) def.angularOffset = angular;
            def.maxForce = f.f();
            def.maxTorque = f.f();
            def.correctionFactor = f.f();
            def.collideConnected = f.b();
            call = [&w, &joints, name, def] { joints[name] = w.createJoint(def); };
        } else if (command == "maxForce") {
            JointId j = joint(f.word());
            const float force = f.f();
            call = [&w, j, force] { w.setJointMaxForce(j, force); };
        } else if (command == "linearOffset") {
            JointId j = joint(f.word());
            const Vec2 offset = f.v();
            call = [&w, j, offset] { w.setMotorJointLinearOffset(j, offset); };
        } else if (command == "correctionFactor") {
            JointId j = joint(f.word());
            const float factor = f.f();
            call = [&w, j, factor] { w.setMotorJointCorrectionFactor(j, factor); };
        } else if (command == "mouse") {
            std::string name = f.word();
            MouseJointDef def;
            def.body = body(f.word());
            def.target = f.v();
            def.maxForce = f.f();
            def.hertz = f.f();
            def.dampingRatio = f.f();
            call = [&w, &mice, name, def] { mice[name] = w.createMouseJoint(def); };
        } else if (command == "destroyBody") {
            BodyId b = body(f.word());
            call = [&w, b] { w.destroyBody(b); };
        } else if (command == "destroyShape") {
            ShapeId s = shape(f.word());
            call = [&w, s] { w.destroyShape(s); };
        } else if (command == "destroyJoint") {
            JointId j = joint(f.word());
            call = [&w, j] { w.destroyJoint(j); };
        } else if (command == "destroyMouse") {
            MouseJointId m = mouse(f.word());
            call = [&w, m] { w.destroyMouseJoint(m); };
        } else if (command == "transform") {
            BodyId b = body(f.word());
            Vec2 p = f.v();
            float a = f.f();
            call = [&w, b, p, a] { w.setBodyTransform(b, p, a); };
        } else if (command == "velocity") {
            BodyId b = body(f.word());
            Vec2 v = f.v();
            call = [&w, b, v] { w.setBodyLinearVelocity(b, v); };
        } else if (command == "omega") {
            BodyId b = body(f.word());
            float v = f.f();
            call = [&w, b, v] { w.setBodyAngularVelocity(b, v); };
        } else if (command == "force" || command == "impulse") {
            BodyId b = body(f.word());
            Vec2 v = f.v();
            Vec2 p = f.v();
            if (command == "force") {
                call = [&w, b, v, p] { w.applyForce(b, v, p); };
            } else {
                call = [&w, b, v, p] { w.applyLinearImpulse(b, v, p); };
            }
        } else if (command == "forceCenter") {
            BodyId b = body(f.word());
            Vec2 v = f.v();
            call = [&w, b, v] { w.applyForceToCenter(b, v); };
        } else if (command == "torque" || command == "angularImpulse") {
            BodyId b = body(f.word());
            float v = f.f();
            if (command == "torque") {
                call = [&w, b, v] { w.applyTorque(b, v); };
            } else {
                call = [&w, b, v] { w.applyAngularImpulse(b, v); };
            }
        } else if (command == "shapeSensor") {
            ShapeId s = shape(f.word());
            bool v = f.b();
            call = [&w, s, v] { w.setShapeSensor(s, v); };
        } else if (command == "shapeFriction" || command == "shapeRestitution") {
            ShapeId s = shape(f.word());
            float v = f.f();
            if (command == "shapeFriction") {
                call = [&w, s, v] { w.setShapeFriction(s, v); };
            } else {
                call = [&w, s, v] { w.setShapeRestitution(s, v); };
            }
        } else if (command == "linearDamping" || command == "angularDamping" ||
                   command == "gravityScale") {
            BodyId b = body(f.word());
            float v = f.f();
            if (command == "linearDamping") {
                call = [&w, b, v] { w.setBodyLinearDamping(b, v); };
            } else if (command == "angularDamping") {
                call = [&w, b, v] { w.setBodyAngularDamping(b, v); };
            } else {
                call = [&w, b, v] { w.setBodyGravityScale(b, v); };
            }
        } else if (command == "awake" || command == "sleepAllowed" || command == "bullet" ||
                   command == "bodyContinuous" || command == "fixedRotation") {
            BodyId b = body(f.word());
            bool v = f.b();
            if (command == "fixedRotation") {
                call = [&w, b, v] { w.setBodyFixedRotation(b, v); };
            } else if (command == "awake") {
                call = [&w, b, v] { w.setBodyAwake(b, v); };
            } else if (command == "sleepAllowed") {
                call = [&w, b, v] { w.setBodySleepAllowed(b, v); };
            } else if (command == "bullet") {
                call = [&w, b, v] { w.setBodyBullet(b, v); };
            } else {
                call = [&w, b, v] { w.setBodyContinuous(b, v); };
            }
        } else if (command == "type") {
            BodyId b = body(f.word());
            auto t = static_cast<BodyType>(f.i());
            call = [&w, b, t] { w.setBodyType(b, t); };
        } else if (command == "density") {
            ShapeId s = shape(f.word());
            float d = f.f();
            call = [&w, s, d] { w.setShapeDensity(s, d); };
        } else if (command == "filter") {
            ShapeId s = shape(f.word());
            Filter filter = f.filter();
            call = [&w, s, filter] { w.setShapeFilter(s, filter); };
        } else if (command == "limit") {
            JointId j = joint(f.word());
            JointLimit l;
            l.enabled = f.b();
            l.lower = f.f();
            l.upper = f.f();
            call = [&w, j, l] { w.setJointLimit(j, l); };
        } else if (command == "restLength") {
            JointId j = joint(f.word());
            const float length = f.f();
            call = [&w, j, length] { w.setDistanceJointRestLength(j, length); };
        } else if (command == "lengthLimit") {
            JointId j = joint(f.word());
            LengthLimit l;
            l.enabled = f.b();
            l.min = f.f();
            l.max = f.f();
            call = [&w, j, l] { w.setDistanceJointLimit(j, l); };
        } else if (command == "spring") {
            JointId j = joint(f.word());
            JointSpring sp;
            sp.enabled = f.b();
            sp.hertz = f.f();
            sp.dampingRatio = f.f();
            call = [&w, j, sp] { w.setDistanceJointSpring(j, sp); };
        } else if (command == "motor") {
            JointId j = joint(f.word());
            JointMotor m;
            m.enabled = f.b();
            m.speed = f.f();
            m.maxTorque = f.f();
            call = [&w, j, m] { w.setJointMotor(j, m); };
        } else if (command == "solver") {
            JointId j = joint(f.word());
            auto s = static_cast<PositionSolver>(f.i());
            call = [&w, j, s] { w.setJointPositionSolver(j, s); };
        } else if (command == "bias") {
            JointId j = joint(f.word());
            float b = f.f();
            std::optional<float> bias;
            if (b >= 0.0f) bias = b;
            call = [&w, j, bias] { w.setJointBiasFactor(j, bias); };
        } else if (command == "extra") {
            JointId j = joint(f.word());
            const int count = f.i();
            call = [&w, j, count] { w.setJointExtraPositionIterations(j, count); };
        } else if (command == "softness") {
            JointId j = joint(f.word());
            const float hertz = f.f();
            const float ratio = f.f();
            const float compliance = f.f();
            call = [&w, j, hertz, ratio, compliance] {
                w.setJointSoftness(j, {hertz, ratio, compliance});
            };
        } else if (command == "letgo") {
            JointId j = joint(f.word());
            const float value = f.f();
            std::optional<float> separation;
            if (value >= 0.0f) separation = value;
            call = [&w, j, separation] { w.setJointLetGoSeparation(j, separation); };
        } else if (command == "rearm") {
            JointId j = joint(f.word());
            call = [&w, j] { w.rearmJoint(j); };
        } else if (command == "bodydata") {
            BodyId b = body(f.word());
            const std::uint64_t value = f.u64();
            call = [&w, b, value] { w.setBodyUserData(b, value); };
        } else if (command == "shapedata") {
            ShapeId s = shape(f.word());
            const std::uint64_t value = f.u64();
            call = [&w, s, value] { w.setShapeUserData(s, value); };
        } else if (command == "jointdata") {
            JointId j = joint(f.word());
            const std::uint64_t value = f.u64();
            call = [&w, j, value] { w.setJointUserData(j, value); };
        } else if (command == "target") {
            MouseJointId m = mouse(f.word());
            Vec2 t = f.v();
            call = [&w, m, t] { w.setMouseTarget(m, t); };
        } else if (command == "gravity") {
            Vec2 g = f.v();
            call = [&w, g] { w.setGravity(g); };
        } else if (command == "correction") {
            auto c = static_cast<ContactCorrection>(f.i());
            call = [&w, c] { w.setContactCorrection(c); };
        } else if (command == "substeps") {
            const int n = f.i();
            call = [&w, n] { w.setSubstepCount(n); };
        } else if (command == "sleep") {
            bool on = f.b();
            call = [&w, on] { w.setSleepEnabled(on); };
        } else if (command == "continuous") {
            bool on = f.b();
            call = [&w, on] { w.setContinuousEnabled(on); };
        } else if (command == "ccd") {
            auto policy = static_cast<ContinuousCollision>(f.i());
            call = [&w, policy] { w.setContinuousCollision(policy); };
        } else if (command == "hitThreshold") {
            const float v = f.f();
            call = [&w, v] { w.setHitEventThreshold(v); };
        } else if (command == "shapeHitEvents" || command == "shapePreSolve") {
            ShapeId s = shape(f.word());
            bool v = f.b();
            if (command == "shapeHitEvents") {
                call = [&w, s, v] { w.setShapeHitEventsEnabled(s, v); };
            } else {
                call = [&w, s, v] { w.setShapePreSolveEnabled(s, v); };
            }
        } else if (command == "breakForce" || command == "breakTorque") {
            JointId j = joint(f.word());
            const float v = f.f();
            if (command == "breakForce") {
                call = [&w, j, v] { w.setJointBreakForce(j, v); };
            } else {
                call = [&w, j, v] { w.setJointBreakTorque(j, v); };
            }
        } else if (command == "collideConnected") {
            JointId j = joint(f.word());
            const bool v = f.b();
            call = [&w, j, v] { w.setJointCollideConnected(j, v); };
        } else if (command == "callbacks") {
            const bool preSolve = f.b();
            const bool filter = f.b();
            call = [&w, preSolve, filter] { installFuzzCallbacks(w, preSolve, filter); };
        } else if (command == "step") {
            // An optional fourth field repeats the step (hand-written reproductions).
            float dt = f.f();
            int vi = f.i();
            int pi = f.i();
            int repeat = f.optionalInt(1);
            std::string* what = &result.nonFinite;
            ReplayResult* counts = &result;
            call = [&w, dt, vi, pi, repeat, what, counts] {
                for (int k = 0; k < repeat; ++k) {
                    w.step(dt, vi, pi);
                    counts->letGoJoints += w.lastStepStats().letGoJointCount;
                    counts->discardedBodies += w.lastStepStats().discardedBodyCount;
                    if (!worldIsFinite(w, what)) return;
                }
            };
        } else {
            result.error = "line " + std::to_string(result.lines) + ": unknown command " + command;
            return result;
        }
        if (!f.ok()) {
            result.error =
                "line " + std::to_string(result.lines) + ": cannot read \"" + line + "\"";
            return result;
        }
        if (missing) {
            ++result.skipped;
            continue;
        }
        try {
            call();
            ++result.applied;
        } catch (const Error&) {
            ++result.refused;
        }
        if (command == "step" && !worldIsFinite(w, &result.nonFinite)) {
            result.nonFiniteLine = result.lines;
            return result;
        }
        if (command == "step" && !worldWithinLimits(w, &result.beyondLimits)) {
            result.beyondLimitsLine = result.lines;
            return result;
        }
    }
    return result;
}

}  // namespace pivot::fuzz
