// The World facade, part four: joints, what every type answers (the typed calls are in
// world_joint_types.cpp, creation in world_joint_defs.cpp).
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

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
        case JointType::Gear: return "gear";
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

// A joint's breakForce or breakTorque. The island plans read them (the revision bumps), and the
// joint's bodies wake, as every setter's do: a sleeping joint is not measured.
void setBreakThreshold(World::Impl& w, const char* call, JointId id, const char* name, float value,
                       float Joint::*threshold) {
    w.setJoint(
        call, [&] { return w.jointIndex(call, id); },
        [&](const Joint&) { requireNonNegative(call, name, value); },
        [&](Joint& j) {
            j.*threshold = value;
            w.islandRevision.bump();
        });
}

// A strategy's setting (solver, bias factor, softness, extra iterations): only a joint with a
// position error has one, so a velocity-only joint is refused before the value is checked.
template <typename Check, typename Apply>
void setStrategySetting(World::Impl& w, const char* call, JointId id, Check&& check,
                        Apply&& apply) {
    w.setJoint(
        call, [&] { return w.jointIndex(call, id); },
        [&](const Joint& j) {
            requirePositionError(call, id.index, j);
            check();
        },
        apply);
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
    islandRevision.bump();
    // A joint that forbids its bodies to collide ends any contact between them.
    if (!joint.collideConnected) contactManager.refilterBodyPair(a, b);
    wakeUp(bodies[a], islandRevision);
    wakeUp(bodies[b], islandRevision);
    return jointId(index);
}

void World::Impl::removeJoint(std::int32_t index) {
    const Joint& joint = joints[index];
    if (const auto* gear = std::get_if<GearJoint>(&joint.data)) {
        --joints[gear->side1.joint].gearCount;
        --joints[gear->side2.joint].gearCount;
    }
    std::int32_t a = joint.bodyA(), b = joint.bodyB();
    bool preventedCollision = !joint.collideConnected;
    unlinkEdges(joints, bodies, &Body::jointList, index);
    joints.erase(index);
    islandRevision.bump();
    wakeUp(bodies[a], islandRevision);
    wakeUp(bodies[b], islandRevision);
    if (preventedCollision) contactManager.refilterBodyPair(a, b);
}

void World::Impl::removeJointAndItsGears(std::int32_t index) {
    if (joints[index].gearCount > 0) {
        joints.forEach([&](std::int32_t gearIndex, const Joint& gear) {
            const auto* g = std::get_if<GearJoint>(&gear.data);
            if (g && (g->side1.joint == index || g->side2.joint == index)) {
                wakeJointBodies(gear);
                removeJoint(gearIndex);
            }
        });
    }
    removeJoint(index);
}

void World::destroyJoint(JointId id) {
    const char* call = "World::destroyJoint";
    impl_->requireStructureChange(call);
    const std::int32_t index = impl_->jointIndex(call, id);
    const std::int32_t gears = impl_->joints[index].gearCount;
    if (gears > 0) {
        fail(call, "joint " + std::to_string(index) + " has " + std::to_string(gears) +
                       " gear joint(s) built on it; destroy them first");
    }
    impl_->removeJoint(index);
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
    return j.separation(impl_->bodies);
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
    impl_->requireChange("World::rearmJoint");
    Joint& j = impl_->joints[impl_->jointIndex("World::rearmJoint", id)];
    if (!j.letGo) return;
    j.letGo = false;  // letGoFor cleared its impulses
    impl_->islandRevision.bump();
    impl_->wakeJointBodies(j);
}

float World::jointLetGoSeparation(JointId id) const {
    const Joint& j = impl_->joints[impl_->jointIndex("World::jointLetGoSeparation", id)];
    return j.letGoSeparation(impl_->settings.jointLetGoSeparation);
}

void World::setJointLetGoSeparation(JointId id, std::optional<float> separation) {
    const char* call = "World::setJointLetGoSeparation";
    impl_->requireChange(call);
    Joint& j = impl_->joints[impl_->jointIndex(call, id)];
    if (separation) requireNonNegative(call, "separation", *separation);
    j.hasLetGoOverride = separation.has_value();
    j.letGoOverride = separation.value_or(0.0f);
}

std::vector<JointLetGoEvent> World::jointLetGoEvents() const {
    impl_->requireRead("World::jointLetGoEvents");
    return impl_->letGoEvents;
}

Vec2 World::jointLocalAnchorA(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointLocalAnchorA", id)].localAnchorA;
}
Vec2 World::jointLocalAnchorB(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointLocalAnchorB", id)].localAnchorB;
}
float World::jointReferenceAngle(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointReferenceAngle", id)].referenceAngle;
}
bool World::jointCollideConnected(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointCollideConnected", id)].collideConnected;
}
void World::setJointCollideConnected(JointId id, bool collide) {
    const char* call = "World::setJointCollideConnected";
    Impl& w = *impl_;
    w.requireChange(call);
    Joint& j = w.joints[w.jointIndex(call, id)];
    if (j.collideConnected == collide) return;
    j.collideConnected = collide;
    w.contactManager.refilterBodyPair(j.bodyA(), j.bodyB());
    w.wakeJointBodies(j);
}

float World::jointBreakForce(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointBreakForce", id)].breakForce;
}
void World::setJointBreakForce(JointId id, float force) {
    setBreakThreshold(*impl_, "World::setJointBreakForce", id, "force", force, &Joint::breakForce);
}
float World::jointBreakTorque(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointBreakTorque", id)].breakTorque;
}
void World::setJointBreakTorque(JointId id, float torque) {
    setBreakThreshold(*impl_, "World::setJointBreakTorque", id, "torque", torque,
                      &Joint::breakTorque);
}
Vec2 World::jointReactionForce(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointReactionForce", id)].reactionForce();
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
    return impl_->joints[impl_->jointIndex("World::jointReactionTorque", id)].reactionTorque();
}

PositionSolver World::jointPositionSolver(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointPositionSolver", id)].solver;
}

void World::setJointPositionSolver(JointId id, PositionSolver solver) {
    const char* call = "World::setJointPositionSolver";
    setStrategySetting(
        *impl_, call, id, [&] { checkSolver(call, "solver", solver); },
        [&](Joint& j) {
            j.solver = solver;
            impl_->islandRevision.bump();  // the island plans read it
        });
}

float World::jointBiasFactor(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointBiasFactor", id)].biasFactor();
}

void World::setJointBiasFactor(JointId id, std::optional<float> biasFactor) {
    const char* call = "World::setJointBiasFactor";
    setStrategySetting(
        *impl_, call, id,
        [&] {
            if (biasFactor) checkBiasFactor(call, "biasFactor", *biasFactor);
        },
        [&](Joint& j) {
            j.hasBiasOverride = biasFactor.has_value();
            j.biasOverride = biasFactor.value_or(0.0f);
        });
}

int World::jointExtraPositionIterations(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointExtraPositionIterations", id)]
        .extraPositionIterations;
}

void World::setJointExtraPositionIterations(JointId id, int count) {
    const char* call = "World::setJointExtraPositionIterations";
    setStrategySetting(
        *impl_, call, id, [&] { checkExtraPositionIterations(call, "count", count); },
        [&](Joint& j) {
            j.extraPositionIterations = count;
            impl_->islandRevision.bump();  // the island plans read it
        });
}

JointSoftness World::jointSoftness(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointSoftness", id)].softness;
}

void World::setJointSoftness(JointId id, const JointSoftness& softness) {
    const char* call = "World::setJointSoftness";
    setStrategySetting(
        *impl_, call, id, [&] { checkSoftness(call, "softness", softness); },
        [&](Joint& j) { j.softness = softness; });
}

std::uint64_t World::jointUserData(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointUserData", id)].userData;
}

void World::setJointUserData(JointId id, std::uint64_t userData) {
    impl_->requireChange("World::setJointUserData");
    impl_->joints[impl_->jointIndex("World::setJointUserData", id)].userData = userData;
}

std::vector<JointId> World::jointIds() const {
    impl_->requireRead("World::jointIds");
    std::vector<JointId> ids;
    impl_->joints.forEach(
        [&](std::int32_t index, const Joint&) { ids.push_back(impl_->jointId(index)); });
    return ids;
}

}  // namespace pivot
