// A seeded random-operation driver for the public API. It creates, changes, steps and destroys
// bodies, shapes, revolute joints and mouse joints in random order, with random arguments of
// which a share are ones the API must refuse (NaN, inf, huge, negative or zero sizes,
// degenerate polygons, out-of-range enums, stale, null, foreign and made-up ids), and checks:
//   - every call either returns or throws pivot::Error, never anything else;
//   - a call given an argument it must refuse throws (the driver knows which it generated);
//   - a call that throws leaves the world exactly as it was (state hash and object counts);
//   - after every step the invariants visible through the API hold: the id lists match the
//     counts and hold only valid ids, every shape is listed by its body, every joint's bodies
//     are valid, contacts and events name valid shapes, the statistics add up, and every body
//     and joint reports finite numbers;
//   - changes made where the world must refuse them are refused: from a step's task callbacks
//     and other threads, structural ones from query callbacks (reentry.h);
//   - snapshots restore to the same hash and go on alike, leave every id the target issued
//     before stale, and damaged or re-sealed ones are refused or restore a world that steps.
// The same seed gives the same run on every platform and compiler (see random.h).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pivot/pivot.h"
#include "random.h"

namespace pivot::fuzz {

struct Options {
    std::uint64_t seed = 1;
    long operations = 100000;
    /// Print every operation as it is made (for reducing a failure to a reproduction).
    bool trace = false;
    /// Stop at the first failure instead of counting them.
    bool stopAtFirstFailure = true;
    /// Check the invariants after every operation, not only after steps (slower; finds the
    /// operation that broke one).
    bool checkEveryOperation = false;
    /// Print the whole world before this operation (-1: never), to build a reproduction.
    long dumpBefore = -1;
    /// Draw valid values at the edges of their ranges too (kMaxCoordinate, kMaxMagnitude, a
    /// 1 s step, ...), not only typical ones.
    bool extremes = true;
    /// Count a body or joint reporting a non-finite number as a failure. Off, such a world is
    /// counted (Report::nonFiniteWorlds), kept for a while (so the API is exercised on it
    /// too), then replaced.
    bool requireFinite = false;
    /// When set, the calls that built a world are written to PREFIX-SEED-OPERATION.journal when
    /// it fails a check or turns non-finite (replay with pivot-fuzz --replay).
    std::string journalPrefix;
};

struct OperationCount {
    long accepted = 0;
    long rejected = 0;
};

struct Report {
    long operations = 0;
    long accepted = 0;  ///< calls that returned
    long rejected = 0;  ///< calls that threw pivot::Error, each checked to have changed nothing
    long steps = 0;
    long worlds = 0;                    ///< worlds created (the driver starts afresh now and then)
    long snapshots = 0;                 ///< snapshots restored into a second world and compared
    long damagedSnapshotsRefused = 0;   ///< damaged snapshots World::restore refused
    long damagedSnapshotsRestored = 0;  ///< damaged (re-sealed) snapshots it took, then stepped
    /// Changing calls and reads refused from a step's task callbacks and other threads during
    /// a step, and structural calls refused from query callbacks.
    long refusedDuringSteps = 0;
    long refusedInQueries = 0;
    /// Foreign snapshots restored over a world whose earlier ids were checked to stay stale,
    /// and pairs of worlds (one restored) that hashed alike and then went on alike.
    long staleIdsChecked = 0;
    long equalFuturesChecked = 0;
    long maxBodies = 0;
    /// Worlds in which a body or joint came to report a non-finite number, and the operation
    /// at which each was first seen.
    std::vector<long> nonFiniteWorlds;
    /// Joints the worlds reported let go, and body-steps whose non-finite solved state they
    /// discarded (StepStats): blow-ups the engine contained.
    long letGoJoints = 0;
    long discardedBodies = 0;
    long maxContacts = 0;
    std::map<std::string, OperationCount> byOperation;
    std::vector<std::string> failures;  ///< each with the operation number, for --trace
    std::vector<std::string> journals;  ///< journal files written
};

/// Runs the operations and returns what happened; failures are in Report::failures.
Report run(const Options& options);

}  // namespace pivot::fuzz
