// Small islands solved together. A chain, a ragdoll or a brick on the ground is an island of
// its own, and solving it alone leaves the processor waiting: each joint of a chain reads the
// velocity the joint before it just wrote, so a sweep along it is one long dependency, and each
// island pays for its own planning and set-up. A bundle is a run of consecutive islands planned
// and solved as one on one thread (island_schedule.h): their joints dealt out in turn, so the
// processor works on several chains at once, and one plan, one set-up and one pass of each
// stage for all of them.
//
// Each island of a bundle is solved to the bits it would be alone: the islands share no body,
// each keeps its own order of constraints, its own NGS sweeps (position_phase.h: an island stops
// when it is solved) and its own sleep test and report. The bundles depend only on the
// islands, never on the number of workers. One thing is shared: when a joint of any island of
// a bundle can break, every joint of the bundle is stored and checked at every substep
// (storeJointImpulses in island_solver.cpp), which lets a joint whose reactions went non-finite
// go a substep earlier than it would alone; that happens only in an island that diverged.
#pragma once

#include <cstdint>
#include <vector>

#include "islands/island_schedule.h"
#include "islands/island_set.h"
#include "solver/island_solver.h"

namespace pivot {

/// Islands [first, first + count) of one IslandSet.
struct IslandRun {
    std::int32_t first;
    std::int32_t count;
};

/// A bundle holds at most this many joints and contacts: enough islands to keep the processor
/// busy, few enough that the bundle's solver arrays stay in the first levels of cache.
constexpr int kMostBundleConstraints = 256;

/// Whether `island` may be bundled with others: one that is solved without a workspace
/// (isLoneBody), whose contacts are coloured (colorsContacts), or that has a mouse joint is
/// solved alone.
inline bool bundles(const IslandView& island) {
    return !isLoneBody(island) && !colorsContacts(island) && island.mouseCount == 0 &&
           island.jointCount + island.contactCount <= kMostBundleConstraints;
}

/// Appends `islands` (indices into `set`, increasing) to `runs`, each run one island or a
/// bundle of consecutive ones.
void bundleIslands(const IslandSet& set, const std::vector<int>& islands,
                   std::vector<IslandRun>& runs);

/// For tests, process-wide: off, every island is solved alone, the reference each island of a
/// bundle must match bit for bit.
void setIslandBundling(bool enabled);
/// Islands solved in bundles of more than one, process-wide, since the program started.
std::uint64_t islandsSolvedInBundles();

}  // namespace pivot
