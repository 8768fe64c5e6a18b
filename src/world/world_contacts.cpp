// The World facade, part five: what users can read about contacts, the step's events and the
// callbacks that take part in it.
#include <utility>

#include "model/body_edge.h"
#include "world/world_impl.h"

namespace pivot {

std::vector<ContactData> World::contacts() const {
    impl_->requireRead("World::contacts");
    const Impl& w = *impl_;
    std::vector<ContactData> result;
    w.contacts.forEach([&](std::int32_t, const Contact& c) {
        if (c.touching && !c.sensor) result.push_back(w.contactManager.contactData(c));
    });
    return result;
}

std::vector<ContactData> World::bodyContacts(BodyId id) const {
    const Impl& w = *impl_;
    const Body& body = w.bodies[w.bodyIndex("World::bodyContacts", id)];
    std::vector<ContactData> result;
    for (std::int32_t key = body.contactList; key != -1;) {
        const Contact& c = w.contacts[edgeOwner(key)];
        if (c.touching && !c.sensor) result.push_back(w.contactManager.contactData(c));
        key = c.edges[edgeSide(key)].nextKey;
    }
    return result;
}

std::vector<ContactEvent> World::contactBeginEvents() const {
    impl_->requireRead("World::contactBeginEvents");
    return impl_->contactManager.beginEvents();
}
std::vector<ContactEvent> World::contactEndEvents() const {
    impl_->requireRead("World::contactEndEvents");
    return impl_->contactManager.endEvents();
}
std::vector<SensorEvent> World::sensorBeginEvents() const {
    impl_->requireRead("World::sensorBeginEvents");
    return impl_->contactManager.sensorBeginEvents();
}
std::vector<SensorEvent> World::sensorEndEvents() const {
    impl_->requireRead("World::sensorEndEvents");
    return impl_->contactManager.sensorEndEvents();
}
std::vector<ContactHitEvent> World::contactHitEvents() const {
    impl_->requireRead("World::contactHitEvents");
    return impl_->hitEvents;
}
std::vector<BodyMoveEvent> World::bodyMoveEvents() const {
    impl_->requireRead("World::bodyMoveEvents");
    return impl_->moveEvents;
}

void World::setPreSolveCallback(PreSolveCallback callback) {
    impl_->requireChange("World::setPreSolveCallback");
    impl_->contactManager.setPreSolve(std::move(callback));
}
void World::setCustomFilterCallback(CustomFilterCallback callback) {
    impl_->requireChange("World::setCustomFilterCallback");
    impl_->contactManager.setCustomFilter(std::move(callback));
}

}  // namespace pivot
