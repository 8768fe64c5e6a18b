// The islands of one step: sets of awake bodies connected by joints and touching contacts,
// each independent of every other for this step. Built by IslandBuilder.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "constraints/solver_body.h"
#include "core/buffer.h"

namespace pivot {

/// One island's slice of an IslandSet.
struct IslandView {
    const std::int32_t* bodies;
    int bodyCount;
    const std::int32_t* contacts;
    const BodyPair* contactBodies;
    int contactCount;
    const std::int32_t* joints;
    const JointSlots* jointBodies;
    int jointCount;
    const std::int32_t* mouseJoints;
    const std::int32_t* mouseBodies;
    int mouseCount;
};

/// Every island of a step, island after island in flat arrays. The solver indices are recorded
/// here rather than in the bodies, because a static body belongs to every island that touches
/// it, with a different index in each.
struct IslandSet {
    struct Range {
        std::int32_t bodyBegin, bodyEnd;
        std::int32_t contactBegin, contactEnd;
        std::int32_t jointBegin, jointEnd;
        std::int32_t mouseBegin, mouseEnd;
    };
    std::vector<std::int32_t> bodies;    // body pool indices; solver index = position - bodyBegin
    std::vector<std::int32_t> contacts;  // touching contacts, in the order they were reached
    std::vector<BodyPair> contactBodies;
    std::vector<std::int32_t> joints;  // joints, in the order they were reached
    std::vector<JointSlots> jointBodies;
    std::vector<std::int32_t> mouseJoints;
    std::vector<std::int32_t> mouseBodies;  // solver index of each mouse joint's body
    std::vector<Range> ranges;

    /// Room for every island the world could form: a static body is listed once in each island
    /// it touches, so the bodies of all islands are at most the bodies plus the constraints.
    void reserve(const BufferBounds& bound) {
        bodies.reserve(bound.bodies + bound.joints + bound.contacts);
        contacts.reserve(bound.contacts);
        contactBodies.reserve(bound.contacts);
        joints.reserve(bound.joints);
        jointBodies.reserve(bound.joints);
        mouseJoints.reserve(bound.mouseJoints);
        mouseBodies.reserve(bound.mouseJoints);
        ranges.reserve(bound.bodies);
    }

    void clear() {
        bodies.clear();
        contacts.clear();
        contactBodies.clear();
        joints.clear();
        jointBodies.clear();
        mouseJoints.clear();
        mouseBodies.clear();
        ranges.clear();
    }

    IslandView view(int index) const { return view(index, 1); }

    /// Islands [first, first + count) as one view: their flat arrays are consecutive. The
    /// solver slots in contactBodies, jointBodies and mouseBodies stay each island's own.
    IslandView view(int first, int count) const {
        Range r = ranges[first];
        const Range& last = ranges[first + count - 1];
        r.bodyEnd = last.bodyEnd;
        r.contactEnd = last.contactEnd;
        r.jointEnd = last.jointEnd;
        r.mouseEnd = last.mouseEnd;
        return {bodies.data() + r.bodyBegin,       r.bodyEnd - r.bodyBegin,
                contacts.data() + r.contactBegin,  contactBodies.data() + r.contactBegin,
                r.contactEnd - r.contactBegin,     joints.data() + r.jointBegin,
                jointBodies.data() + r.jointBegin, r.jointEnd - r.jointBegin,
                mouseJoints.data() + r.mouseBegin, mouseBodies.data() + r.mouseBegin,
                r.mouseEnd - r.mouseBegin};
    }
};

}  // namespace pivot
