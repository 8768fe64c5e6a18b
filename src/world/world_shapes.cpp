// The World facade, part three: shapes.
#include "model/body_edge.h"
#include "world/world_checks.h"
#include "world/world_impl.h"

namespace pivot {

namespace {

void checkShapeDef(const char* call, const ShapeDef& def, const Body& body) {
    requireDensity(call, "def.density", def.density);
    if (body.type == BodyType::Dynamic && def.density <= 0.0f) {
        fail(call,
             "def.density must be > 0 on a dynamic body (got " + formatFloat(def.density) + ")");
    }
    requireWithin(call, "def.friction", def.friction, kMaxFriction, "kMaxFriction");
    requireNonNegative(call, "def.friction", def.friction);
    requireInRange(call, "def.restitution", def.restitution, 0.0f, 1.0f);
}

ShapeId attachShape(const char* call, World::Impl& w, std::int32_t bodyIndex, const ShapeDef& def,
                    Shape shape) {
    shape.body = bodyIndex;
    shape.density = def.density;
    shape.friction = def.friction;
    shape.restitution = def.restitution;
    shape.filter = def.filter;
    shape.userData = def.userData;
    shape.sensor = def.isSensor;
    shape.hitEvents = def.enableHitEvents;
    shape.preSolve = def.enablePreSolve;
    Body& body = w.bodies[bodyIndex];
    requireMotionAfterMassChange(
        call, bodyAfterMassChange(body, w.shapes, MassChange{body.type, &shape}), body);
    w.contactManager.countCategories(shape.filter, +1);
    if (movesAndStopsTunnelling(body)) w.contactManager.countMovingStoppers(+1);
    if (shape.hitEvents) ++w.hitEventShapeCount;
    shape.next = body.shapeList;
    std::int32_t index = w.shapes.insert(shape);
    if (body.shapeList != -1) w.shapes[body.shapeList].prev = index;
    body.shapeList = index;
    ++body.shapeCount;
    updateBodyMass(body, w.shapes);
    w.shapes[index].box = computeShapeBox(w.shapes[index], body.xf);
    w.shapes[index].proxyId = w.contactManager.broadPhase().createProxy(
        w.shapes[index].box, index, body.type == BodyType::Static);
    w.contactManager.markNewShapes();
    // A sleeping body stays asleep, as Box2D's do: a body made asleep (BodyDef::isAwake false)
    // is given its shapes and sleeps on until something wakes it.
    if (body.awake) wakeUp(body, w.islandRevision);
    return w.shapeId(index);
}

}  // namespace

void World::Impl::removeShape(std::int32_t index) {
    const Shape& shape = shapes[index];
    contactManager.countCategories(shape.filter, -1);
    if (shape.hitEvents) --hitEventShapeCount;
    Body& body = bodies[shape.body];
    if (movesAndStopsTunnelling(body)) contactManager.countMovingStoppers(-1);
    for (std::int32_t key = body.contactList; key != -1;) {
        std::int32_t contactIndex = edgeOwner(key);
        const Contact& contact = contacts[contactIndex];
        key = contact.edges[edgeSide(key)].nextKey;
        if (contact.shapeA == index || contact.shapeB == index)
            contactManager.destroyContact(contactIndex);
    }
    contactManager.broadPhase().destroyProxy(shape.proxyId);
    if (shape.prev != -1) {
        shapes[shape.prev].next = shape.next;
    } else {
        body.shapeList = shape.next;
    }
    if (shape.next != -1) shapes[shape.next].prev = shape.prev;
    --body.shapeCount;
    shapes.erase(index);
}

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Circle& circle) {
    const char* call = "World::createShape";
    impl_->requireStructureChange(call);
    std::int32_t bodyIndex = impl_->bodyIndex(call, bodyId);
    checkShapeDef(call, def, impl_->bodies[bodyIndex]);
    checkCircle(call, circle);
    Shape shape;
    shape.type = ShapeType::Circle;
    shape.circle = circle;
    return attachShape(call, *impl_, bodyIndex, def, shape);
}

namespace {

// A polygon or capsule: checked by `make` into the two-vertex-or-more polygon collision sees.
template <typename Geometry>
ShapeId createPolygonal(World::Impl& w, BodyId bodyId, const ShapeDef& def, ShapeType type,
                        const Geometry& geometry,
                        std::string (*make)(const Geometry&, ConvexPolygon&)) {
    const char* call = "World::createShape";
    w.requireStructureChange(call);
    std::int32_t bodyIndex = w.bodyIndex(call, bodyId);
    checkShapeDef(call, def, w.bodies[bodyIndex]);
    Shape shape;
    shape.type = type;
    std::string problem = make(geometry, shape.polygon);
    if (!problem.empty()) fail(call, problem);
    return attachShape(call, w, bodyIndex, def, shape);
}

}  // namespace

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Polygon& polygon) {
    return createPolygonal(*impl_, bodyId, def, ShapeType::Polygon, polygon, makeConvexPolygon);
}

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Capsule& capsule) {
    return createPolygonal(*impl_, bodyId, def, ShapeType::Capsule, capsule, makeCapsulePolygon);
}

namespace {

std::int32_t segmentBody(const char* call, World::Impl& w, BodyId bodyId, const ShapeDef& def) {
    w.requireStructureChange(call);
    std::int32_t bodyIndex = w.bodyIndex(call, bodyId);
    if (w.bodies[bodyIndex].type == BodyType::Dynamic) {
        fail(call,
             "a segment has no area and so no mass: it goes on a static or kinematic "
             "body, not a dynamic one");
    }
    checkShapeDef(call, def, w.bodies[bodyIndex]);
    return bodyIndex;
}

}  // namespace

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const Segment& segment) {
    const char* call = "World::createShape";
    impl_->requireStructureChange(call);
    const std::int32_t bodyIndex = segmentBody(call, *impl_, bodyId, def);
    Shape shape;
    shape.type = ShapeType::Segment;
    std::string problem = makeSegmentPolygon(segment, shape.polygon);
    if (!problem.empty()) fail(call, problem);
    return attachShape(call, *impl_, bodyIndex, def, shape);
}

ShapeId World::createShape(BodyId bodyId, const ShapeDef& def, const ChainSegment& segment) {
    const char* call = "World::createShape";
    impl_->requireStructureChange(call);
    const std::int32_t bodyIndex = segmentBody(call, *impl_, bodyId, def);
    Shape shape;
    shape.type = ShapeType::ChainSegment;
    std::string problem = makeChainSegment(segment, shape.polygon);
    if (!problem.empty()) fail(call, problem);
    shape.ghost1 = segment.ghost1;
    shape.ghost2 = segment.ghost2;
    return attachShape(call, *impl_, bodyIndex, def, shape);
}

std::vector<ShapeId> World::createChain(BodyId bodyId, const ShapeDef& def, const Chain& chain) {
    const char* call = "World::createChain";
    impl_->requireStructureChange(call);
    const std::int32_t bodyIndex = segmentBody(call, *impl_, bodyId, def);
    const std::vector<Vec2>& p = chain.points;
    const int n = static_cast<int>(p.size());
    const int fewest = chain.loop ? 3 : 4;
    if (n < fewest) {
        fail(call, std::string(chain.loop ? "a loop" : "an open chain") + " needs at least " +
                       std::to_string(fewest) + " points (got " + std::to_string(n) + ")");
    }
    auto name = [](int i) { return "chain.points[" + std::to_string(i) + "]"; };
    for (int i = 0; i < n; ++i) {
        std::string problem = checkPathPoint(name(i), p[i]);
        if (!problem.empty()) fail(call, problem);
    }
    const int steps = chain.loop ? n : n - 1;
    for (int i = 0; i < steps; ++i) {
        const int j = (i + 1) % n;
        std::string problem = checkPathStep(name(i), p[i], name(j), p[j]);
        if (!problem.empty()) fail(call, problem);
    }
    // Segment k runs from point k to point k + 1 (a loop's last one back to point 0; an open
    // chain's first and last points are ghosts only).
    const int first = chain.loop ? 0 : 1;
    const int segments = chain.loop ? n : n - 3;
    auto at = [&](int i) { return p[static_cast<std::size_t>((i + n) % n)]; };
    std::vector<Shape> made;
    made.reserve(static_cast<std::size_t>(segments));
    for (int k = first; k < first + segments; ++k) {
        Shape shape;
        shape.type = ShapeType::ChainSegment;
        const ChainSegment segment{at(k - 1), Segment{at(k), at(k + 1)}, at(k + 2)};
        std::string problem = makeChainSegment(segment, shape.polygon);
        if (!problem.empty()) fail(call, problem);  // checked above; kept as a guard
        shape.ghost1 = segment.ghost1;
        shape.ghost2 = segment.ghost2;
        made.push_back(shape);
    }
    std::vector<ShapeId> ids;
    ids.reserve(made.size());
    try {
        for (const Shape& shape : made) {
            ids.push_back(attachShape(call, *impl_, bodyIndex, def, shape));
        }
    } catch (...) {
        // All or nothing: a chain cut short would be a chain the caller did not ask for.
        for (ShapeId id : ids) impl_->removeShape(impl_->shapeIndex(call, id));
        updateBodyMass(impl_->bodies[bodyIndex], impl_->shapes);
        throw;
    }
    return ids;
}

void World::destroyShape(ShapeId id) {
    const char* call = "World::destroyShape";
    Impl& w = *impl_;
    w.requireStructureChange(call);
    std::int32_t index = w.shapeIndex(call, id);
    std::int32_t bodyIndex = w.shapes[index].body;
    MassChange change{w.bodies[bodyIndex].type};
    change.removed = index;
    requireMotionAfterMassChange(call, bodyAfterMassChange(w.bodies[bodyIndex], w.shapes, change),
                                 w.bodies[bodyIndex]);
    w.removeShape(index);
    updateBodyMass(w.bodies[bodyIndex], w.shapes);
    wakeUp(w.bodies[bodyIndex], w.islandRevision);
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

ShapeType World::shapeType(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeType", id)].type;
}

namespace {

const char* shapeTypeName(ShapeType type) {
    switch (type) {
        case ShapeType::Circle: return "a circle";
        case ShapeType::Polygon: return "a polygon";
        case ShapeType::Segment: return "a segment";
        case ShapeType::ChainSegment: return "a chain segment";
        case ShapeType::Capsule: return "a capsule";
    }
    return "unknown";
}

const Shape& shapeOfType(const char* call, const World::Impl& w, ShapeId id, ShapeType type) {
    const Shape& shape = w.shapes[w.shapeIndex(call, id)];
    if (shape.type != type) {
        fail(call,
             std::string("shape is ") + shapeTypeName(shape.type) + ", not " + shapeTypeName(type));
    }
    return shape;
}

}  // namespace

Circle World::shapeCircle(ShapeId id) const {
    return shapeOfType("World::shapeCircle", *impl_, id, ShapeType::Circle).circle;
}

Segment World::shapeSegment(ShapeId id) const {
    const Shape& shape = shapeOfType("World::shapeSegment", *impl_, id, ShapeType::Segment);
    return Segment{shape.polygon.vertices[0], shape.polygon.vertices[1]};
}

Capsule World::shapeCapsule(ShapeId id) const {
    const Shape& shape = shapeOfType("World::shapeCapsule", *impl_, id, ShapeType::Capsule);
    return Capsule{shape.polygon.vertices[0], shape.polygon.vertices[1], shape.polygon.radius};
}

ChainSegment World::shapeChainSegment(ShapeId id) const {
    const Shape& shape =
        shapeOfType("World::shapeChainSegment", *impl_, id, ShapeType::ChainSegment);
    return ChainSegment{shape.ghost1, Segment{shape.polygon.vertices[0], shape.polygon.vertices[1]},
                        shape.ghost2};
}

Polygon World::shapePolygon(ShapeId id) const {
    const Shape& shape = shapeOfType("World::shapePolygon", *impl_, id, ShapeType::Polygon);
    Polygon polygon;
    polygon.count = shape.polygon.count;
    for (int i = 0; i < polygon.count; ++i) polygon.vertices[i] = shape.polygon.vertices[i];
    polygon.radius = shape.polygon.radius;
    return polygon;
}

float World::shapeFriction(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeFriction", id)].friction;
}

float World::shapeRestitution(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeRestitution", id)].restitution;
}

namespace {

// Contacts keep their shapes' mixed friction and restitution; a change of either is mixed
// into every contact of the shape at once, so the next step uses it.
void remixContacts(World::Impl& w, std::int32_t shapeIndex) {
    const Body& body = w.bodies[w.shapes[shapeIndex].body];
    for (std::int32_t key = body.contactList; key != -1;) {
        Contact& c = w.contacts[edgeOwner(key)];
        key = c.edges[edgeSide(key)].nextKey;
        if (c.shapeA != shapeIndex && c.shapeB != shapeIndex) continue;
        const Shape& a = w.shapes[c.shapeA];
        const Shape& b = w.shapes[c.shapeB];
        c.friction = mixFriction(a.friction, b.friction);
        c.restitution = mixRestitution(a.restitution, b.restitution);
    }
}

}  // namespace

bool World::shapeHitEventsEnabled(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeHitEventsEnabled", id)].hitEvents;
}
void World::setShapeHitEventsEnabled(ShapeId id, bool enabled) {
    const char* call = "World::setShapeHitEventsEnabled";
    impl_->requireChange(call);
    Shape& shape = impl_->shapes[impl_->shapeIndex(call, id)];
    if (shape.hitEvents != enabled) impl_->hitEventShapeCount += enabled ? 1 : -1;
    shape.hitEvents = enabled;
}
bool World::shapePreSolveEnabled(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapePreSolveEnabled", id)].preSolve;
}
void World::setShapePreSolveEnabled(ShapeId id, bool enabled) {
    const char* call = "World::setShapePreSolveEnabled";
    impl_->requireChange(call);
    Impl& w = *impl_;
    const std::int32_t index = w.shapeIndex(call, id);
    w.shapes[index].preSolve = enabled;
    // A sleeping pair is not asked: wake what the shape touches (a static platform does not
    // sleep, the bodies on it do).
    Body& body = w.bodies[w.shapes[index].body];
    wakeUp(body, w.islandRevision);
    for (std::int32_t key = body.contactList; key != -1;) {
        const Contact& c = w.contacts[edgeOwner(key)];
        const int side = edgeSide(key);
        key = c.edges[side].nextKey;
        if (c.shapeA == index || c.shapeB == index)
            wakeUp(w.bodies[c.edges[1 - side].body], w.islandRevision);
    }
}

bool World::isShapeSensor(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::isShapeSensor", id)].sensor;
}

void World::setShapeSensor(ShapeId id, bool sensor) {
    const char* call = "World::setShapeSensor";
    Impl& w = *impl_;
    w.requireStructureChange(call);
    const std::int32_t index = w.shapeIndex(call, id);
    Shape& shape = w.shapes[index];
    if (shape.sensor == sensor) return;
    // Its contacts become sensor overlaps or the other way: drop them now (with their end
    // events) and let the next step pair the shape again.
    Body& body = w.bodies[shape.body];
    for (std::int32_t key = body.contactList; key != -1;) {
        const std::int32_t contactIndex = edgeOwner(key);
        const Contact& contact = w.contacts[contactIndex];
        key = contact.edges[edgeSide(key)].nextKey;
        if (contact.shapeA == index || contact.shapeB == index) {
            w.contactManager.destroyContact(contactIndex);
        }
    }
    shape.sensor = sensor;
    w.contactManager.broadPhase().touchProxy(shape.proxyId);
    w.contactManager.markNewShapes();
    wakeUp(body, w.islandRevision);
}

void World::setShapeFriction(ShapeId id, float friction) {
    const char* call = "World::setShapeFriction";
    impl_->requireChange(call);
    Impl& w = *impl_;
    const std::int32_t index = w.shapeIndex(call, id);
    requireWithin(call, "friction", friction, kMaxFriction, "kMaxFriction");
    requireNonNegative(call, "friction", friction);
    w.shapes[index].friction = friction;
    remixContacts(w, index);
    wakeUp(w.bodies[w.shapes[index].body], w.islandRevision);
}

void World::setShapeRestitution(ShapeId id, float restitution) {
    const char* call = "World::setShapeRestitution";
    impl_->requireChange(call);
    Impl& w = *impl_;
    const std::int32_t index = w.shapeIndex(call, id);
    requireInRange(call, "restitution", restitution, 0.0f, 1.0f);
    w.shapes[index].restitution = restitution;
    remixContacts(w, index);
    wakeUp(w.bodies[w.shapes[index].body], w.islandRevision);
}

float World::shapeDensity(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeDensity", id)].density;
}

void World::setShapeDensity(ShapeId id, float density) {
    const char* call = "World::setShapeDensity";
    impl_->requireChange(call);
    Impl& w = *impl_;
    std::int32_t index = w.shapeIndex(call, id);
    requireDensity(call, "density", density);
    Shape& shape = w.shapes[index];
    Body& body = w.bodies[shape.body];
    if (body.type == BodyType::Dynamic && density == 0.0f) {
        fail(call, "density must be > 0 on a dynamic body (got 0)");
    }
    MassChange change{body.type};
    change.reweighed = index;
    change.density = density;
    requireMotionAfterMassChange(call, bodyAfterMassChange(body, w.shapes, change), body);
    shape.density = density;
    updateBodyMass(body, w.shapes);
    wakeUp(body, w.islandRevision);
}

Filter World::shapeFilter(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeFilter", id)].filter;
}

std::uint64_t World::shapeUserData(ShapeId id) const {
    return impl_->shapes[impl_->shapeIndex("World::shapeUserData", id)].userData;
}

void World::setShapeUserData(ShapeId id, std::uint64_t userData) {
    impl_->requireChange("World::setShapeUserData");
    impl_->shapes[impl_->shapeIndex("World::setShapeUserData", id)].userData = userData;
}

void World::setShapeFilter(ShapeId id, const Filter& filter) {
    impl_->requireChange("World::setShapeFilter");
    Impl& w = *impl_;
    std::int32_t index = w.shapeIndex("World::setShapeFilter", id);
    Shape& shape = w.shapes[index];
    w.contactManager.countCategories(shape.filter, -1);
    shape.filter = filter;
    w.contactManager.countCategories(shape.filter, +1);
    // Existing contacts may now be forbidden; pairs the old filter refused may now be allowed.
    for (std::int32_t key = w.bodies[shape.body].contactList; key != -1;) {
        const Contact& contact = w.contacts[edgeOwner(key)];
        if (contact.shapeA == index || contact.shapeB == index) {
            w.contactManager.refilterContact(edgeOwner(key));
        }
        key = contact.edges[edgeSide(key)].nextKey;
    }
    w.contactManager.broadPhase().touchProxy(shape.proxyId);
    w.contactManager.markNewShapes();
    wakeUp(w.bodies[shape.body], w.islandRevision);
}

}  // namespace pivot
