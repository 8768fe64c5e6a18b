#include "solver/island_builder.h"

namespace pivot {

void IslandBuilder::reach(std::int32_t other) {
    if (bodyVisited_[other]) return;
    bodyVisited_[other] = 1;
    stack_.push_back(other);
}

void IslandBuilder::collect(std::int32_t seed, SolverStorage& storage, Island& island) {
    island.bodies.clear();
    island.contacts.clear();
    island.joints.clear();
    island.mouseJoints.clear();
    stack_.clear();
    stack_.push_back(seed);
    bodyVisited_[seed] = 1;

    while (!stack_.empty()) {
        std::int32_t bodyIndex = stack_.back();
        stack_.pop_back();
        Body& body = storage.bodies[bodyIndex];
        body.islandIndex = static_cast<std::int32_t>(island.bodies.size());
        island.bodies.push_back(bodyIndex);
        if (body.type == BodyType::Static) continue;  // does not connect islands
        body.awake = true;  // keeps its sleep timer: it may still be at rest
        for (std::int32_t m = body.mouseList; m != -1; m = storage.mouseJoints[m].next) {
            island.mouseJoints.push_back(m);
        }

        for (std::int32_t key = body.contactList; key != -1;) {
            std::int32_t contactIndex = edgeOwner(key);
            const Contact& contact = storage.contacts[contactIndex];
            int side = edgeSide(key);
            key = contact.edges[side].nextKey;
            if (contactVisited_[contactIndex] || !contact.touching) continue;
            contactVisited_[contactIndex] = 1;
            island.contacts.push_back(contactIndex);
            reach(contact.edges[1 - side].body);
        }

        for (std::int32_t key = body.jointList; key != -1;) {
            std::int32_t jointIndex = edgeOwner(key);
            const RevoluteJoint& joint = storage.joints[jointIndex];
            int side = edgeSide(key);
            key = joint.edges[side].nextKey;
            if (jointVisited_[jointIndex]) continue;
            jointVisited_[jointIndex] = 1;
            island.joints.push_back(jointIndex);
            reach(joint.edges[1 - side].body);
        }
    }
}

}  // namespace pivot
