// The World facade, part two: bodies.
#include "world_checks.h"
#include "world_impl.h"

namespace pivot {

BodyId World::createBody(const BodyDef& def) {
    const char* call = "World::createBody";
    checkBodyType(call, "def.type", def.type);
    requireCoordinate(call, "def.position", def.position);
    requireMagnitude(call, "def.angle", def.angle);
    requireMagnitude(call, "def.linearVelocity", def.linearVelocity);
    requireMagnitude(call, "def.angularVelocity", def.angularVelocity);
    requireNonNegative(call, "def.linearDamping", def.linearDamping);
    requireNonNegative(call, "def.angularDamping", def.angularDamping);
    requireMagnitude(call, "def.gravityScale", def.gravityScale);
    if (def.type == BodyType::Static &&
        (def.linearVelocity != Vec2{} || def.angularVelocity != 0.0f)) {
        fail(call, "a static body cannot move: def.linearVelocity " +
                       formatVec2(def.linearVelocity) + " and def.angularVelocity " +
                       formatFloat(def.angularVelocity) + " must be zero");
    }

    Body body;
    body.type = def.type;
    body.xf = {def.position, Rot(def.angle)};
    body.center = def.position;
    body.angle = def.angle;
    body.linearVelocity = def.linearVelocity;
    body.angularVelocity = def.fixedRotation ? 0.0f : def.angularVelocity;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.allowSleep = def.allowSleep;
    body.awake = def.isAwake || def.type == BodyType::Static;
    body.userData = def.userData;
    std::int32_t index = impl_->bodies.insert(body);
    updateBodyMass(impl_->bodies[index], impl_->shapes);
    return impl_->bodyId(index);
}

void World::destroyBody(BodyId id) {
    Impl& w = *impl_;
    std::int32_t index = w.bodyIndex("World::destroyBody", id);
    Body& body = w.bodies[index];
    // Joints first (waking what they held), then contacts (waking what touched), then shapes.
    while (body.jointList != -1) {
        const RevoluteJoint& joint = w.joints[edgeOwner(body.jointList)];
        wakeUp(w.bodies[joint.bodyA()]);
        wakeUp(w.bodies[joint.bodyB()]);
        w.removeJoint(edgeOwner(body.jointList));
    }
    while (body.contactList != -1) {
        const Contact& contact = w.contacts[edgeOwner(body.contactList)];
        wakeUp(w.bodies[contact.bodyA()]);
        wakeUp(w.bodies[contact.bodyB()]);
        w.destroyContact(edgeOwner(body.contactList));
    }
    while (body.shapeList != -1) w.removeShape(body.shapeList);
    while (body.mouseList != -1) w.removeMouseJoint(body.mouseList);
    w.bodies.erase(index);
}

bool World::isValid(BodyId id) const {
    return id.world == impl_->id && impl_->bodies.isAlive(id.index) &&
           impl_->bodies.generation(id.index) == id.generation;
}

int World::bodyCount() const {
    return impl_->bodies.size();
}

BodyType World::bodyType(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyType", id)].type;
}

void World::setBodyType(BodyId id, BodyType type) {
    const char* call = "World::setBodyType";
    Impl& w = *impl_;
    std::int32_t index = w.bodyIndex(call, id);
    checkBodyType(call, "type", type);
    Body& body = w.bodies[index];
    if (type == BodyType::Dynamic) {
        // The rule createShape enforces, so a dynamic body's mass always comes from its shapes.
        for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
            if (w.shapes[s].density == 0.0f) {
                fail(call, "a dynamic body needs density > 0 in every shape, and shape " +
                               std::to_string(s) +
                               " has density 0 (give it a density with setShapeDensity first)");
            }
        }
    }
    if (body.type == type) return;

    body.type = type;
    body.force = Vec2{};
    body.torque = 0.0f;
    updateBodyMass(body, w.shapes);
    if (type == BodyType::Static) {
        // After the mass update, which moves the velocity with the centre of mass.
        body.linearVelocity = Vec2{};
        body.angularVelocity = 0.0f;
    }
    body.sleepTime = 0.0f;
    body.awake = true;
    // Contacts that became static-static or kinematic-static go at the next step's contact
    // update; pairs that were not allowed to collide before are found then.
    w.refilterBody(index);
}
Vec2 World::bodyPosition(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyPosition", id)].xf.p;
}
float World::bodyAngle(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyAngle", id)].angle;
}
Transform World::bodyTransform(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyTransform", id)].xf;
}
Vec2 World::bodyWorldCenter(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyWorldCenter", id)].center;
}
Vec2 World::bodyLocalCenter(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyLocalCenter", id)].localCenter;
}
Vec2 World::bodyLinearVelocity(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyLinearVelocity", id)].linearVelocity;
}
float World::bodyAngularVelocity(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyAngularVelocity", id)].angularVelocity;
}
float World::bodyMass(BodyId id) const {
    const Body& b = impl_->bodies[impl_->bodyIndex("World::bodyMass", id)];
    return b.type == BodyType::Dynamic ? b.mass : 0.0f;
}
float World::bodyRotationalInertia(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyRotationalInertia", id)].inertia;
}
Vec2 World::bodyWorldPoint(BodyId id, Vec2 localPoint) const {
    const char* call = "World::bodyWorldPoint";
    const Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireCoordinate(call, "localPoint", localPoint);
    return transformPoint(b.xf, localPoint);
}
Vec2 World::bodyLocalPoint(BodyId id, Vec2 worldPoint) const {
    const char* call = "World::bodyLocalPoint";
    const Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireCoordinate(call, "worldPoint", worldPoint);
    return inverseTransformPoint(b.xf, worldPoint);
}

bool World::isBodyAwake(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::isBodyAwake", id)].awake;
}

void World::setBodyAwake(BodyId id, bool awake) {
    Body& b = impl_->bodies[impl_->bodyIndex("World::setBodyAwake", id)];
    if (b.type == BodyType::Static) return;
    if (awake) {
        wakeUp(b);
    } else {
        putToSleep(b);
    }
}

void World::setBodySleepAllowed(BodyId id, bool allowed) {
    Body& b = impl_->bodies[impl_->bodyIndex("World::setBodySleepAllowed", id)];
    b.allowSleep = allowed;
    if (!allowed) wakeUp(b);
}

void World::setBodyTransform(BodyId id, Vec2 position, float angle) {
    const char* call = "World::setBodyTransform";
    Impl& w = *impl_;
    std::int32_t index = w.bodyIndex(call, id);
    requireCoordinate(call, "position", position);
    requireMagnitude(call, "angle", angle);
    Body& b = w.bodies[index];
    b.xf = {position, Rot(angle)};
    b.angle = angle;
    b.center = transformPoint(b.xf, b.localCenter);
    // A teleport is not a motion: the broad-phase boxes jump without a swept extent.
    w.synchronizeShapes(index, false);
    w.newShapes = true;
    wakeUp(b);
}

namespace {
Body& movableBody(World::Impl& w, const char* call, BodyId id) {
    Body& b = w.bodies[w.bodyIndex(call, id)];
    if (b.type == BodyType::Static) fail(call, "body is static and cannot be given a velocity");
    return b;
}
}  // namespace

void World::setBodyLinearVelocity(BodyId id, Vec2 velocity) {
    const char* call = "World::setBodyLinearVelocity";
    Body& b = movableBody(*impl_, call, id);
    requireMagnitude(call, "velocity", velocity);
    b.linearVelocity = velocity;
    wakeUp(b);
}

void World::setBodyAngularVelocity(BodyId id, float omega) {
    const char* call = "World::setBodyAngularVelocity";
    Body& b = movableBody(*impl_, call, id);
    requireMagnitude(call, "omega", omega);
    b.angularVelocity = b.fixedRotation ? 0.0f : omega;
    wakeUp(b);
}

// Forces and impulses move dynamic bodies only; static and kinematic bodies ignore them by
// definition (infinite mass), as BodyType documents.
void World::applyForce(BodyId id, Vec2 force, Vec2 worldPoint) {
    const char* call = "World::applyForce";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireMagnitude(call, "force", force);
    requireCoordinate(call, "worldPoint", worldPoint);
    if (b.type != BodyType::Dynamic) return;
    b.force += force;
    b.torque += cross(worldPoint - b.center, force);
    wakeUp(b);
}

void World::applyForceToCenter(BodyId id, Vec2 force) {
    const char* call = "World::applyForceToCenter";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireMagnitude(call, "force", force);
    if (b.type != BodyType::Dynamic) return;
    b.force += force;
    wakeUp(b);
}

void World::applyTorque(BodyId id, float torque) {
    const char* call = "World::applyTorque";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireMagnitude(call, "torque", torque);
    if (b.type != BodyType::Dynamic) return;
    b.torque += torque;
    wakeUp(b);
}

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint) {
    const char* call = "World::applyLinearImpulse";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireMagnitude(call, "impulse", impulse);
    requireCoordinate(call, "worldPoint", worldPoint);
    if (b.type != BodyType::Dynamic) return;
    b.linearVelocity += b.invMass * impulse;
    b.angularVelocity += b.invInertia * cross(worldPoint - b.center, impulse);
    wakeUp(b);
}

void World::applyAngularImpulse(BodyId id, float impulse) {
    const char* call = "World::applyAngularImpulse";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireMagnitude(call, "impulse", impulse);
    if (b.type != BodyType::Dynamic) return;
    b.angularVelocity += b.invInertia * impulse;
    wakeUp(b);
}

std::vector<BodyId> World::bodyIds() const {
    std::vector<BodyId> ids;
    impl_->bodies.forEach(
        [&](std::int32_t index, const Body&) { ids.push_back(impl_->bodyId(index)); });
    return ids;
}

std::vector<ShapeId> World::bodyShapes(BodyId id) const {
    const Body& body = impl_->bodies[impl_->bodyIndex("World::bodyShapes", id)];
    std::vector<ShapeId> ids;
    for (std::int32_t s = body.shapeList; s != -1; s = impl_->shapes[s].next) {
        ids.push_back(impl_->shapeId(s));
    }
    return ids;
}

}  // namespace pivot
