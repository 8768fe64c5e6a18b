// The World facade, part four: the calls one or two joint types answer (and refuse for the
// others, naming both types).
#include "world/joint_settings.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

float World::jointMotorTorque(JointId id) const {
    const char* call = "World::jointMotorTorque";
    const std::int32_t index =
        impl_->jointIndexOfTypes(call, id, JointType::Revolute, JointType::Wheel);
    const Joint& j = impl_->joints[index];
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        return j.impulseInvDt * wheel->motorImpulse;
    }
    return j.impulseInvDt * std::get<RevoluteJoint>(j.data).motorImpulse;
}

JointLimit World::jointLimit(JointId id) const {
    const Joint& j =
        impl_->joints[impl_->jointIndexOfType("World::jointLimit", id, JointType::Revolute)];
    const RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
    return {r.enableLimit, r.lowerAngle, r.upperAngle};
}
void World::setJointLimit(JointId id, const JointLimit& limit) {
    const char* call = "World::setJointLimit";
    impl_->setJointData<RevoluteJoint>(
        call, id, JointType::Revolute, [&] { checkLimit(call, "limit", limit); },
        [&](RevoluteJoint& r) {
            r.enableLimit = limit.enabled;
            r.lowerAngle = limit.lower;
            r.upperAngle = limit.upper;
            r.lowerImpulse = 0.0f;
            r.upperImpulse = 0.0f;
        });
}
JointMotor World::jointMotor(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndexOfTypes("World::jointMotor", id,
                                                            JointType::Revolute, JointType::Wheel)];
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        return {wheel->enableMotor, wheel->motorSpeed, wheel->maxMotorTorque};
    }
    const RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
    return {r.enableMotor, r.motorSpeed, r.maxMotorTorque};
}
void World::setJointMotor(JointId id, const JointMotor& motor) {
    const char* call = "World::setJointMotor";
    impl_->setJoint(
        call,
        [&] { return impl_->jointIndexOfTypes(call, id, JointType::Revolute, JointType::Wheel); },
        [&](const Joint&) { checkMotor(call, "motor", motor); },
        [&](Joint& j) {
            if (auto* wheel = std::get_if<WheelJoint>(&j.data)) {
                setMotor(*wheel, motor);
            } else {
                RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
                r.enableMotor = motor.enabled;
                r.motorSpeed = motor.speed;
                r.maxMotorTorque = motor.maxTorque;
            }
        });
}

float World::distanceJointRestLength(JointId id) const {
    return impl_
        ->jointData<DistanceJoint>("World::distanceJointRestLength", id, JointType::Distance)
        .length;
}
void World::setDistanceJointRestLength(JointId id, float length) {
    const char* call = "World::setDistanceJointRestLength";
    impl_->setJointData<DistanceJoint>(
        call, id, JointType::Distance, [&] { checkRestLength(call, "length", length); },
        [&](DistanceJoint& d) { d.length = length; });
}
LengthLimit World::distanceJointLimit(JointId id) const {
    const DistanceJoint& d =
        impl_->jointData<DistanceJoint>("World::distanceJointLimit", id, JointType::Distance);
    return {d.enableLimit, d.minLength, d.maxLength};
}
void World::setDistanceJointLimit(JointId id, const LengthLimit& limit) {
    const char* call = "World::setDistanceJointLimit";
    impl_->setJointData<DistanceJoint>(
        call, id, JointType::Distance, [&] { checkLengthLimit(call, "limit", limit); },
        [&](DistanceJoint& d) {
            setLimit(d, limit);
            d.lowerImpulse = d.upperImpulse = 0.0f;
        });
}
JointSpring World::distanceJointSpring(JointId id) const {
    const DistanceJoint& d =
        impl_->jointData<DistanceJoint>("World::distanceJointSpring", id, JointType::Distance);
    return {d.enableSpring, d.hertz, d.dampingRatio};
}
void World::setDistanceJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setDistanceJointSpring";
    impl_->setJointData<DistanceJoint>(
        call, id, JointType::Distance, [&] { checkSpring(call, "spring", spring); },
        [&](DistanceJoint& d) { setSpring(d, spring); });
}

Vec2 World::pulleyJointGroundAnchorA(JointId id) const {
    return impl_->jointData<PulleyJoint>("World::pulleyJointGroundAnchorA", id, JointType::Pulley)
        .groundAnchorA;
}
Vec2 World::pulleyJointGroundAnchorB(JointId id) const {
    return impl_->jointData<PulleyJoint>("World::pulleyJointGroundAnchorB", id, JointType::Pulley)
        .groundAnchorB;
}
float World::pulleyJointRatio(JointId id) const {
    return impl_->jointData<PulleyJoint>("World::pulleyJointRatio", id, JointType::Pulley).ratio;
}
float World::pulleyJointLengthA(JointId id) const {
    const char* call = "World::pulleyJointLengthA";
    const Joint& j = impl_->joints[impl_->jointIndexOfType(call, id, JointType::Pulley)];
    return distance(transformPoint(impl_->bodies[j.bodyA()].xf, j.localAnchorA),
                    std::get<PulleyJoint>(j.data).groundAnchorA);
}
float World::pulleyJointLengthB(JointId id) const {
    const char* call = "World::pulleyJointLengthB";
    const Joint& j = impl_->joints[impl_->jointIndexOfType(call, id, JointType::Pulley)];
    return distance(transformPoint(impl_->bodies[j.bodyB()].xf, j.localAnchorB),
                    std::get<PulleyJoint>(j.data).groundAnchorB);
}

namespace {
// The friction or motor joint's maximum force and torque: the two types share these calls.
struct Limits {
    float* force;
    float* torque;
};
Limits velocityJointLimits(Joint& j) {
    if (auto* f = std::get_if<FrictionJoint>(&j.data)) return {&f->maxForce, &f->maxTorque};
    auto& m = std::get<MotorJoint>(j.data);
    return {&m.maxForce, &m.maxTorque};
}
}  // namespace

std::int32_t World::Impl::velocityJointIndex(const char* call, JointId id) const {
    const std::int32_t index = jointIndex(call, id);
    if (!joints[index].isVelocityOnly()) {
        fail(call, "joint " + std::to_string(index) + " is a " +
                       jointTypeName(joints[index].type()) +
                       " joint; this call is for friction and motor joints");
    }
    return index;
}

float World::jointMaxForce(JointId id) const {
    Joint& j = impl_->joints[impl_->velocityJointIndex("World::jointMaxForce", id)];
    return *velocityJointLimits(j).force;
}
void World::setJointMaxForce(JointId id, float force) {
    const char* call = "World::setJointMaxForce";
    impl_->setJoint(
        call, [&] { return impl_->velocityJointIndex(call, id); },
        [&](const Joint&) { requireNonNegative(call, "force", force); },
        [&](Joint& j) { *velocityJointLimits(j).force = force; });
}
float World::jointMaxTorque(JointId id) const {
    Joint& j = impl_->joints[impl_->velocityJointIndex("World::jointMaxTorque", id)];
    return *velocityJointLimits(j).torque;
}
void World::setJointMaxTorque(JointId id, float torque) {
    const char* call = "World::setJointMaxTorque";
    impl_->setJoint(
        call, [&] { return impl_->velocityJointIndex(call, id); },
        [&](const Joint&) { requireNonNegative(call, "torque", torque); },
        [&](Joint& j) { *velocityJointLimits(j).torque = torque; });
}

Vec2 World::motorJointLinearOffset(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointLinearOffset", id, JointType::Motor)
        .linearOffset;
}
void World::setMotorJointLinearOffset(JointId id, Vec2 offset) {
    const char* call = "World::setMotorJointLinearOffset";
    impl_->setJointData<MotorJoint>(
        call, id, JointType::Motor, [&] { requireCoordinate(call, "offset", offset); },
        [&](MotorJoint& m) { m.linearOffset = offset; });
}
float World::motorJointAngularOffset(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointAngularOffset", id, JointType::Motor)
        .angularOffset;
}
void World::setMotorJointAngularOffset(JointId id, float offset) {
    const char* call = "World::setMotorJointAngularOffset";
    impl_->setJointData<MotorJoint>(
        call, id, JointType::Motor, [&] { requireMagnitude(call, "offset", offset); },
        [&](MotorJoint& m) { m.angularOffset = offset; });
}
float World::motorJointCorrectionFactor(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointCorrectionFactor", id, JointType::Motor)
        .correctionFactor;
}
void World::setMotorJointCorrectionFactor(JointId id, float factor) {
    const char* call = "World::setMotorJointCorrectionFactor";
    impl_->setJointData<MotorJoint>(
        call, id, JointType::Motor, [&] { requireInRange(call, "factor", factor, 0.0f, 1.0f); },
        [&](MotorJoint& m) { m.correctionFactor = factor; });
}

// --- prismatic and wheel joints ----------------------------------------------------------------

namespace {
/// The axis in body A's frame of a joint that slides along one.
Vec2 localAxisOf(const Joint& j) {
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) return wheel->localAxisA;
    return std::get<PrismaticJoint>(j.data).localAxisA;
}
}  // namespace

float World::jointTranslation(JointId id) const {
    const char* call = "World::jointTranslation";
    const Joint& j =
        impl_->joints[impl_->jointIndexOfTypes(call, id, JointType::Prismatic, JointType::Wheel)];
    const Transform& xfA = impl_->bodies[j.bodyA()].xf;
    const Transform& xfB = impl_->bodies[j.bodyB()].xf;
    const Vec2 d = transformPoint(xfB, j.localAnchorB) - transformPoint(xfA, j.localAnchorA);
    return dot(rotate(xfA.q, localAxisOf(j)), d);
}

float World::jointTranslationSpeed(JointId id) const {
    const char* call = "World::jointTranslationSpeed";
    const Joint& j =
        impl_->joints[impl_->jointIndexOfTypes(call, id, JointType::Prismatic, JointType::Wheel)];
    const Body& a = impl_->bodies[j.bodyA()];
    const Body& b = impl_->bodies[j.bodyB()];
    const Vec2 rA = rotate(a.xf.q, j.localAnchorA - a.localCenter);
    const Vec2 rB = rotate(b.xf.q, j.localAnchorB - b.localCenter);
    const Vec2 d = (b.center + rB) - (a.center + rA);
    const Vec2 axis = rotate(a.xf.q, localAxisOf(j));
    // The axis turns with A: d . (wA x axis), plus the anchors' relative velocity along it.
    const Vec2 vA = a.linearVelocity + cross(a.angularVelocity, rA);
    const Vec2 vB = b.linearVelocity + cross(b.angularVelocity, rB);
    return dot(d, cross(a.angularVelocity, axis)) + dot(axis, vB - vA);
}

Vec2 World::wheelJointAxis(JointId id) const {
    const Joint& j =
        impl_->joints[impl_->jointIndexOfType("World::wheelJointAxis", id, JointType::Wheel)];
    return rotate(impl_->bodies[j.bodyA()].xf.q, std::get<WheelJoint>(j.data).localAxisA);
}

float World::pulleyJointRestLengthA(JointId id) const {
    return std::get<PulleyJoint>(impl_
                                     ->joints[impl_->jointIndexOfType(
                                         "World::pulleyJointRestLengthA", id, JointType::Pulley)]
                                     .data)
        .lengthA;
}
float World::pulleyJointRestLengthB(JointId id) const {
    return std::get<PulleyJoint>(impl_
                                     ->joints[impl_->jointIndexOfType(
                                         "World::pulleyJointRestLengthB", id, JointType::Pulley)]
                                     .data)
        .lengthB;
}

Vec2 World::prismaticJointAxis(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndexOfType("World::prismaticJointAxis", id,
                                                           JointType::Prismatic)];
    return rotate(impl_->bodies[j.bodyA()].xf.q, std::get<PrismaticJoint>(j.data).localAxisA);
}

TranslationLimit World::prismaticJointLimit(JointId id) const {
    const PrismaticJoint& p =
        impl_->jointData<PrismaticJoint>("World::prismaticJointLimit", id, JointType::Prismatic);
    return {p.enableLimit, p.lowerTranslation, p.upperTranslation};
}
void World::setPrismaticJointLimit(JointId id, const TranslationLimit& limit) {
    const char* call = "World::setPrismaticJointLimit";
    impl_->setJointData<PrismaticJoint>(
        call, id, JointType::Prismatic, [&] { checkTranslationLimit(call, "limit", limit); },
        [&](PrismaticJoint& p) { setLimit(p, limit); });
}
LinearMotor World::prismaticJointMotor(JointId id) const {
    const PrismaticJoint& p =
        impl_->jointData<PrismaticJoint>("World::prismaticJointMotor", id, JointType::Prismatic);
    return {p.enableMotor, p.motorSpeed, p.maxMotorForce};
}
void World::setPrismaticJointMotor(JointId id, const LinearMotor& motor) {
    const char* call = "World::setPrismaticJointMotor";
    impl_->setJointData<PrismaticJoint>(
        call, id, JointType::Prismatic, [&] { checkLinearMotor(call, "motor", motor); },
        [&](PrismaticJoint& p) { setMotor(p, motor); });
}
JointSpring World::prismaticJointSpring(JointId id) const {
    const PrismaticJoint& p =
        impl_->jointData<PrismaticJoint>("World::prismaticJointSpring", id, JointType::Prismatic);
    return {p.enableSpring, p.hertz, p.dampingRatio};
}
void World::setPrismaticJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setPrismaticJointSpring";
    impl_->setJointData<PrismaticJoint>(
        call, id, JointType::Prismatic, [&] { checkSpring(call, "spring", spring); },
        [&](PrismaticJoint& p) { setSpring(p, spring); });
}
float World::prismaticJointMotorForce(JointId id) const {
    const char* call = "World::prismaticJointMotorForce";
    const Joint& j = impl_->joints[impl_->jointIndexOfType(call, id, JointType::Prismatic)];
    return j.impulseInvDt * std::get<PrismaticJoint>(j.data).motorImpulse;
}

// --- gear joints -----------------------------------------------------------------------------

JointId World::gearJointJoint1(JointId id) const {
    const GearJoint& g = impl_->jointData<GearJoint>("World::gearJointJoint1", id, JointType::Gear);
    return impl_->jointId(g.side1.joint);
}
JointId World::gearJointJoint2(JointId id) const {
    const GearJoint& g = impl_->jointData<GearJoint>("World::gearJointJoint2", id, JointType::Gear);
    return impl_->jointId(g.side2.joint);
}
float World::gearJointRatio(JointId id) const {
    return impl_->jointData<GearJoint>("World::gearJointRatio", id, JointType::Gear).ratio;
}
void World::setGearJointRatio(JointId id, float ratio) {
    const char* call = "World::setGearJointRatio";
    impl_->requireChange(call);
    Impl& w = *impl_;
    Joint& joint = w.joints[w.jointIndexOfType(call, id, JointType::Gear)];
    checkGearRatio(call, "ratio", ratio);
    GearJoint& g = std::get<GearJoint>(joint.data);
    const Body& a = w.bodies[joint.bodyA()];
    const Body& b = w.bodies[joint.bodyB()];
    const Body& c = w.bodies[g.side1.base];
    const Body& d = w.bodies[g.side2.base];
    const float error = g.error(a, b, c, d);
    g.ratio = ratio;
    g.constant = (g.side1.coordinate(c, a) + ratio * g.side2.coordinate(d, b)) - error;
    w.wakeJointBodies(joint);
}

// --- weld joints -----------------------------------------------------------------------------

JointSpring World::weldJointLinearSpring(JointId id) const {
    return impl_->jointData<WeldJoint>("World::weldJointLinearSpring", id, JointType::Weld)
        .linearSpring;
}
JointSpring World::weldJointAngularSpring(JointId id) const {
    return impl_->jointData<WeldJoint>("World::weldJointAngularSpring", id, JointType::Weld)
        .angularSpring;
}
void World::setWeldJointLinearSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setWeldJointLinearSpring";
    impl_->setJointData<WeldJoint>(
        call, id, JointType::Weld, [&] { checkSpring(call, "spring", spring); },
        [&](WeldJoint& w) { w.linearSpring = spring; });
}
void World::setWeldJointAngularSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setWeldJointAngularSpring";
    impl_->setJointData<WeldJoint>(
        call, id, JointType::Weld, [&] { checkSpring(call, "spring", spring); },
        [&](WeldJoint& w) { w.angularSpring = spring; });
}

// --- wheel joints ----------------------------------------------------------------------------

JointSpring World::wheelJointSpring(JointId id) const {
    return impl_->jointData<WheelJoint>("World::wheelJointSpring", id, JointType::Wheel).spring;
}
void World::setWheelJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setWheelJointSpring";
    impl_->setJointData<WheelJoint>(
        call, id, JointType::Wheel, [&] { checkSpring(call, "spring", spring); },
        [&](WheelJoint& w) { w.spring = spring; });
}
TranslationLimit World::wheelJointLimit(JointId id) const {
    const WheelJoint& w =
        impl_->jointData<WheelJoint>("World::wheelJointLimit", id, JointType::Wheel);
    return {w.enableLimit, w.lowerTranslation, w.upperTranslation};
}
void World::setWheelJointLimit(JointId id, const TranslationLimit& limit) {
    const char* call = "World::setWheelJointLimit";
    impl_->setJointData<WheelJoint>(
        call, id, JointType::Wheel, [&] { checkTranslationLimit(call, "limit", limit); },
        [&](WheelJoint& w) { setLimit(w, limit); });
}

}  // namespace pivot
