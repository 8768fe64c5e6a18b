// The World facade, part six: mouse joints.
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

void World::Impl::removeMouseJoint(std::int32_t index) {
    Body& body = bodies[mouseJoints[index].body];
    // Singly linked: find the link that points at this joint.
    std::int32_t* link = &body.mouseList;
    while (*link != index) link = &mouseJoints[*link].next;
    *link = mouseJoints[index].next;
    mouseJoints.erase(index);
    islandRevision.bump();
    wakeUp(body, islandRevision);
}

MouseJointId World::createMouseJoint(const MouseJointDef& def) {
    const char* call = "World::createMouseJoint";
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    std::int32_t bodyIndex = checkHandle(call, "def.body", def.body, w.bodies, w.id);
    Body& body = w.bodies[bodyIndex];
    if (body.type != BodyType::Dynamic) fail(call, "def.body must be dynamic to be dragged");
    requireCoordinate(call, "def.target", def.target);
    requirePositive(call, "def.maxForce", def.maxForce);
    requirePositive(call, "def.hertz", def.hertz);
    requireNonNegative(call, "def.dampingRatio", def.dampingRatio);

    MouseJoint joint;
    joint.body = bodyIndex;
    joint.localAnchor = inverseTransformPoint(body.xf, def.target);
    joint.target = def.target;
    joint.maxForce = def.maxForce;
    joint.hertz = def.hertz;
    joint.dampingRatio = def.dampingRatio;
    joint.next = body.mouseList;
    std::int32_t index = w.mouseJoints.insert(joint);
    w.bodies[bodyIndex].mouseList = index;
    w.islandRevision.bump();
    wakeUp(w.bodies[bodyIndex], w.islandRevision);
    return w.mouseJointId(index);
}

void World::destroyMouseJoint(MouseJointId id) {
    impl_->requireStructureChange("World::destroyMouseJoint");
    impl_->removeMouseJoint(impl_->mouseJointIndex("World::destroyMouseJoint", id));
}

bool World::isValid(MouseJointId id) const {
    return id.world == impl_->id && impl_->mouseJoints.isAlive(id.index) &&
           impl_->mouseJoints.generation(id.index) == id.generation;
}

void World::setMouseTarget(MouseJointId id, Vec2 target) {
    const char* call = "World::setMouseTarget";
    impl_->requireChange(call);
    MouseJoint& joint = impl_->mouseJoints[impl_->mouseJointIndex(call, id)];
    requireCoordinate(call, "target", target);
    joint.target = target;
    wakeUp(impl_->bodies[joint.body], impl_->islandRevision);
}

Vec2 World::mouseTarget(MouseJointId id) const {
    return impl_->mouseJoints[impl_->mouseJointIndex("World::mouseTarget", id)].target;
}

BodyId World::mouseJointBody(MouseJointId id) const {
    return impl_->bodyId(
        impl_->mouseJoints[impl_->mouseJointIndex("World::mouseJointBody", id)].body);
}
float World::mouseJointMaxForce(MouseJointId id) const {
    return impl_->mouseJoints[impl_->mouseJointIndex("World::mouseJointMaxForce", id)].maxForce;
}
void World::setMouseJointMaxForce(MouseJointId id, float force) {
    const char* call = "World::setMouseJointMaxForce";
    impl_->requireChange(call);
    MouseJoint& joint = impl_->mouseJoints[impl_->mouseJointIndex(call, id)];
    requirePositive(call, "force", force);
    joint.maxForce = force;
    wakeUp(impl_->bodies[joint.body], impl_->islandRevision);
}
float World::mouseJointHertz(MouseJointId id) const {
    return impl_->mouseJoints[impl_->mouseJointIndex("World::mouseJointHertz", id)].hertz;
}
float World::mouseJointDampingRatio(MouseJointId id) const {
    return impl_->mouseJoints[impl_->mouseJointIndex("World::mouseJointDampingRatio", id)]
        .dampingRatio;
}
void World::setMouseJointSpring(MouseJointId id, float hertz, float dampingRatio) {
    const char* call = "World::setMouseJointSpring";
    impl_->requireChange(call);
    MouseJoint& joint = impl_->mouseJoints[impl_->mouseJointIndex(call, id)];
    requirePositive(call, "hertz", hertz);
    requireNonNegative(call, "dampingRatio", dampingRatio);
    joint.hertz = hertz;
    joint.dampingRatio = dampingRatio;
    wakeUp(impl_->bodies[joint.body], impl_->islandRevision);
}

}  // namespace pivot
