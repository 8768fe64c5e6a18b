// Contact bookkeeping: contacts are made when the broad phase reports a new pair of
// overlapping boxes, updated (narrow phase) at the start of every step, and destroyed when the
// boxes part or a shape goes. Touching begins and ends are recorded as events.
#include "world_impl.h"

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
    if (a.body == b.body) return;
    std::uint64_t key = PairMap::key(shapeA, shapeB);
    if (contactPairs.find(key) != -1) return;
    if (!bodiesMayCollide(a.body, b.body)) return;
    if (!filtersAllowContact(a.filter, b.filter)) return;

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

void World::Impl::updateContacts() {
    for (std::int32_t index = 0; index < contacts.capacity(); ++index) {
        if (!contacts.isAlive(index)) continue;
        Contact& contact = contacts[index];
        const Shape& shapeA = shapes[contact.shapeA];
        const Shape& shapeB = shapes[contact.shapeB];
        if (contact.needsFiltering) {
            if (!bodiesMayCollide(contact.bodyA(), contact.bodyB()) ||
                !filtersAllowContact(shapeA.filter, shapeB.filter)) {
                destroyContact(index);
                continue;
            }
            contact.needsFiltering = false;
        }
        Body& bodyA = bodies[contact.bodyA()];
        Body& bodyB = bodies[contact.bodyB()];
        bool activeA = bodyA.awake && bodyA.type != BodyType::Static;
        bool activeB = bodyB.awake && bodyB.type != BodyType::Static;
        if (!activeA && !activeB) continue;  // both asleep (or static): nothing changed
        if (!broadPhase.testOverlap(shapeA.proxyId, shapeB.proxyId)) {
            destroyContact(index);
            continue;
        }
        bool wasTouching = contact.touching;
        bool touching = updateContact(contact, shapeA, bodyA.xf, shapeB, bodyB.xf);
        if (touching != wasTouching) {
            wakeUp(bodyA);
            wakeUp(bodyB);
            std::vector<ContactEvent>& events = touching ? beginEvents : endEvents;
            events.push_back({shapeId(contact.shapeA), shapeId(contact.shapeB)});
        }
    }
}

void World::Impl::findNewContacts() {
    broadPhase.updatePairs([this](std::int32_t a, std::int32_t b) { addPair(a, b); });
}

void World::Impl::synchronizeShapes(std::int32_t bodyIndex) {
    const Body& body = bodies[bodyIndex];
    Transform xf0;
    xf0.q = Rot(body.angle0);
    xf0.p = body.center0 - rotate(xf0.q, body.localCenter);
    for (std::int32_t s = body.shapeList; s != -1; s = shapes[s].next) {
        const Shape& shape = shapes[s];
        AABB before = computeShapeBox(shape, xf0);
        AABB after = computeShapeBox(shape, body.xf);
        Vec2 displacement =
            0.5f * (after.lower + after.upper) - 0.5f * (before.lower + before.upper);
        broadPhase.moveProxy(shape.proxyId, combine(before, after), displacement);
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
