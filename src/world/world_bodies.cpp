// The World facade, part two: bodies.
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

BodyId World::createBody(const BodyDef& def) {
    const char* call = "World::createBody";
    impl_->requireStructureChange(call);
    checkBodyType(call, "def.type", def.type);
    requireCoordinate(call, "def.position", def.position);
    requireMagnitude(call, "def.angle", def.angle);
    requireWithin(call, "def.linearVelocity", def.linearVelocity, kMaxSpeed, "kMaxSpeed");
    requireWithin(call, "def.angularVelocity", def.angularVelocity, kMaxAngularSpeed,
                  "kMaxAngularSpeed");
    requireNonNegative(call, "def.linearDamping", def.linearDamping);
    requireNonNegative(call, "def.angularDamping", def.angularDamping);
    requireWithin(call, "def.gravityScale", def.gravityScale, kMaxGravityScale, "kMaxGravityScale");
    if (def.type == BodyType::Static &&
        (def.linearVelocity != Vec2{} || def.angularVelocity != 0.0f)) {
        fail(call, "a static body cannot move: def.linearVelocity " +
                       formatVec2(def.linearVelocity) + " and def.angularVelocity " +
                       formatFloat(def.angularVelocity) + " must be zero");
    }
    if (def.fixedRotation && def.angularVelocity != 0.0f) {
        fail(call,
             "a body with def.fixedRotation never turns: def.angularVelocity must be 0 (got " +
                 formatFloat(def.angularVelocity) + ")");
    }

    Body body;
    body.type = def.type;
    body.xf = {def.position, Rot(def.angle)};
    body.center = def.position;
    body.angle = def.angle;
    body.linearVelocity = def.linearVelocity;
    body.angularVelocity = def.angularVelocity;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.allowSleep = def.allowSleep;
    body.awake = def.isAwake || def.type == BodyType::Static;
    body.userData = def.userData;
    body.bullet = def.bullet;
    body.continuous = def.continuous;
    std::int32_t index = impl_->bodies.insert(body);
    updateBodyMass(impl_->bodies[index], impl_->shapes);
    impl_->islandRevision.bump();
    return impl_->bodyId(index);
}

void World::destroyBody(BodyId id) {
    Impl& w = *impl_;
    w.requireStructureChange("World::destroyBody");
    std::int32_t index = w.bodyIndex("World::destroyBody", id);
    Body& body = w.bodies[index];
    // Joints first (waking what they held), then contacts (waking what touched), then shapes.
    while (body.jointList != -1) {
        const Joint& joint = w.joints[edgeOwner(body.jointList)];
        w.wakeJointBodies(joint);
        w.removeJointAndItsGears(edgeOwner(body.jointList));
    }
    while (body.contactList != -1) {
        const Contact& contact = w.contacts[edgeOwner(body.contactList)];
        wakeUp(w.bodies[contact.bodyA()], w.islandRevision);
        wakeUp(w.bodies[contact.bodyB()], w.islandRevision);
        w.contactManager.destroyContact(edgeOwner(body.contactList));
    }
    while (body.shapeList != -1) w.removeShape(body.shapeList);
    while (body.mouseList != -1) w.removeMouseJoint(body.mouseList);
    w.bodies.erase(index);
    w.islandRevision.bump();
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
    impl_->requireStructureChange(call);
    Impl& w = *impl_;
    std::int32_t index = w.bodyIndex(call, id);
    checkBodyType(call, "type", type);
    Body& body = w.bodies[index];
    if (type == BodyType::Dynamic) {
        // The rule createShape enforces, so a dynamic body's mass always comes from its shapes.
        for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
            if (isSegmentLike(w.shapes[s].type)) {
                fail(call, "a dynamic body cannot carry a segment, which has no mass, and shape " +
                               std::to_string(s) + " is one (destroy it first)");
            }
            if (w.shapes[s].density == 0.0f) {
                fail(call, "a dynamic body needs density > 0 in every shape, and shape " +
                               std::to_string(s) +
                               " has density 0 (give it a density with setShapeDensity first)");
            }
        }
    }
    if (body.type == type) return;
    requireMotionAfterMassChange(call, bodyAfterMassChange(body, w.shapes, MassChange{type}), body);

    if (movesAndStopsTunnelling(body)) w.contactManager.countMovingStoppers(-body.shapeCount);
    body.type = type;
    if (movesAndStopsTunnelling(body)) w.contactManager.countMovingStoppers(+body.shapeCount);
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
    w.islandRevision.bump();  // a static body joins islands, a dynamic one seeds them
    // Under BroadPhaseBoxes::Compact static bodies' proxies live in a tree of their own.
    for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
        Shape& shape = w.shapes[s];
        shape.proxyId = w.contactManager.broadPhase().setOnStaticBody(shape.proxyId, shape.box,
                                                                      type == BodyType::Static);
    }
    // Contacts that became static-static or kinematic-static go at the next step's contact
    // update; pairs that were not allowed to collide before are found then.
    w.contactManager.refilterBody(index);
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
bool World::bodyFixedRotation(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyFixedRotation", id)].fixedRotation;
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
    impl_->requireChange("World::setBodyAwake");
    Body& b = impl_->bodies[impl_->bodyIndex("World::setBodyAwake", id)];
    if (b.type == BodyType::Static) return;
    if (awake) {
        wakeUp(b, impl_->islandRevision);
    } else {
        if (b.awake) impl_->islandRevision.bump();
        putToSleep(b);
    }
}

bool World::isBodySleepAllowed(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::isBodySleepAllowed", id)].allowSleep;
}

float World::bodyLinearDamping(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyLinearDamping", id)].linearDamping;
}

void World::setBodyLinearDamping(BodyId id, float damping) {
    const char* call = "World::setBodyLinearDamping";
    impl_->requireChange(call);
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireNonNegative(call, "damping", damping);
    b.linearDamping = damping;
    wakeUp(b, impl_->islandRevision);
}

float World::bodyAngularDamping(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyAngularDamping", id)].angularDamping;
}

void World::setBodyAngularDamping(BodyId id, float damping) {
    const char* call = "World::setBodyAngularDamping";
    impl_->requireChange(call);
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireNonNegative(call, "damping", damping);
    b.angularDamping = damping;
    wakeUp(b, impl_->islandRevision);
}

float World::bodyGravityScale(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyGravityScale", id)].gravityScale;
}

void World::setBodyGravityScale(BodyId id, float scale) {
    const char* call = "World::setBodyGravityScale";
    impl_->requireChange(call);
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireWithin(call, "scale", scale, kMaxGravityScale, "kMaxGravityScale");
    b.gravityScale = scale;
    wakeUp(b, impl_->islandRevision);
}

void World::setBodyFixedRotation(BodyId id, bool fixedRotation) {
    impl_->requireChange("World::setBodyFixedRotation");
    Impl& w = *impl_;
    Body& b = w.bodies[w.bodyIndex("World::setBodyFixedRotation", id)];
    if (b.fixedRotation == fixedRotation) return;
    b.fixedRotation = fixedRotation;
    if (fixedRotation) {
        // A body that never turns keeps no spin and no torque to turn it later.
        b.angularVelocity = 0.0f;
        b.torque = 0.0f;
    }
    // The inertia comes and goes with the flag; the centre of mass stays where it is.
    updateBodyMass(b, w.shapes);
    wakeUp(b, impl_->islandRevision);
}

void World::setBodySleepAllowed(BodyId id, bool allowed) {
    impl_->requireChange("World::setBodySleepAllowed");
    Body& b = impl_->bodies[impl_->bodyIndex("World::setBodySleepAllowed", id)];
    b.allowSleep = allowed;
    if (!allowed) wakeUp(b, impl_->islandRevision);
}

bool World::isBodyContinuous(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::isBodyContinuous", id)].continuous;
}

void World::setBodyContinuous(BodyId id, bool continuous) {
    impl_->requireChange("World::setBodyContinuous");
    impl_->bodies[impl_->bodyIndex("World::setBodyContinuous", id)].continuous = continuous;
}

bool World::isBodyBullet(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::isBodyBullet", id)].bullet;
}

void World::setBodyBullet(BodyId id, bool bullet) {
    impl_->requireChange("World::setBodyBullet");
    Body& body = impl_->bodies[impl_->bodyIndex("World::setBodyBullet", id)];
    ContactManager& contactManager = impl_->contactManager;
    if (movesAndStopsTunnelling(body)) contactManager.countMovingStoppers(-body.shapeCount);
    body.bullet = bullet;
    if (movesAndStopsTunnelling(body)) contactManager.countMovingStoppers(+body.shapeCount);
}

std::uint64_t World::bodyUserData(BodyId id) const {
    return impl_->bodies[impl_->bodyIndex("World::bodyUserData", id)].userData;
}

void World::setBodyUserData(BodyId id, std::uint64_t userData) {
    const char* call = "World::setBodyUserData";
    impl_->requireChange(call);
    impl_->bodies[impl_->bodyIndex(call, id)].userData = userData;
}

void World::setBodyTransform(BodyId id, Vec2 position, float angle) {
    const char* call = "World::setBodyTransform";
    Impl& w = *impl_;
    w.requireStructureChange(call);
    std::int32_t index = w.bodyIndex(call, id);
    requireCoordinate(call, "position", position);
    requireMagnitude(call, "angle", angle);
    Body& b = w.bodies[index];
    b.xf = {position, Rot(angle)};
    b.angle = angle;
    b.center = transformPoint(b.xf, b.localCenter);
    restartSweep(b);
    // A teleport is not a motion: the broad-phase boxes jump without a swept extent.
    w.contactManager.synchronizeShapes(index, false);
    w.contactManager.markNewShapes();
    wakeUp(b, impl_->islandRevision);
}

// What calls may do to a body's motion. One rule for the velocity setters and for forces,
// torques and impulses: a call that could have no effect is refused rather than silently
// dropped. A static body never moves, so it takes none of them; forces, torques and impulses
// move dynamic bodies only (a kinematic body has infinite mass: set its velocity instead); a
// body with fixed rotation never turns, so it takes no torque, angular impulse or non-zero
// angular velocity. And what calls accumulate between steps stays within the input limits: the
// velocities impulses add up to, which can then be read back and set again; the pending force
// and torque; and the accelerations they give the body (force / mass, torque / inertia, at most
// kMaxMagnitude m/s^2 and rad/s^2, like gravity times gravity scale), whose products in the
// step must stay inside float range: 1e10 N on a 1e-11 kg sliver was 1e21 m/s^2.
namespace {

const char* typeName(BodyType type) {
    switch (type) {
        case BodyType::Static: return "static";
        case BodyType::Kinematic: return "kinematic";
        case BodyType::Dynamic: return "dynamic";
    }
    return "invalid";
}

Body& bodyTakingVelocity(World::Impl& w, const char* call, BodyId id) {
    Body& b = w.bodies[w.bodyIndex(call, id)];
    if (b.type == BodyType::Static) fail(call, "body is static and cannot be given a velocity");
    return b;
}

Body& bodyTakingForce(World::Impl& w, const char* call, BodyId id) {
    Body& b = w.bodies[w.bodyIndex(call, id)];
    if (b.type != BodyType::Dynamic) {
        fail(call, std::string("body is ") + typeName(b.type) +
                       ": forces, torques and impulses move dynamic bodies only" +
                       (b.type == BodyType::Kinematic ? " (set a kinematic body's velocity)" : ""));
    }
    return b;
}

void requireTurning(const char* call, const Body& b) {
    if (b.fixedRotation) {
        fail(call, "body has fixed rotation: a torque or angular impulse cannot turn it");
    }
}

// What a call would leave accumulated on the body, checked before it is stored.
void requireAccumulated(const char* call, const char* what, float value,
                        float limit = kMaxMagnitude, const char* limitName = "kMaxMagnitude") {
    if (!(std::fabs(value) <= limit)) {
        fail(call, std::string("this call would take the body's ") + what + " to " +
                       formatFloat(value) + ", beyond +-" + limitName + " (" + formatFloat(limit) +
                       ")");
    }
}
void requireAccumulated(const char* call, const char* what, Vec2 value, float limit = kMaxMagnitude,
                        const char* limitName = "kMaxMagnitude") {
    if (!(std::fabs(value.x) <= limit && std::fabs(value.y) <= limit)) {
        fail(call, std::string("this call would take the body's ") + what + " to " +
                       formatVec2(value) + ", beyond +-" + limitName + " (" + formatFloat(limit) +
                       ")");
    }
}

}  // namespace

void World::setBodyLinearVelocity(BodyId id, Vec2 velocity) {
    const char* call = "World::setBodyLinearVelocity";
    impl_->requireChange(call);
    Body& b = bodyTakingVelocity(*impl_, call, id);
    requireWithin(call, "velocity", velocity, kMaxSpeed, "kMaxSpeed");
    b.linearVelocity = velocity;
    wakeUp(b, impl_->islandRevision);
}

void World::setBodyAngularVelocity(BodyId id, float omega) {
    const char* call = "World::setBodyAngularVelocity";
    impl_->requireChange(call);
    Body& b = bodyTakingVelocity(*impl_, call, id);
    requireWithin(call, "omega", omega, kMaxAngularSpeed, "kMaxAngularSpeed");
    if (b.fixedRotation && omega != 0.0f) {
        fail(call, "body has fixed rotation: its angular velocity stays 0 (got omega " +
                       formatFloat(omega) + ")");
    }
    b.angularVelocity = omega;
    wakeUp(b, impl_->islandRevision);
}

void World::applyForce(BodyId id, Vec2 force, Vec2 worldPoint) {
    const char* call = "World::applyForce";
    impl_->requireChange(call);
    Body& b = bodyTakingForce(*impl_, call, id);
    requireMagnitude(call, "force", force);
    requireCoordinate(call, "worldPoint", worldPoint);
    const Vec2 total = b.force + force;
    // A body with fixed rotation keeps no torque: it could never turn it.
    const float torque =
        b.fixedRotation ? b.torque : b.torque + cross(worldPoint - b.center, force);
    requireAccumulated(call, "pending force", total);
    requireAccumulated(call, "pending torque", torque);
    requireAccumulated(call, "linear acceleration (pending force / mass)", b.invMass * total);
    requireAccumulated(call, "angular acceleration (pending torque / inertia)",
                       b.invInertia * torque);
    b.force = total;
    b.torque = torque;
    wakeUp(b, impl_->islandRevision);
}

void World::applyForceToCenter(BodyId id, Vec2 force) {
    const char* call = "World::applyForceToCenter";
    impl_->requireChange(call);
    Body& b = bodyTakingForce(*impl_, call, id);
    requireMagnitude(call, "force", force);
    const Vec2 total = b.force + force;
    requireAccumulated(call, "pending force", total);
    requireAccumulated(call, "linear acceleration (pending force / mass)", b.invMass * total);
    b.force = total;
    wakeUp(b, impl_->islandRevision);
}

void World::applyTorque(BodyId id, float torque) {
    const char* call = "World::applyTorque";
    impl_->requireChange(call);
    Body& b = bodyTakingForce(*impl_, call, id);
    requireMagnitude(call, "torque", torque);
    requireTurning(call, b);
    const float total = b.torque + torque;
    requireAccumulated(call, "pending torque", total);
    requireAccumulated(call, "angular acceleration (pending torque / inertia)",
                       b.invInertia * total);
    b.torque = total;
    wakeUp(b, impl_->islandRevision);
}

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint) {
    const char* call = "World::applyLinearImpulse";
    impl_->requireChange(call);
    Body& b = bodyTakingForce(*impl_, call, id);
    requireMagnitude(call, "impulse", impulse);
    requireCoordinate(call, "worldPoint", worldPoint);
    const Vec2 v = b.linearVelocity + b.invMass * impulse;
    const float w = b.angularVelocity + b.invInertia * cross(worldPoint - b.center, impulse);
    requireAccumulated(call, "linear velocity", v, kMaxSpeed, "kMaxSpeed");
    requireAccumulated(call, "angular velocity", w, kMaxAngularSpeed, "kMaxAngularSpeed");
    b.linearVelocity = v;
    b.angularVelocity = w;
    wakeUp(b, impl_->islandRevision);
}

void World::applyAngularImpulse(BodyId id, float impulse) {
    const char* call = "World::applyAngularImpulse";
    impl_->requireChange(call);
    Body& b = bodyTakingForce(*impl_, call, id);
    requireMagnitude(call, "impulse", impulse);
    requireTurning(call, b);
    const float w = b.angularVelocity + b.invInertia * impulse;
    requireAccumulated(call, "angular velocity", w, kMaxAngularSpeed, "kMaxAngularSpeed");
    b.angularVelocity = w;
    wakeUp(b, impl_->islandRevision);
}

std::vector<BodyId> World::bodyIds() const {
    impl_->requireRead("World::bodyIds");
    std::vector<BodyId> ids;
    impl_->bodies.forEach(
        [&](std::int32_t index, const Body&) { ids.push_back(impl_->bodyId(index)); });
    return ids;
}

std::vector<JointId> World::bodyJoints(BodyId id) const {
    const Body& body = impl_->bodies[impl_->bodyIndex("World::bodyJoints", id)];
    std::vector<JointId> ids;
    for (std::int32_t key = body.jointList; key != -1;) {
        ids.push_back(impl_->jointId(edgeOwner(key)));
        key = impl_->joints[edgeOwner(key)].edges[edgeSide(key)].nextKey;
    }
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
