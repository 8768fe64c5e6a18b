// The World facade, part four: joints.
#include <utility>

#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

namespace {
void setLimit(DistanceJoint& joint, const LengthLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.minLength = limit.min;
    joint.maxLength = limit.max;
}
template <typename Storage>
void setSpring(Storage& joint, const JointSpring& spring) {
    joint.enableSpring = spring.enabled;
    joint.hertz = spring.hertz;
    joint.dampingRatio = spring.dampingRatio;
}
void setLimit(PrismaticJoint& joint, const TranslationLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.lowerTranslation = limit.lower;
    joint.upperTranslation = limit.upper;
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
}
void setLimit(WheelJoint& joint, const TranslationLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.lowerTranslation = limit.lower;
    joint.upperTranslation = limit.upper;
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
}
void setMotor(WheelJoint& joint, const JointMotor& motor) {
    joint.enableMotor = motor.enabled;
    joint.motorSpeed = motor.speed;
    joint.maxMotorTorque = motor.maxTorque;
}
void setMotor(PrismaticJoint& joint, const LinearMotor& motor) {
    joint.enableMotor = motor.enabled;
    joint.motorSpeed = motor.speed;
    joint.maxMotorForce = motor.maxForce;
}

// The checks and fields every def shares: two distinct live bodies of this world.
template <typename Def>
std::pair<std::int32_t, std::int32_t> checkBodies(const char* call, const Def& def,
                                                  const World::Impl& w) {
    std::int32_t a = checkHandle(call, "def.bodyA", def.bodyA, w.bodies, w.id);
    std::int32_t b = checkHandle(call, "def.bodyB", def.bodyB, w.bodies, w.id);
    if (a == b) fail(call, "def.bodyA and def.bodyB are the same body; a joint needs two bodies");
    return {a, b};
}
template <typename Def>
Joint jointFromDef(const Def& def, std::int32_t a, std::int32_t b) {
    Joint joint;
    joint.edges[0].body = a;
    joint.edges[1].body = b;
    joint.collideConnected = def.collideConnected;
    joint.userData = def.userData;
    return joint;
}

// And those of the joints with a position error: the strategy, its bias and the let-go
// separation.
template <typename Def>
PositionSolver checkSolverOf(const char* call, const Def& def, const World::Impl& w) {
    const PositionSolver solver = def.positionSolver.value_or(w.defaultPositionSolver);
    checkSolver(call, "def.positionSolver", solver);
    return solver;
}
template <typename Def>
void checkBiasAndLetGo(const char* call, const Def& def) {
    if (def.biasFactor) checkBiasFactor(call, "def.biasFactor", *def.biasFactor);
    if (def.letGoSeparation) {
        requireNonNegative(call, "def.letGoSeparation", *def.letGoSeparation);
    }
}
template <typename Def>
void setStrategyFields(Joint& joint, const Def& def, PositionSolver solver) {
    joint.solver = solver;
    joint.hasBiasOverride = def.biasFactor.has_value();
    joint.biasOverride = def.biasFactor.value_or(0.0f);
    joint.hasLetGoOverride = def.letGoSeparation.has_value();
    joint.letGoOverride = def.letGoSeparation.value_or(0.0f);
}

// The defs with an optional world anchor (revolute, prismatic, weld): it replaces the local
// anchors and the reference angle, so a def that sets both is refused rather than one of them
// ignored.
template <typename Def>
void checkWorldAnchor(const char* call, const Def& def) {
    if (!def.worldAnchor) return;
    requireCoordinate(call, "def.worldAnchor", *def.worldAnchor);
    if (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{} || def.referenceAngle != 0.0f) {
        fail(call, "def.worldAnchor " + formatVec2(*def.worldAnchor) +
                       " is set together with def.localAnchorA " + formatVec2(def.localAnchorA) +
                       ", def.localAnchorB " + formatVec2(def.localAnchorB) +
                       " or def.referenceAngle " + formatFloat(def.referenceAngle) +
                       "; the world anchor would replace them: set one or the other");
    }
}
template <typename Def>
void setAnchors(Joint& joint, const Def& def, const Body& bodyA, const Body& bodyB) {
    if (def.worldAnchor) {
        joint.localAnchorA = inverseTransformPoint(bodyA.xf, *def.worldAnchor);
        joint.localAnchorB = inverseTransformPoint(bodyB.xf, *def.worldAnchor);
        joint.referenceAngle = bodyB.angle - bodyA.angle;
    } else {
        joint.localAnchorA = def.localAnchorA;
        joint.localAnchorB = def.localAnchorB;
        joint.referenceAngle = def.referenceAngle;
    }
}
}  // namespace

const char* jointTypeName(JointType type) {
    switch (type) {
        case JointType::Revolute: return "revolute";
        case JointType::Distance: return "distance";
        case JointType::Pulley: return "pulley";
        case JointType::Friction: return "friction";
        case JointType::Motor: return "motor";
        case JointType::Prismatic: return "prismatic";
        case JointType::Weld: return "weld";
        case JointType::Wheel: return "wheel";
    }
    return "invalid";
}

// A velocity-only joint has no position error for a strategy to correct: choosing one would
// change nothing, so it is refused rather than accepted and ignored.
void requirePositionError(const char* call, std::int32_t index, const Joint& joint) {
    if (joint.isVelocityOnly()) {
        fail(call, "joint " + std::to_string(index) + " is a " + jointTypeName(joint.type()) +
                       " joint, which acts in the velocity phase only and has no position "
                       "error for a strategy to correct");
    }
}

std::int32_t World::Impl::jointIndexOfType(const char* call, JointId id, JointType type) const {
    const std::int32_t index = jointIndex(call, id);
    const JointType actual = joints[index].type();
    if (actual != type) {
        fail(call, "joint " + std::to_string(index) + " is a " + jointTypeName(actual) +
                       " joint; this call is for " + jointTypeName(type) + " joints");
    }
    return index;
}

std::int32_t World::Impl::jointIndexOfTypes(const char* call, JointId id, JointType type,
                                            JointType other) const {
    const std::int32_t index = jointIndex(call, id);
    const JointType actual = joints[index].type();
    if (actual != type && actual != other) {
        fail(call, "joint " + std::to_string(index) + " is a " + jointTypeName(actual) +
                       " joint; this call is for " + jointTypeName(type) + " and " +
                       jointTypeName(other) + " joints");
    }
    return index;
}

JointId World::Impl::addJoint(const Joint& joint) {
    const std::int32_t a = joint.bodyA(), b = joint.bodyB();
    const std::int32_t index = joints.insert(joint);
    linkEdges(joints, bodies, &Body::jointList, index);
    // A joint that forbids its bodies to collide ends any contact between them.
    if (!joint.collideConnected) contactManager.refilterBodyPair(a, b);
    wakeUp(bodies[a]);
    wakeUp(bodies[b]);
    return jointId(index);
}

void World::Impl::removeJoint(std::int32_t index) {
    const Joint& joint = joints[index];
    std::int32_t a = joint.bodyA(), b = joint.bodyB();
    bool preventedCollision = !joint.collideConnected;
    unlinkEdges(joints, bodies, &Body::jointList, index);
    joints.erase(index);
    wakeUp(bodies[a]);
    wakeUp(bodies[b]);
    if (preventedCollision) contactManager.refilterBodyPair(a, b);
}

JointId World::createJoint(const RevoluteJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireMagnitude(call, "def.referenceAngle", def.referenceAngle);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkWorldAnchor(call, def);
    checkBiasAndLetGo(call, def);
    checkLimit(call, "def.limit", def.limit);
    checkMotor(call, "def.motor", def.motor);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    RevoluteJoint& revolute = joint.data.emplace<RevoluteJoint>();
    setAnchors(joint, def, w.bodies[a], w.bodies[b]);
    revolute.enableLimit = def.limit.enabled;
    revolute.lowerAngle = def.limit.lower;
    revolute.upperAngle = def.limit.upper;
    revolute.enableMotor = def.motor.enabled;
    revolute.motorSpeed = def.motor.speed;
    revolute.maxMotorTorque = def.motor.maxTorque;
    return w.addJoint(joint);
}

JointId World::createJoint(const DistanceJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkBiasAndLetGo(call, def);
    const Body& bodyA = w.bodies[a];
    const Body& bodyB = w.bodies[b];
    const float anchorDistance = distance(transformPoint(bodyA.xf, def.localAnchorA),
                                          transformPoint(bodyB.xf, def.localAnchorB));
    const float length = def.length.value_or(anchorDistance);
    checkRestLength(call, def.length ? "def.length" : "def.length (the anchors' distance)", length);
    checkLengthLimit(call, "def.limit", def.limit);
    checkSpring(call, "def.spring", def.spring);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    joint.localAnchorA = def.localAnchorA;
    joint.localAnchorB = def.localAnchorB;
    DistanceJoint& distanceJoint = joint.data.emplace<DistanceJoint>();
    distanceJoint.length = length;
    setLimit(distanceJoint, def.limit);
    setSpring(distanceJoint, def.spring);
    return w.addJoint(joint);
}

JointId World::createJoint(const PulleyJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.groundAnchorA", def.groundAnchorA);
    requireCoordinate(call, "def.groundAnchorB", def.groundAnchorB);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireInRange(call, "def.ratio", def.ratio, kMinPulleyRatio, 1.0f / kMinPulleyRatio);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkBiasAndLetGo(call, def);
    const float currentA =
        distance(transformPoint(w.bodies[a].xf, def.localAnchorA), def.groundAnchorA);
    const float currentB =
        distance(transformPoint(w.bodies[b].xf, def.localAnchorB), def.groundAnchorB);
    const float lengthA = def.lengthA.value_or(currentA);
    const float lengthB = def.lengthB.value_or(currentB);
    checkPulleyLength(call, def.lengthA ? "def.lengthA" : "def.lengthA (anchor A's distance)",
                      lengthA);
    checkPulleyLength(call, def.lengthB ? "def.lengthB" : "def.lengthB (anchor B's distance)",
                      lengthB);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    joint.localAnchorA = def.localAnchorA;
    joint.localAnchorB = def.localAnchorB;
    PulleyJoint& pulley = joint.data.emplace<PulleyJoint>();
    pulley.groundAnchorA = def.groundAnchorA;
    pulley.groundAnchorB = def.groundAnchorB;
    pulley.lengthA = lengthA;
    pulley.lengthB = lengthB;
    pulley.ratio = def.ratio;
    return w.addJoint(joint);
}

JointId World::createJoint(const PrismaticJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireMagnitude(call, "def.referenceAngle", def.referenceAngle);
    const Vec2 givenAxis = def.worldAxis.value_or(def.localAxisA);
    const Vec2 unitAxis =
        checkedUnitAxis(call, def.worldAxis ? "def.worldAxis" : "def.localAxisA", givenAxis);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkWorldAnchor(call, def);
    if (def.worldAxis && def.localAxisA != Vec2{1.0f, 0.0f}) {
        fail(call, "def.worldAxis " + formatVec2(*def.worldAxis) +
                       " is set together with def.localAxisA " + formatVec2(def.localAxisA) +
                       "; the world axis would replace it: set one or the other");
    }
    checkBiasAndLetGo(call, def);
    checkTranslationLimit(call, "def.limit", def.limit);
    checkLinearMotor(call, "def.motor", def.motor);
    checkSpring(call, "def.spring", def.spring);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    const Body& bodyA = w.bodies[a];
    const Body& bodyB = w.bodies[b];
    setAnchors(joint, def, bodyA, bodyB);
    PrismaticJoint& prismatic = joint.data.emplace<PrismaticJoint>();
    prismatic.localAxisA = def.worldAxis ? inverseRotate(bodyA.xf.q, unitAxis) : unitAxis;
    setLimit(prismatic, def.limit);
    setMotor(prismatic, def.motor);
    setSpring(prismatic, def.spring);
    return w.addJoint(joint);
}

JointId World::createJoint(const WeldJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireMagnitude(call, "def.referenceAngle", def.referenceAngle);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkWorldAnchor(call, def);
    checkBiasAndLetGo(call, def);
    checkSpring(call, "def.linearSpring", def.linearSpring);
    checkSpring(call, "def.angularSpring", def.angularSpring);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    setAnchors(joint, def, w.bodies[a], w.bodies[b]);
    WeldJoint& weld = joint.data.emplace<WeldJoint>();
    weld.linearSpring = def.linearSpring;
    weld.angularSpring = def.angularSpring;
    return w.addJoint(joint);
}

JointId World::createJoint(const WheelJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    const Vec2 unitAxis = checkedUnitAxis(call, def.worldAxis ? "def.worldAxis" : "def.localAxisA",
                                          def.worldAxis.value_or(def.localAxisA));
    const PositionSolver solver = checkSolverOf(call, def, w);
    if (def.worldAnchor) {
        requireCoordinate(call, "def.worldAnchor", *def.worldAnchor);
        if (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{}) {
            fail(call, "def.worldAnchor " + formatVec2(*def.worldAnchor) +
                           " is set together with def.localAnchorA " +
                           formatVec2(def.localAnchorA) + " or def.localAnchorB " +
                           formatVec2(def.localAnchorB) +
                           "; the world anchor would replace them: set one or the other");
        }
    }
    if (def.worldAxis && def.localAxisA != Vec2{1.0f, 0.0f}) {
        fail(call, "def.worldAxis " + formatVec2(*def.worldAxis) +
                       " is set together with def.localAxisA " + formatVec2(def.localAxisA) +
                       "; the world axis would replace it: set one or the other");
    }
    checkBiasAndLetGo(call, def);
    checkSpring(call, "def.spring", def.spring);
    checkTranslationLimit(call, "def.limit", def.limit);
    checkMotor(call, "def.motor", def.motor);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    const Body& bodyA = w.bodies[a];
    joint.localAnchorA =
        def.worldAnchor ? inverseTransformPoint(bodyA.xf, *def.worldAnchor) : def.localAnchorA;
    joint.localAnchorB = def.worldAnchor ? inverseTransformPoint(w.bodies[b].xf, *def.worldAnchor)
                                         : def.localAnchorB;
    WheelJoint& wheel = joint.data.emplace<WheelJoint>();
    wheel.localAxisA = def.worldAxis ? inverseRotate(bodyA.xf.q, unitAxis) : unitAxis;
    wheel.spring = def.spring;
    setLimit(wheel, def.limit);
    setMotor(wheel, def.motor);
    return w.addJoint(joint);
}

JointId World::createJoint(const FrictionJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireNonNegative(call, "def.maxForce", def.maxForce);
    requireNonNegative(call, "def.maxTorque", def.maxTorque);
    Joint joint = jointFromDef(def, a, b);
    joint.solver = w.defaultPositionSolver;
    joint.localAnchorA = def.localAnchorA;
    joint.localAnchorB = def.localAnchorB;
    FrictionJoint& friction = joint.data.emplace<FrictionJoint>();
    friction.maxForce = def.maxForce;
    friction.maxTorque = def.maxTorque;
    return w.addJoint(joint);
}

JointId World::createJoint(const MotorJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    if (def.linearOffset) requireCoordinate(call, "def.linearOffset", *def.linearOffset);
    if (def.angularOffset) requireMagnitude(call, "def.angularOffset", *def.angularOffset);
    requireNonNegative(call, "def.maxForce", def.maxForce);
    requireNonNegative(call, "def.maxTorque", def.maxTorque);
    requireInRange(call, "def.correctionFactor", def.correctionFactor, 0.0f, 1.0f);
    const Body& bodyA = w.bodies[a];
    const Body& bodyB = w.bodies[b];
    const Vec2 linearOffset =
        def.linearOffset.value_or(inverseTransformPoint(bodyA.xf, bodyB.xf.p));
    const float angularOffset = def.angularOffset.value_or(bodyB.angle - bodyA.angle);
    // Offsets taken from far-apart bodies can still be out of range.
    requireCoordinate(call, "def.linearOffset (body B's origin in A's frame)", linearOffset);
    requireMagnitude(call, "def.angularOffset (angleB - angleA)", angularOffset);
    Joint joint = jointFromDef(def, a, b);
    joint.solver = w.defaultPositionSolver;
    MotorJoint& motor = joint.data.emplace<MotorJoint>();
    motor.linearOffset = linearOffset;
    motor.angularOffset = angularOffset;
    motor.maxForce = def.maxForce;
    motor.maxTorque = def.maxTorque;
    motor.correctionFactor = def.correctionFactor;
    return w.addJoint(joint);
}

void World::destroyJoint(JointId id) {
    impl_->removeJoint(impl_->jointIndex("World::destroyJoint", id));
}

bool World::isValid(JointId id) const {
    return id.world == impl_->id && impl_->joints.isAlive(id.index) &&
           impl_->joints.generation(id.index) == id.generation;
}

int World::jointCount() const {
    return impl_->joints.size();
}

BodyId World::jointBodyA(JointId id) const {
    return impl_->bodyId(impl_->joints[impl_->jointIndex("World::jointBodyA", id)].bodyA());
}
BodyId World::jointBodyB(JointId id) const {
    return impl_->bodyId(impl_->joints[impl_->jointIndex("World::jointBodyB", id)].bodyB());
}
Vec2 World::jointAnchorA(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointAnchorA", id)];
    return transformPoint(impl_->bodies[j.bodyA()].xf, j.localAnchorA);
}
Vec2 World::jointAnchorB(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointAnchorB", id)];
    return transformPoint(impl_->bodies[j.bodyB()].xf, j.localAnchorB);
}
float World::jointSeparation(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointSeparation", id)];
    return j.separation(impl_->bodies[j.bodyA()].xf, impl_->bodies[j.bodyB()].xf);
}
float World::jointLength(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointLength", id)];
    return j.anchorDistance(impl_->bodies[j.bodyA()].xf, impl_->bodies[j.bodyB()].xf);
}
JointType World::jointType(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointType", id)].type();
}
bool World::isJointLetGo(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::isJointLetGo", id)].letGo;
}

void World::rearmJoint(JointId id) {
    Joint& j = impl_->joints[impl_->jointIndex("World::rearmJoint", id)];
    if (!j.letGo) return;
    j.letGo = false;  // letGoFor cleared its impulses
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

float World::jointLetGoSeparation(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointLetGoSeparation", id)];
    return j.letGoSeparation(impl_->jointLetGoSeparation);
}

void World::setJointLetGoSeparation(JointId id, std::optional<float> separation) {
    const char* call = "World::setJointLetGoSeparation";
    Joint& j = impl_->joints[impl_->jointIndex(call, id)];
    if (separation) requireNonNegative(call, "separation", *separation);
    j.hasLetGoOverride = separation.has_value();
    j.letGoOverride = separation.value_or(0.0f);
}

std::vector<JointLetGoEvent> World::jointLetGoEvents() const {
    return impl_->letGoEvents;
}
Vec2 World::jointReactionForce(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointReactionForce", id)];
    if (const auto* distance = std::get_if<DistanceJoint>(&j.data)) {
        return (j.impulseInvDt * distance->axialImpulse()) * distance->axis;
    }
    if (const auto* pulley = std::get_if<PulleyJoint>(&j.data)) {
        return (j.impulseInvDt * -pulley->ratio * pulley->impulse) * pulley->axisB;
    }
    if (const auto* friction = std::get_if<FrictionJoint>(&j.data)) {
        return j.impulseInvDt * friction->linearImpulse;
    }
    if (const auto* motor = std::get_if<MotorJoint>(&j.data)) {
        return j.impulseInvDt * motor->linearImpulse;
    }
    if (const auto* weld = std::get_if<WeldJoint>(&j.data)) {
        return j.impulseInvDt * Vec2{weld->impulse.x, weld->impulse.y};
    }
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        const Vec2 perp{-wheel->axis.y, wheel->axis.x};
        return j.impulseInvDt * (wheel->impulse * perp + wheel->axialImpulse() * wheel->axis);
    }
    if (const auto* prismatic = std::get_if<PrismaticJoint>(&j.data)) {
        const Vec2 perp{-prismatic->axis.y, prismatic->axis.x};
        return j.impulseInvDt *
               (prismatic->impulse.x * perp + prismatic->axialImpulse() * prismatic->axis);
    }
    return j.impulseInvDt * std::get<RevoluteJoint>(j.data).impulse;
}

float World::jointAngle(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointAngle", id)];
    return impl_->bodies[j.bodyB()].angle - impl_->bodies[j.bodyA()].angle - j.referenceAngle;
}
float World::jointSpeed(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointSpeed", id)];
    return impl_->bodies[j.bodyB()].angularVelocity - impl_->bodies[j.bodyA()].angularVelocity;
}
float World::jointReactionTorque(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointReactionTorque", id)];
    if (const auto* r = std::get_if<RevoluteJoint>(&j.data)) {
        return j.impulseInvDt * (r->motorImpulse + r->lowerImpulse - r->upperImpulse);
    }
    if (const auto* friction = std::get_if<FrictionJoint>(&j.data)) {
        return j.impulseInvDt * friction->angularImpulse;
    }
    if (const auto* motor = std::get_if<MotorJoint>(&j.data)) {
        return j.impulseInvDt * motor->angularImpulse;
    }
    if (const auto* prismatic = std::get_if<PrismaticJoint>(&j.data)) {
        return j.impulseInvDt * prismatic->impulse.y;
    }
    if (const auto* weld = std::get_if<WeldJoint>(&j.data)) {
        return j.impulseInvDt * weld->impulse.z;
    }
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        return j.impulseInvDt * wheel->motorImpulse;
    }
    return 0.0f;
}
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
    Joint& j = impl_->joints[impl_->jointIndexOfType(call, id, JointType::Revolute)];
    checkLimit(call, "limit", limit);
    RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
    r.enableLimit = limit.enabled;
    r.lowerAngle = limit.lower;
    r.upperAngle = limit.upper;
    r.lowerImpulse = 0.0f;
    r.upperImpulse = 0.0f;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
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
    Joint& j =
        impl_->joints[impl_->jointIndexOfTypes(call, id, JointType::Revolute, JointType::Wheel)];
    checkMotor(call, "motor", motor);
    if (auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        setMotor(*wheel, motor);
    } else {
        RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
        r.enableMotor = motor.enabled;
        r.motorSpeed = motor.speed;
        r.maxMotorTorque = motor.maxTorque;
    }
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

float World::distanceJointRestLength(JointId id) const {
    return impl_
        ->jointData<DistanceJoint>("World::distanceJointRestLength", id, JointType::Distance)
        .length;
}
void World::setDistanceJointRestLength(JointId id, float length) {
    const char* call = "World::setDistanceJointRestLength";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Distance);
    checkRestLength(call, "length", length);
    Joint& j = impl_->joints[index];
    std::get<DistanceJoint>(j.data).length = length;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
LengthLimit World::distanceJointLimit(JointId id) const {
    const DistanceJoint& d =
        impl_->jointData<DistanceJoint>("World::distanceJointLimit", id, JointType::Distance);
    return {d.enableLimit, d.minLength, d.maxLength};
}
void World::setDistanceJointLimit(JointId id, const LengthLimit& limit) {
    const char* call = "World::setDistanceJointLimit";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Distance);
    checkLengthLimit(call, "limit", limit);
    Joint& j = impl_->joints[index];
    DistanceJoint& d = std::get<DistanceJoint>(j.data);
    setLimit(d, limit);
    d.lowerImpulse = d.upperImpulse = 0.0f;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
JointSpring World::distanceJointSpring(JointId id) const {
    const DistanceJoint& d =
        impl_->jointData<DistanceJoint>("World::distanceJointSpring", id, JointType::Distance);
    return {d.enableSpring, d.hertz, d.dampingRatio};
}
void World::setDistanceJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setDistanceJointSpring";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Distance);
    checkSpring(call, "spring", spring);
    Joint& j = impl_->joints[index];
    setSpring(std::get<DistanceJoint>(j.data), spring);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

PositionSolver World::jointPositionSolver(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointPositionSolver", id)].solver;
}

void World::setJointPositionSolver(JointId id, PositionSolver solver) {
    const char* call = "World::setJointPositionSolver";
    Joint& j = impl_->joints[impl_->jointIndex(call, id)];
    requirePositionError(call, id.index, j);
    checkSolver(call, "solver", solver);
    j.solver = solver;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

float World::jointBiasFactor(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointBiasFactor", id)].biasFactor();
}

void World::setJointBiasFactor(JointId id, std::optional<float> biasFactor) {
    const char* call = "World::setJointBiasFactor";
    Joint& j = impl_->joints[impl_->jointIndex(call, id)];
    requirePositionError(call, id.index, j);
    if (biasFactor) checkBiasFactor(call, "biasFactor", *biasFactor);
    j.hasBiasOverride = biasFactor.has_value();
    j.biasOverride = biasFactor.value_or(0.0f);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
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
    Joint& j = impl_->joints[impl_->velocityJointIndex(call, id)];
    requireNonNegative(call, "force", force);
    *velocityJointLimits(j).force = force;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
float World::jointMaxTorque(JointId id) const {
    Joint& j = impl_->joints[impl_->velocityJointIndex("World::jointMaxTorque", id)];
    return *velocityJointLimits(j).torque;
}
void World::setJointMaxTorque(JointId id, float torque) {
    const char* call = "World::setJointMaxTorque";
    Joint& j = impl_->joints[impl_->velocityJointIndex(call, id)];
    requireNonNegative(call, "torque", torque);
    *velocityJointLimits(j).torque = torque;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

Vec2 World::motorJointLinearOffset(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointLinearOffset", id, JointType::Motor)
        .linearOffset;
}
void World::setMotorJointLinearOffset(JointId id, Vec2 offset) {
    const char* call = "World::setMotorJointLinearOffset";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Motor);
    requireCoordinate(call, "offset", offset);
    Joint& j = impl_->joints[index];
    std::get<MotorJoint>(j.data).linearOffset = offset;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
float World::motorJointAngularOffset(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointAngularOffset", id, JointType::Motor)
        .angularOffset;
}
void World::setMotorJointAngularOffset(JointId id, float offset) {
    const char* call = "World::setMotorJointAngularOffset";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Motor);
    requireMagnitude(call, "offset", offset);
    Joint& j = impl_->joints[index];
    std::get<MotorJoint>(j.data).angularOffset = offset;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
float World::motorJointCorrectionFactor(JointId id) const {
    return impl_->jointData<MotorJoint>("World::motorJointCorrectionFactor", id, JointType::Motor)
        .correctionFactor;
}
void World::setMotorJointCorrectionFactor(JointId id, float factor) {
    const char* call = "World::setMotorJointCorrectionFactor";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Motor);
    requireInRange(call, "factor", factor, 0.0f, 1.0f);
    Joint& j = impl_->joints[index];
    std::get<MotorJoint>(j.data).correctionFactor = factor;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

std::uint64_t World::jointUserData(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointUserData", id)].userData;
}

void World::setJointUserData(JointId id, std::uint64_t userData) {
    impl_->joints[impl_->jointIndex("World::setJointUserData", id)].userData = userData;
}

std::vector<JointId> World::jointIds() const {
    std::vector<JointId> ids;
    impl_->joints.forEach(
        [&](std::int32_t index, const Joint&) { ids.push_back(impl_->jointId(index)); });
    return ids;
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
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Prismatic);
    checkTranslationLimit(call, "limit", limit);
    Joint& j = impl_->joints[index];
    setLimit(std::get<PrismaticJoint>(j.data), limit);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
LinearMotor World::prismaticJointMotor(JointId id) const {
    const PrismaticJoint& p =
        impl_->jointData<PrismaticJoint>("World::prismaticJointMotor", id, JointType::Prismatic);
    return {p.enableMotor, p.motorSpeed, p.maxMotorForce};
}
void World::setPrismaticJointMotor(JointId id, const LinearMotor& motor) {
    const char* call = "World::setPrismaticJointMotor";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Prismatic);
    checkLinearMotor(call, "motor", motor);
    Joint& j = impl_->joints[index];
    setMotor(std::get<PrismaticJoint>(j.data), motor);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
JointSpring World::prismaticJointSpring(JointId id) const {
    const PrismaticJoint& p =
        impl_->jointData<PrismaticJoint>("World::prismaticJointSpring", id, JointType::Prismatic);
    return {p.enableSpring, p.hertz, p.dampingRatio};
}
void World::setPrismaticJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setPrismaticJointSpring";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Prismatic);
    checkSpring(call, "spring", spring);
    Joint& j = impl_->joints[index];
    setSpring(std::get<PrismaticJoint>(j.data), spring);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
float World::prismaticJointMotorForce(JointId id) const {
    const char* call = "World::prismaticJointMotorForce";
    const Joint& j = impl_->joints[impl_->jointIndexOfType(call, id, JointType::Prismatic)];
    return j.impulseInvDt * std::get<PrismaticJoint>(j.data).motorImpulse;
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
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Weld);
    checkSpring(call, "spring", spring);
    Joint& j = impl_->joints[index];
    std::get<WeldJoint>(j.data).linearSpring = spring;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
void World::setWeldJointAngularSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setWeldJointAngularSpring";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Weld);
    checkSpring(call, "spring", spring);
    Joint& j = impl_->joints[index];
    std::get<WeldJoint>(j.data).angularSpring = spring;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

// --- wheel joints ----------------------------------------------------------------------------

JointSpring World::wheelJointSpring(JointId id) const {
    return impl_->jointData<WheelJoint>("World::wheelJointSpring", id, JointType::Wheel).spring;
}
void World::setWheelJointSpring(JointId id, const JointSpring& spring) {
    const char* call = "World::setWheelJointSpring";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Wheel);
    checkSpring(call, "spring", spring);
    Joint& j = impl_->joints[index];
    std::get<WheelJoint>(j.data).spring = spring;
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}
TranslationLimit World::wheelJointLimit(JointId id) const {
    const WheelJoint& w =
        impl_->jointData<WheelJoint>("World::wheelJointLimit", id, JointType::Wheel);
    return {w.enableLimit, w.lowerTranslation, w.upperTranslation};
}
void World::setWheelJointLimit(JointId id, const TranslationLimit& limit) {
    const char* call = "World::setWheelJointLimit";
    const std::int32_t index = impl_->jointIndexOfType(call, id, JointType::Wheel);
    checkTranslationLimit(call, "limit", limit);
    Joint& j = impl_->joints[index];
    setLimit(std::get<WheelJoint>(j.data), limit);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

}  // namespace pivot
