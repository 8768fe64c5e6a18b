// The World facade, part four: joints.
#include "world_checks.h"
#include "world_impl.h"

namespace pivot {

void World::Impl::removeJoint(std::int32_t index) {
    const RevoluteJoint& joint = joints[index];
    std::int32_t a = joint.bodyA(), b = joint.bodyB();
    bool preventedCollision = !joint.collideConnected;
    unlinkEdges(joints, bodies, &Body::jointList, index);
    joints.erase(index);
    wakeUp(bodies[a]);
    wakeUp(bodies[b]);
    if (preventedCollision) refilterBodyPair(a, b);
}

JointId World::createJoint(const RevoluteJointDef& def) {
    const char* call = "World::createJoint";
    Impl& w = *impl_;
    std::int32_t a = checkHandle(call, "def.bodyA", def.bodyA, w.bodies, w.id);
    std::int32_t b = checkHandle(call, "def.bodyB", def.bodyB, w.bodies, w.id);
    if (a == b) fail(call, "def.bodyA and def.bodyB are the same body; a joint needs two bodies");
    requireFinite(call, "def.localAnchorA", def.localAnchorA);
    requireFinite(call, "def.localAnchorB", def.localAnchorB);
    requireFinite(call, "def.referenceAngle", def.referenceAngle);
    if (def.worldAnchor) requireFinite(call, "def.worldAnchor", *def.worldAnchor);
    PositionSolver solver = def.positionSolver.value_or(w.defaultPositionSolver);
    checkSolver(call, "def.positionSolver", solver);
    if (def.biasFactor) checkBiasFactor(call, "def.biasFactor", *def.biasFactor);

    RevoluteJoint joint;
    joint.edges[0].body = a;
    joint.edges[1].body = b;
    const Body& bodyA = w.bodies[a];
    const Body& bodyB = w.bodies[b];
    if (def.worldAnchor) {
        joint.localAnchorA = inverseTransformPoint(bodyA.xf, *def.worldAnchor);
        joint.localAnchorB = inverseTransformPoint(bodyB.xf, *def.worldAnchor);
        joint.referenceAngle = bodyB.angle - bodyA.angle;
    } else {
        joint.localAnchorA = def.localAnchorA;
        joint.localAnchorB = def.localAnchorB;
        joint.referenceAngle = def.referenceAngle;
    }
    joint.solver = solver;
    joint.hasBiasOverride = def.biasFactor.has_value();
    joint.biasOverride = def.biasFactor.value_or(0.0f);
    joint.collideConnected = def.collideConnected;
    joint.userData = def.userData;
    std::int32_t index = w.joints.insert(joint);
    linkEdges(w.joints, w.bodies, &Body::jointList, index);
    // A joint that forbids its bodies to collide ends any contact between them.
    if (!def.collideConnected) w.refilterBodyPair(a, b);
    wakeUp(w.bodies[a]);
    wakeUp(w.bodies[b]);
    return w.jointId(index);
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
    const RevoluteJoint& j = impl_->joints[impl_->jointIndex("World::jointAnchorA", id)];
    return transformPoint(impl_->bodies[j.bodyA()].xf, j.localAnchorA);
}
Vec2 World::jointAnchorB(JointId id) const {
    const RevoluteJoint& j = impl_->joints[impl_->jointIndex("World::jointAnchorB", id)];
    return transformPoint(impl_->bodies[j.bodyB()].xf, j.localAnchorB);
}
float World::jointSeparation(JointId id) const {
    const RevoluteJoint& j = impl_->joints[impl_->jointIndex("World::jointSeparation", id)];
    Vec2 pA = transformPoint(impl_->bodies[j.bodyA()].xf, j.localAnchorA);
    Vec2 pB = transformPoint(impl_->bodies[j.bodyB()].xf, j.localAnchorB);
    return distance(pA, pB);
}
Vec2 World::jointReactionForce(JointId id) const {
    const RevoluteJoint& j = impl_->joints[impl_->jointIndex("World::jointReactionForce", id)];
    return j.impulseInvDt * j.impulse;
}

PositionSolver World::jointPositionSolver(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointPositionSolver", id)].solver;
}

void World::setJointPositionSolver(JointId id, PositionSolver solver) {
    const char* call = "World::setJointPositionSolver";
    RevoluteJoint& j = impl_->joints[impl_->jointIndex(call, id)];
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
    RevoluteJoint& j = impl_->joints[impl_->jointIndex(call, id)];
    if (biasFactor) checkBiasFactor(call, "biasFactor", *biasFactor);
    j.hasBiasOverride = biasFactor.has_value();
    j.biasOverride = biasFactor.value_or(0.0f);
    wakeUp(impl_->bodies[j.bodyA()]);
    wakeUp(impl_->bodies[j.bodyB()]);
}

}  // namespace pivot
