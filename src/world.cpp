// The World facade: every public call checks its input completely, then changes the world.
// A check that fails throws pivot::Error before anything is touched.
#include <atomic>
#include <string>

#include "state_hash.h"
#include "validation.h"
#include "world_impl.h"

namespace pivot {

namespace {

std::uint32_t nextWorldId() {
    static std::atomic<std::uint32_t> counter{0};
    std::uint32_t id = ++counter;
    if (id == 0) id = ++counter;  // 0 marks a null handle
    return id;
}

template <typename Tag, typename T>
std::int32_t checkHandle(const char* call, const char* what, detail::Handle<Tag> id,
                         const SlotPool<T>& pool, std::uint32_t worldId) {
    const std::string name(what);
    if (id.isNull()) fail(call, name + " id is null (default-constructed)");
    if (id.world != worldId) {
        fail(call, name + " id was issued by another world (world " + std::to_string(id.world) +
                       ", this is world " + std::to_string(worldId) + ")");
    }
    if (id.index < 0 || id.index >= pool.capacity()) {
        fail(call, name + " id has index " + std::to_string(id.index) +
                       ", which this world never issued");
    }
    if (!pool.isAlive(id.index) || pool.generation(id.index) != id.generation) {
        fail(call, name + " id is stale: " + name + " " + std::to_string(id.index) +
                       " (generation " + std::to_string(id.generation) + ") was destroyed");
    }
    return id.index;
}

void checkSolver(const char* call, const char* field, PositionSolver solver) {
    int value = static_cast<int>(solver);
    if (value < 0 || value >= kPositionSolverCount) {
        fail(call,
             std::string(field) + " is not a PositionSolver (got " + std::to_string(value) + ")");
    }
}

void checkBiasFactor(const char* call, const char* field, float bias) {
    requireInRange(call, field, bias, 0.0f, 1.0f);
}

void checkShapeDef(const char* call, const ShapeDef& def, const Body& body) {
    requireNonNegative(call, "def.density", def.density);
    if (body.type == BodyType::Dynamic && def.density <= 0.0f) {
        fail(call,
             "def.density must be > 0 on a dynamic body (got " + formatFloat(def.density) + ")");
    }
    requireNonNegative(call, "def.friction", def.friction);
    requireInRange(call, "def.restitution", def.restitution, 0.0f, 1.0f);
}

}  // namespace

// --- World::Impl ------------------------------------------------------------------------------

World::Impl::Impl(const WorldDef& def)
    : id(nextWorldId()),
      gravity(def.gravity),
      defaultPositionSolver(def.defaultPositionSolver),
      warmStarting(def.warmStarting) {}

std::int32_t World::Impl::bodyIndex(const char* call, BodyId id) const {
    return checkHandle(call, "body", id, bodies, this->id);
}
std::int32_t World::Impl::shapeIndex(const char* call, ShapeId id) const {
    return checkHandle(call, "shape", id, shapes, this->id);
}
std::int32_t World::Impl::jointIndex(const char* call, JointId id) const {
    return checkHandle(call, "joint", id, joints, this->id);
}

void World::Impl::linkJoint(std::int32_t index) {
    RevoluteJoint& joint = joints[index];
    for (int side = 0; side < 2; ++side) {
        std::int32_t key = jointEdgeKey(index, side);
        Body& body = bodies[joint.edges[side].body];
        joint.edges[side].prevKey = -1;
        joint.edges[side].nextKey = body.jointList;
        if (body.jointList != -1) {
            joints[jointOfKey(body.jointList)].edges[sideOfKey(body.jointList)].prevKey = key;
        }
        body.jointList = key;
    }
}

void World::Impl::unlinkJoint(std::int32_t index) {
    RevoluteJoint& joint = joints[index];
    for (int side = 0; side < 2; ++side) {
        const JointEdge& edge = joint.edges[side];
        if (edge.prevKey != -1) {
            joints[jointOfKey(edge.prevKey)].edges[sideOfKey(edge.prevKey)].nextKey = edge.nextKey;
        } else {
            bodies[edge.body].jointList = edge.nextKey;
        }
        if (edge.nextKey != -1) {
            joints[jointOfKey(edge.nextKey)].edges[sideOfKey(edge.nextKey)].prevKey = edge.prevKey;
        }
    }
}

void World::Impl::removeJoint(std::int32_t index) {
    unlinkJoint(index);
    joints.erase(index);
}

void World::Impl::removeShape(std::int32_t index) {
    const Shape& shape = shapes[index];
    Body& body = bodies[shape.body];
    if (shape.prev != -1) {
        shapes[shape.prev].next = shape.next;
    } else {
        body.shapeList = shape.next;
    }
    if (shape.next != -1) shapes[shape.next].prev = shape.prev;
    --body.shapeCount;
    shapes.erase(index);
}

// --- World: lifetime and simulation -------------------------------------------------------------

World::World(const WorldDef& def) {
    const char* call = "World::World";
    requireFinite(call, "def.gravity", def.gravity);
    checkSolver(call, "def.defaultPositionSolver", def.defaultPositionSolver);
    impl_ = std::make_unique<Impl>(def);
}

World::~World() = default;

void World::step(float dt, int velocityIterations, int positionIterations) {
    const char* call = "World::step";
    requireFinite(call, "dt", dt);
    if (dt <= 0.0f) fail(call, "dt must be > 0 (got " + formatFloat(dt) + ")");
    auto checkIterations = [&](const char* field, int value) {
        if (value < 0 || value > kMaxIterations) {
            fail(call, std::string(field) + " must be in [0, " + std::to_string(kMaxIterations) +
                           "] (got " + std::to_string(value) + ")");
        }
    };
    checkIterations("velocityIterations", velocityIterations);
    checkIterations("positionIterations", positionIterations);
    impl_->step(dt, velocityIterations, positionIterations);
}

const StepStats& World::lastStepStats() const {
    return impl_->stats;
}

Vec2 World::gravity() const {
    return impl_->gravity;
}

void World::setGravity(Vec2 gravity) {
    requireFinite("World::setGravity", "gravity", gravity);
    impl_->gravity = gravity;
}

PositionSolver World::defaultPositionSolver() const {
    return impl_->defaultPositionSolver;
}

// --- bodies ------------------------------------------------------------------------------------

BodyId World::createBody(const BodyDef& def) {
    const char* call = "World::createBody";
    int type = static_cast<int>(def.type);
    if (type < 0 || type > static_cast<int>(BodyType::Dynamic)) {
        fail(call, "def.type is not a BodyType (got " + std::to_string(type) + ")");
    }
    requireFinite(call, "def.position", def.position);
    requireFinite(call, "def.angle", def.angle);
    requireFinite(call, "def.linearVelocity", def.linearVelocity);
    requireFinite(call, "def.angularVelocity", def.angularVelocity);
    requireNonNegative(call, "def.linearDamping", def.linearDamping);
    requireNonNegative(call, "def.angularDamping", def.angularDamping);
    requireFinite(call, "def.gravityScale", def.gravityScale);
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
    body.userData = def.userData;
    std::int32_t index = impl_->bodies.insert(body);
    updateBodyMass(impl_->bodies[index], impl_->shapes);
    return impl_->bodyId(index);
}

void World::destroyBody(BodyId id) {
    Impl& w = *impl_;
    std::int32_t index = w.bodyIndex("World::destroyBody", id);
    Body& body = w.bodies[index];
    while (body.jointList != -1) w.removeJoint(jointOfKey(body.jointList));
    while (body.shapeList != -1) w.removeShape(body.shapeList);
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
    requireFinite(call, "localPoint", localPoint);
    return transformPoint(b.xf, localPoint);
}
Vec2 World::bodyLocalPoint(BodyId id, Vec2 worldPoint) const {
    const char* call = "World::bodyLocalPoint";
    const Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "worldPoint", worldPoint);
    return inverseTransformPoint(b.xf, worldPoint);
}

void World::setBodyTransform(BodyId id, Vec2 position, float angle) {
    const char* call = "World::setBodyTransform";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "position", position);
    requireFinite(call, "angle", angle);
    b.xf = {position, Rot(angle)};
    b.angle = angle;
    b.center = transformPoint(b.xf, b.localCenter);
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
    requireFinite(call, "velocity", velocity);
    b.linearVelocity = velocity;
}

void World::setBodyAngularVelocity(BodyId id, float omega) {
    const char* call = "World::setBodyAngularVelocity";
    Body& b = movableBody(*impl_, call, id);
    requireFinite(call, "omega", omega);
    b.angularVelocity = b.fixedRotation ? 0.0f : omega;
}

// Forces and impulses move dynamic bodies only; static and kinematic bodies ignore them by
// definition (infinite mass), as BodyType documents.
void World::applyForce(BodyId id, Vec2 force, Vec2 worldPoint) {
    const char* call = "World::applyForce";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "force", force);
    requireFinite(call, "worldPoint", worldPoint);
    if (b.type != BodyType::Dynamic) return;
    b.force += force;
    b.torque += cross(worldPoint - b.center, force);
}

void World::applyForceToCenter(BodyId id, Vec2 force) {
    const char* call = "World::applyForceToCenter";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "force", force);
    if (b.type != BodyType::Dynamic) return;
    b.force += force;
}

void World::applyTorque(BodyId id, float torque) {
    const char* call = "World::applyTorque";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "torque", torque);
    if (b.type != BodyType::Dynamic) return;
    b.torque += torque;
}

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint) {
    const char* call = "World::applyLinearImpulse";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "impulse", impulse);
    requireFinite(call, "worldPoint", worldPoint);
    if (b.type != BodyType::Dynamic) return;
    b.linearVelocity += b.invMass * impulse;
    b.angularVelocity += b.invInertia * cross(worldPoint - b.center, impulse);
}

void World::applyAngularImpulse(BodyId id, float impulse) {
    const char* call = "World::applyAngularImpulse";
    Body& b = impl_->bodies[impl_->bodyIndex(call, id)];
    requireFinite(call, "impulse", impulse);
    if (b.type != BodyType::Dynamic) return;
    b.angularVelocity += b.invInertia * impulse;
}

// --- shapes -----------------------------------------------------------------------------------

namespace {
ShapeId attachShape(World::Impl& w, std::int32_t bodyIndex, const ShapeDef& def, Shape shape) {
    shape.body = bodyIndex;
    shape.density = def.density;
    shape.friction = def.friction;
    shape.restitution = def.restitution;
    shape.userData = def.userData;
    Body& body = w.bodies[bodyIndex];
    shape.next = body.shapeList;
    std::int32_t index = w.shapes.insert(shape);
    if (body.shapeList != -1) w.shapes[body.shapeList].prev = index;
    body.shapeList = index;
    ++body.shapeCount;
    updateBodyMass(body, w.shapes);
    return w.shapeId(index);
}
}  // namespace

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Circle& circle) {
    const char* call = "World::createShape";
    std::int32_t bodyIndex = impl_->bodyIndex(call, bodyId);
    checkShapeDef(call, def, impl_->bodies[bodyIndex]);
    requireFinite(call, "circle.center", circle.center);
    requireFinite(call, "circle.radius", circle.radius);
    if (circle.radius <= 0.0f) {
        fail(call, "circle.radius must be > 0 (got " + formatFloat(circle.radius) + ")");
    }
    Shape shape;
    shape.type = ShapeType::Circle;
    shape.circle = circle;
    return attachShape(*impl_, bodyIndex, def, shape);
}

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Polygon& polygon) {
    const char* call = "World::createShape";
    std::int32_t bodyIndex = impl_->bodyIndex(call, bodyId);
    checkShapeDef(call, def, impl_->bodies[bodyIndex]);
    Shape shape;
    shape.type = ShapeType::Polygon;
    std::string problem = makeConvexPolygon(polygon, shape.polygon);
    if (!problem.empty()) fail(call, problem);
    return attachShape(*impl_, bodyIndex, def, shape);
}

void World::destroyShape(ShapeId id) {
    Impl& w = *impl_;
    std::int32_t index = w.shapeIndex("World::destroyShape", id);
    std::int32_t bodyIndex = w.shapes[index].body;
    w.removeShape(index);
    updateBodyMass(w.bodies[bodyIndex], w.shapes);
}

bool World::isValid(ShapeId id) const {
    return id.world == impl_->id && impl_->shapes.isAlive(id.index) &&
           impl_->shapes.generation(id.index) == id.generation;
}

int World::shapeCount() const {
    return impl_->shapes.size();
}

BodyId World::shapeBody(ShapeId id) const {
    return impl_->bodyId(impl_->shapes[impl_->shapeIndex("World::shapeBody", id)].body);
}

// --- joints -----------------------------------------------------------------------------------

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
    w.linkJoint(index);
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
    return impl_->previousInvDt * j.impulse;
}

PositionSolver World::jointPositionSolver(JointId id) const {
    return impl_->joints[impl_->jointIndex("World::jointPositionSolver", id)].solver;
}

void World::setJointPositionSolver(JointId id, PositionSolver solver) {
    const char* call = "World::setJointPositionSolver";
    RevoluteJoint& j = impl_->joints[impl_->jointIndex(call, id)];
    checkSolver(call, "solver", solver);
    j.solver = solver;
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
}

// --- inspection -------------------------------------------------------------------------------

std::uint64_t World::stateHash() const {
    StateHasher h;
    impl_->bodies.forEach([&](std::int32_t index, const Body& b) {
        h.add(index);
        h.add(static_cast<std::int32_t>(b.type));
        h.add(b.center);
        h.add(b.angle);
        h.add(b.linearVelocity);
        h.add(b.angularVelocity);
        h.add(b.force);
        h.add(b.torque);
        h.add(b.mass);
        h.add(b.inertia);
        h.add(b.localCenter);
        h.add(b.shapeCount);
    });
    impl_->shapes.forEach([&](std::int32_t index, const Shape& s) {
        h.add(index);
        h.add(s.body);
        h.add(s.density);
    });
    impl_->joints.forEach([&](std::int32_t index, const RevoluteJoint& j) {
        h.add(index);
        h.add(static_cast<std::int32_t>(j.solver));
        h.add(j.biasFactor());
        h.add(j.impulse);
        h.add(j.bodyA());
        h.add(j.bodyB());
    });
    return h.value();
}

}  // namespace pivot
