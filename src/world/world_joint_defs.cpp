// The World facade, part four: creating joints, one def at a time. The checks every def shares
// come first; a def that fails any check is refused before anything changes.
#include <utility>

#include "world/joint_settings.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

namespace {

// The checks and fields every def shares: two distinct live bodies of this world, and the
// break thresholds.
template <typename Def>
std::pair<std::int32_t, std::int32_t> checkBodies(const char* call, const Def& def,
                                                  const World::Impl& w) {
    std::int32_t a = checkHandle(call, "def.bodyA", def.bodyA, w.bodies, w.id);
    std::int32_t b = checkHandle(call, "def.bodyB", def.bodyB, w.bodies, w.id);
    if (a == b) fail(call, "def.bodyA and def.bodyB are the same body; a joint needs two bodies");
    requireNonNegative(call, "def.breakForce", def.breakForce);
    requireNonNegative(call, "def.breakTorque", def.breakTorque);
    return {a, b};
}
template <typename Def>
Joint jointFromDef(const Def& def, std::int32_t a, std::int32_t b) {
    Joint joint;
    joint.edges[0].body = a;
    joint.edges[1].body = b;
    joint.collideConnected = def.collideConnected;
    joint.userData = def.userData;
    joint.breakForce = def.breakForce;
    joint.breakTorque = def.breakTorque;
    return joint;
}

// And those of the joints with a position error: the strategy, its bias or softness and the
// let-go separation.
template <typename Def>
PositionSolver checkSolverOf(const char* call, const Def& def, const World::Impl& w) {
    const PositionSolver solver = def.positionSolver.value_or(w.settings.defaultPositionSolver);
    checkSolver(call, "def.positionSolver", solver);
    return solver;
}
template <typename Def>
void checkBiasAndLetGo(const char* call, const Def& def) {
    if (def.biasFactor) checkBiasFactor(call, "def.biasFactor", *def.biasFactor);
    checkExtraPositionIterations(call, "def.extraPositionIterations", def.extraPositionIterations);
    checkSoftness(call, "def.softness", def.softness);
    if (def.letGoSeparation) {
        requireNonNegative(call, "def.letGoSeparation", *def.letGoSeparation);
    }
}
template <typename Def>
void setStrategyFields(Joint& joint, const Def& def, PositionSolver solver) {
    joint.solver = solver;
    joint.hasBiasOverride = def.biasFactor.has_value();
    joint.biasOverride = def.biasFactor.value_or(0.0f);
    joint.extraPositionIterations = def.extraPositionIterations;
    joint.softness = def.softness;
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
// The defs with an axis (prismatic, wheel): in body A's frame, or in the world's at creation; a
// def that sets both is refused. Returns the axis normalised.
template <typename Def>
Vec2 checkAxis(const char* call, const Def& def) {
    const Vec2 unit = checkedUnitAxis(call, def.worldAxis ? "def.worldAxis" : "def.localAxisA",
                                      def.worldAxis.value_or(def.localAxisA));
    if (def.worldAxis && def.localAxisA != Vec2{1.0f, 0.0f}) {
        fail(call, "def.worldAxis " + formatVec2(*def.worldAxis) +
                       " is set together with def.localAxisA " + formatVec2(def.localAxisA) +
                       "; the world axis would replace it: set one or the other");
    }
    return unit;
}
template <typename Def>
Vec2 axisInBodyA(const Def& def, Vec2 unitAxis, const Body& bodyA) {
    return def.worldAxis ? inverseRotate(bodyA.xf.q, unitAxis) : unitAxis;
}
}  // namespace

JointId World::createJoint(const RevoluteJointDef& def) {
    const char* call = "World::createJoint";
    impl_->requireStructureChange(call);
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
    impl_->requireStructureChange(call);
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
    impl_->requireStructureChange(call);
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
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireMagnitude(call, "def.referenceAngle", def.referenceAngle);
    const Vec2 unitAxis = checkAxis(call, def);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkWorldAnchor(call, def);
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
    prismatic.localAxisA = axisInBodyA(def, unitAxis, bodyA);
    setLimit(prismatic, def.limit);
    setMotor(prismatic, def.motor);
    setSpring(prismatic, def.spring);
    return w.addJoint(joint);
}

JointId World::createJoint(const WeldJointDef& def) {
    const char* call = "World::createJoint";
    impl_->requireStructureChange(call);
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
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    const Vec2 unitAxis = checkAxis(call, def);
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
    wheel.localAxisA = axisInBodyA(def, unitAxis, bodyA);
    wheel.spring = def.spring;
    setLimit(wheel, def.limit);
    setMotor(wheel, def.motor);
    return w.addJoint(joint);
}

// One joint a gear couples: a live revolute or prismatic joint of this world.
GearSide checkGearSide(const char* call, const char* field, JointId id, const World::Impl& w) {
    const std::int32_t index = checkHandle(call, field, id, w.joints, w.id);
    const Joint& joint = w.joints[index];
    const JointType type = joint.type();
    if (type != JointType::Revolute && type != JointType::Prismatic) {
        fail(call, std::string(field) + " is a " + jointTypeName(type) +
                       " joint; a gear couples revolute and prismatic joints");
    }
    GearSide side;
    side.prismatic = type == JointType::Prismatic;
    side.joint = index;
    side.base = joint.bodyA();
    side.localAnchorBase = joint.localAnchorA;
    side.localAnchorMover = joint.localAnchorB;
    side.referenceAngle = joint.referenceAngle;
    if (side.prismatic) side.localAxis = std::get<PrismaticJoint>(joint.data).localAxisA;
    return side;
}

JointId World::createJoint(const GearJointDef& def) {
    const char* call = "World::createJoint";
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    const GearSide side1 = checkGearSide(call, "def.joint1", def.joint1, w);
    const GearSide side2 = checkGearSide(call, "def.joint2", def.joint2, w);
    if (side1.joint == side2.joint) {
        fail(call, "def.joint1 and def.joint2 are the same joint; a gear couples two");
    }
    const std::int32_t a = w.joints[side1.joint].bodyB();
    const std::int32_t b = w.joints[side2.joint].bodyB();
    if (a == b) {
        fail(call,
             "def.joint1 and def.joint2 move the same body (their body B); the gear "
             "would join that body to itself");
    }
    if (w.bodies[a].type == BodyType::Static && w.bodies[b].type == BodyType::Static) {
        fail(call,
             "def.joint1 and def.joint2 both move a static body (their body B); a gear "
             "turns the bodies its joints move, so one of them must be able to move");
    }
    checkGearRatio(call, "def.ratio", def.ratio);
    const PositionSolver solver = checkSolverOf(call, def, w);
    checkBiasAndLetGo(call, def);

    Joint joint = jointFromDef(def, a, b);
    setStrategyFields(joint, def, solver);
    joint.localAnchorA = side1.localAnchorMover;
    joint.localAnchorB = side2.localAnchorMover;
    GearJoint& gear = joint.data.emplace<GearJoint>();
    gear.side1 = side1;
    gear.side2 = side2;
    gear.ratio = def.ratio;
    gear.constant = side1.coordinate(w.bodies[side1.base], w.bodies[a]) +
                    def.ratio * side2.coordinate(w.bodies[side2.base], w.bodies[b]);
    const JointId id = w.addJoint(joint);
    ++w.joints[side1.joint].gearCount;
    ++w.joints[side2.joint].gearCount;
    return id;
}

JointId World::createJoint(const FrictionJointDef& def) {
    const char* call = "World::createJoint";
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    const auto [a, b] = checkBodies(call, def, w);
    requireCoordinate(call, "def.localAnchorA", def.localAnchorA);
    requireCoordinate(call, "def.localAnchorB", def.localAnchorB);
    requireNonNegative(call, "def.maxForce", def.maxForce);
    requireNonNegative(call, "def.maxTorque", def.maxTorque);
    Joint joint = jointFromDef(def, a, b);
    joint.solver = w.settings.defaultPositionSolver;
    joint.localAnchorA = def.localAnchorA;
    joint.localAnchorB = def.localAnchorB;
    FrictionJoint& friction = joint.data.emplace<FrictionJoint>();
    friction.maxForce = def.maxForce;
    friction.maxTorque = def.maxTorque;
    return w.addJoint(joint);
}

JointId World::createJoint(const MotorJointDef& def) {
    const char* call = "World::createJoint";
    impl_->requireStructureChange(call);
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
    joint.solver = w.settings.defaultPositionSolver;
    MotorJoint& motor = joint.data.emplace<MotorJoint>();
    motor.linearOffset = linearOffset;
    motor.angularOffset = angularOffset;
    motor.maxForce = def.maxForce;
    motor.maxTorque = def.maxTorque;
    motor.correctionFactor = def.correctionFactor;
    return w.addJoint(joint);
}

}  // namespace pivot
