// Contact bookkeeping: contacts are made when the broad phase reports a new pair of
// overlapping boxes, updated (narrow phase) at the start of every step, and destroyed when the
// boxes part or a shape goes. Touching begins and ends are recorded as events.
#include "world/world_impl.h"

namespace pivot {

bool World::Impl::bodiesMayCollide(std::int32_t a, std::int32_t b) const {
    if (bodies[a].type != BodyType::Dynamic && bodies[b].type != BodyType::Dynamic) return false;
    for (std::int32_t key = bodies[b].jointList; key != -1;) {
        const RevoluteJoint& joint = joints[edgeOwner(key)];
        int side = edgeSide(key);
        if (joint.edges[1 - side].body == a && !joint.collideConnected) return false;
        key = joint.edges[side].nextKey;
    }
    return true;
}

void World::Impl::addPair(std::int32_t shapeA, std::int32_t shapeB) {
    const Shape& a = shapes[shapeA];
    const Shape& b = shapes[shapeB];
    // Cheapest rejections first: most reported pairs that make no contact are filtered out.
    if (a.body == b.body || !filtersAllowContact(a.filter, b.filter)) return;
    std::uint64_t key = PairMap::key(shapeA, shapeB);
    if (contactPairs.find(key) != -1) return;
    if (!bodiesMayCollide(a.body, b.body)) return;

    // The narrow phase has polygon-circle but not circle-polygon: put the polygon first.
    if (a.type == ShapeType::Circle && b.type == ShapeType::Polygon) std::swap(shapeA, shapeB);

    Contact contact;
    contact.shapeA = shapeA;
    contact.shapeB = shapeB;
    contact.edges[0].body = shapes[shapeA].body;
    contact.edges[1].body = shapes[shapeB].body;
    contact.friction = mixFriction(shapes[shapeA].friction, shapes[shapeB].friction);
    contact.restitution = mixRestitution(shapes[shapeA].restitution, shapes[shapeB].restitution);
    std::int32_t index = contacts.insert(contact);
    linkEdges(contacts, bodies, &Body::contactList, index);
    contactPairs.insert(key, index);
}

void World::Impl::destroyContact(std::int32_t index) {
    Contact& contact = contacts[index];
    if (contact.touching) {
        endEvents.push_back({shapeId(contact.shapeA), shapeId(contact.shapeB)});
        // Whatever rested on the contact must notice it is gone.
        wakeUp(bodies[contact.bodyA()]);
        wakeUp(bodies[contact.bodyB()]);
    }
    unlinkEdges(contacts, bodies, &Body::contactList, index);
    contactPairs.erase(PairMap::key(contact.shapeA, contact.shapeB));
    contacts.erase(index);
}

// Two phases, so the narrow phase can run on every worker: first each contact decides its own
// fate from what it can read (its shapes, bodies and boxes) and updates its own manifold; then,
// in contact order, the consequences that touch shared state (destruction, waking, events) are
// applied. A contact's fate never depends on another's consequences within the same step.
void World::Impl::updateContacts() {
    enum : std::uint8_t { kKeep, kDestroy, kBegan, kEnded };
    resizeBuffer(contactOutcomes, static_cast<std::size_t>(contacts.capacity()));
    pool.parallelFor(contacts.capacity(), 512, [&](int begin, int end, int) {
        for (std::int32_t index = begin; index < end; ++index) {
            std::uint8_t& outcome = contactOutcomes[index];
            outcome = kKeep;
            if (!contacts.isAlive(index)) continue;
            Contact& contact = contacts[index];
            const Shape& shapeA = shapes[contact.shapeA];
            const Shape& shapeB = shapes[contact.shapeB];
            if (contact.needsFiltering) {
                if (!bodiesMayCollide(contact.bodyA(), contact.bodyB()) ||
                    !filtersAllowContact(shapeA.filter, shapeB.filter)) {
                    outcome = kDestroy;
                    continue;
                }
                contact.needsFiltering = false;
            }
            const Body& bodyA = bodies[contact.bodyA()];
            const Body& bodyB = bodies[contact.bodyB()];
            bool activeA = bodyA.awake && bodyA.type != BodyType::Static;
            bool activeB = bodyB.awake && bodyB.type != BodyType::Static;
            if (!activeA && !activeB) continue;  // both asleep (or static): nothing changed
            if (!broadPhase.testOverlap(shapeA.proxyId, shapeB.proxyId)) {
                outcome = kDestroy;
                continue;
            }
            bool wasTouching = contact.touching;
            bool touching = updateContact(contact, shapeA, bodyA.xf, shapeB, bodyB.xf);
            if (touching != wasTouching) outcome = touching ? kBegan : kEnded;
        }
    });
    for (std::int32_t index = 0; index < contacts.capacity(); ++index) {
        switch (contactOutcomes[index]) {
            case kKeep: break;
            case kDestroy: destroyContact(index); break;
            case kBegan:
            case kEnded: {
                const Contact& contact = contacts[index];
                wakeUp(bodies[contact.bodyA()]);
                wakeUp(bodies[contact.bodyB()]);
                std::vector<ContactEvent>& events =
                    contactOutcomes[index] == kBegan ? beginEvents : endEvents;
                events.push_back({shapeId(contact.shapeA), shapeId(contact.shapeB)});
                break;
            }
        }
    }
}

void World::Impl::countCategories(const Filter& filter, int delta) {
    for (int bit = 0; bit < 16; ++bit) {
        if (filter.categoryBits & (1u << bit)) categoryCounts[bit] += delta;
    }
}

std::uint16_t World::Impl::presentCategories() const {
    std::uint16_t present = 0;
    for (int bit = 0; bit < 16; ++bit) {
        if (categoryCounts[bit] > 0) present = static_cast<std::uint16_t>(present | (1u << bit));
    }
    return present;
}

void World::Impl::findNewContacts() {
    // The cheap, read-only part of addPair's test runs inside the (parallel) queries.
    auto mayPair = [this](std::int32_t a, std::int32_t b) {
        const Shape& shapeA = shapes[a];
        const Shape& shapeB = shapes[b];
        return shapeA.body != shapeB.body && filtersAllowContact(shapeA.filter, shapeB.filter);
    };
    const std::uint16_t present = presentCategories();
    auto mayMeetAnything = [this, present](std::int32_t s) {
        const Filter& filter = shapes[s].filter;
        return filter.groupIndex > 0 || (filter.maskBits & present) != 0;
    };
    broadPhase.updatePairs(pool, mayMeetAnything, mayPair,
                           [this](std::int32_t a, std::int32_t b) { addPair(a, b); });
}

void World::Impl::synchronizeShapes(std::int32_t bodyIndex, bool swept) {
    const Body& body = bodies[bodyIndex];
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        Shape& shape = shapes[s];
        // The box kept from the last sync is the box at the start of this step's motion.
        AABB after = computeShapeBox(shape, body.xf);
        AABB before = swept ? shape.box : after;
        shape.box = after;
        Vec2 displacement =
            0.5f * (after.lower + after.upper) - 0.5f * (before.lower + before.upper);
        broadPhase.moveProxy(shape.proxyId, combine(before, after), displacement);
    }
}

void World::Impl::synchronizeSolvedBodies() {
    resizeBuffer(shapeMoves, static_cast<std::size_t>(shapes.capacity()));
    const int count = static_cast<int>(islands.bodies.size());
    // A box costs about a tenth of a microsecond, a hand-off to the workers tens: share out
    // only big batches.
    pool.parallelFor(count, 1024, [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i) {
            const Body& body = bodies[islands.bodies[i]];
            if (body.type == BodyType::Static) continue;
            for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
                Shape& shape = shapes[s];
                AABB after = computeShapeBox(shape, body.xf);
                ShapeMove& move = shapeMoves[s];
                move.swept = combine(shape.box, after);
                move.displacement =
                    0.5f * (after.lower + after.upper) - 0.5f * (shape.box.lower + shape.box.upper);
                move.needed = broadPhase.needsMove(shape.proxyId, move.swept, move.displacement);
                shape.box = after;
            }
        }
    });
    // Re-insertions change the tree: one at a time, in a fixed order.
    for (std::int32_t b : islands.bodies) {
        const Body& body = bodies[b];
        if (body.type == BodyType::Static) continue;
        for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
            const ShapeMove& move = shapeMoves[s];
            if (move.needed) broadPhase.moveProxy(shapes[s].proxyId, move.swept, move.displacement);
        }
    }
}

void World::Impl::refilterBodyPair(std::int32_t a, std::int32_t b) {
    for (std::int32_t key = bodies[b].contactList; key != -1;) {
        Contact& contact = contacts[edgeOwner(key)];
        int side = edgeSide(key);
        if (contact.edges[1 - side].body == a) contact.needsFiltering = true;
        key = contact.edges[side].nextKey;
    }
    for (std::int32_t body : {a, b}) {
        for (std::int32_t s = bodies[body].shapeList; s != -1; s = shapes[s].next) {
            broadPhase.touchProxy(shapes[s].proxyId);
        }
    }
    newShapes = true;
}

void World::Impl::refilterBody(std::int32_t bodyIndex) {
    Body& body = bodies[bodyIndex];
    for (std::int32_t key = body.contactList; key != -1;) {
        Contact& contact = contacts[edgeOwner(key)];
        int side = edgeSide(key);
        contact.needsFiltering = true;
        wakeUp(bodies[contact.edges[1 - side].body]);
        key = contact.edges[side].nextKey;
    }
    for (std::int32_t key = body.jointList; key != -1;) {
        const RevoluteJoint& joint = joints[edgeOwner(key)];
        int side = edgeSide(key);
        wakeUp(bodies[joint.edges[1 - side].body]);
        key = joint.edges[side].nextKey;
    }
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        broadPhase.touchProxy(shapes[s].proxyId);
    }
    newShapes = true;
}

}  // namespace pivot
