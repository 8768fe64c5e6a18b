// The world's object pools, as the island builder and the island solver reach them.
#pragma once

#include "core/slot_pool.h"
#include "joints/joint.h"
#include "joints/mouse_joint.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/contact_census.h"
#include "model/island_revision.h"
#include "model/shape.h"

namespace pivot {

/// The object pools the solver reads and writes.
struct SolverStorage {
    SlotPool<Body>& bodies;
    const SlotPool<Shape>& shapes;
    SlotPool<Joint>& joints;
    SlotPool<Contact>& contacts;
    const ContactCensus& contactCensus;  // the contacts' summaries (ContactManager keeps it)
    SlotPool<MouseJoint>& mouseJoints;
    IslandRevision& islandRevision;
};

}  // namespace pivot
