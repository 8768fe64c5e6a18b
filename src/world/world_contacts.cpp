// The World facade, part five: what users can read about contacts.
#include "model/body_edge.h"
#include "world/world_impl.h"

namespace pivot {

namespace {

ContactData contactData(const World::Impl& w, const Contact& c) {
    const Shape& a = w.shapes[c.shapeA];
    const Shape& b = w.shapes[c.shapeB];
    WorldManifold wm = computeWorldManifold(c.manifold, w.bodies[a.body].xf, collisionRadius(a),
                                            w.bodies[b.body].xf, collisionRadius(b));
    ContactData data;
    data.shapeA = w.shapeId(c.shapeA);
    data.shapeB = w.shapeId(c.shapeB);
    data.normal = wm.normal;
    data.pointCount = c.manifold.pointCount;
    for (int i = 0; i < data.pointCount; ++i) {
        data.points[i] = {wm.points[i], wm.separations[i], c.manifold.points[i].normalImpulse,
                          c.manifold.points[i].tangentImpulse};
    }
    return data;
}

}  // namespace

std::vector<ContactData> World::contacts() const {
    const Impl& w = *impl_;
    std::vector<ContactData> result;
    w.contacts.forEach([&](std::int32_t, const Contact& c) {
        if (c.touching && !c.sensor) result.push_back(contactData(w, c));
    });
    return result;
}

std::vector<ContactData> World::bodyContacts(BodyId id) const {
    const Impl& w = *impl_;
    const Body& body = w.bodies[w.bodyIndex("World::bodyContacts", id)];
    std::vector<ContactData> result;
    for (std::int32_t key = body.contactList; key != -1;) {
        const Contact& c = w.contacts[edgeOwner(key)];
        if (c.touching && !c.sensor) result.push_back(contactData(w, c));
        key = c.edges[edgeSide(key)].nextKey;
    }
    return result;
}

std::vector<ContactEvent> World::contactBeginEvents() const {
    return impl_->contactManager.beginEvents();
}
std::vector<ContactEvent> World::contactEndEvents() const {
    return impl_->contactManager.endEvents();
}
std::vector<SensorEvent> World::sensorBeginEvents() const {
    return impl_->contactManager.sensorBeginEvents();
}
std::vector<SensorEvent> World::sensorEndEvents() const {
    return impl_->contactManager.sensorEndEvents();
}

}  // namespace pivot
