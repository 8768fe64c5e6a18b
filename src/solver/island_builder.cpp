#include "solver/island_builder.h"

namespace pivot {

void IslandBuilder::collect(std::int32_t seed, SlotPool<Body>& bodies,
                            const SlotPool<RevoluteJoint>& joints, Island& island) {
    island.bodies.clear();
    island.joints.clear();
    stack_.clear();
    stack_.push_back(seed);
    bodyVisited_[seed] = 1;

    while (!stack_.empty()) {
        std::int32_t bodyIndex = stack_.back();
        stack_.pop_back();
        Body& body = bodies[bodyIndex];
        body.islandIndex = static_cast<std::int32_t>(island.bodies.size());
        island.bodies.push_back(bodyIndex);
        if (body.type == BodyType::Static) continue;  // does not connect islands

        for (std::int32_t key = body.jointList; key != -1;) {
            std::int32_t jointIndex = jointOfKey(key);
            const RevoluteJoint& joint = joints[jointIndex];
            int side = sideOfKey(key);
            key = joint.edges[side].nextKey;
            if (jointVisited_[jointIndex]) continue;
            jointVisited_[jointIndex] = 1;
            island.joints.push_back(jointIndex);
            std::int32_t other = joint.edges[1 - side].body;
            if (bodyVisited_[other]) continue;
            bodyVisited_[other] = 1;
            stack_.push_back(other);
        }
    }
}

}  // namespace pivot
