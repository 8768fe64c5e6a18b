#include "solver/stepper.h"

#include <algorithm>
#include <atomic>

namespace pivot {

namespace {
// Below this many island bodies in a step, the islands are solved on the calling thread.
constexpr std::size_t kParallelBodies = 512;

std::atomic<Stepper::IslandReuse> islandReuse{Stepper::IslandReuse::Keep};
std::atomic<std::uint64_t> misKept{0};
std::atomic<std::uint64_t> unchangedSteps{0};

bool sameIslands(const IslandSet& x, const IslandSet& y) {
    const auto sameRanges = [](const IslandSet::Range& a, const IslandSet::Range& b) {
        return a.bodyBegin == b.bodyBegin && a.bodyEnd == b.bodyEnd &&
               a.contactBegin == b.contactBegin && a.contactEnd == b.contactEnd &&
               a.jointBegin == b.jointBegin && a.jointEnd == b.jointEnd &&
               a.mouseBegin == b.mouseBegin && a.mouseEnd == b.mouseEnd;
    };
    return x.bodies == y.bodies && x.contacts == y.contacts && x.contactBodies == y.contactBodies &&
           x.joints == y.joints && x.jointBodies == y.jointBodies &&
           x.mouseJoints == y.mouseJoints && x.mouseBodies == y.mouseBodies &&
           std::equal(x.ranges.begin(), x.ranges.end(), y.ranges.begin(), y.ranges.end(),
                      sameRanges);
}

// Each count that grew past the last reservation is reserved for rounded up to a power of two.
BufferBounds withRoom(const BufferBounds& reserved, const BufferBounds& needed) {
    return {pivot::withRoom(reserved.bodies, needed.bodies),
            pivot::withRoom(reserved.joints, needed.joints),
            pivot::withRoom(reserved.contacts, needed.contacts),
            pivot::withRoom(reserved.mouseJoints, needed.mouseJoints)};
}
}  // namespace

void Stepper::reserveStepBuffers(const SolverStorage& storage) {
    const auto count = [](std::int32_t n) { return static_cast<std::size_t>(n); };
    const BufferBounds bound = withRoom(
        reservedFor_, {count(storage.bodies.capacity()), count(storage.joints.capacity()),
                       count(storage.contacts.capacity()), count(storage.mouseJoints.capacity())});
    if (bound == reservedFor_) return;
    reservedFor_ = bound;
    islands_.reserve(bound);
    builder_.reserve(bound);
    reports_.reserve(bound.bodies);
    smallIslands_.reserve(bound.bodies);
    runs_.reserve(bound.bodies);
}

// The solver's arrays hold one island at a time, and no island holds more than all of this
// step's islands together: a workspace reserved for those totals never grows while it solves,
// whatever the islands merge and split into. The totals themselves (awake bodies, touching
// contacts) reach a record now and then, and the reservation then at least doubles.
void Stepper::reserveWorkspaces() {
    BufferBounds& reserved = reservedWorkspaceFor_;
    const BufferBounds bound =
        withRoom(reserved, {islands_.bodies.size(), islands_.joints.size(),
                            islands_.contacts.size(), islands_.mouseJoints.size()});
    if (bound == reserved) return;
    reserved = bound;
    // The first workspace may solve any island. With several workers the others solve only
    // islands too small to be shared by a team: fewer than kColoringThreshold joints and
    // contacts, and (being connected) at most one more body than that besides the static bodies
    // they touch, and as many solver slots again for private copies of those (colorsContacts).
    reserveWorkspace(workspaces_[0], reserved);
    const std::size_t small = kColoringThreshold;
    const BufferBounds smallIsland{
        std::min(reserved.bodies, 2 * small) + std::min(reserved.contacts, small),
        std::min(reserved.joints, small), std::min(reserved.contacts, small), reserved.mouseJoints};
    for (std::size_t w = 1; w < workspaces_.size(); ++w) {
        reserveWorkspace(workspaces_[w], smallIsland);
    }
}

void Stepper::setIslandReuse(IslandReuse reuse) {
    islandReuse = reuse;
}

std::uint64_t Stepper::islandsMisKept() {
    return misKept.load();
}

std::uint64_t Stepper::stepsWithIslandsUnchanged() {
    return unchangedSteps.load();
}

StepTotals Stepper::solve(SolverStorage& storage, const StepContext& context) {
    reserveStepBuffers(storage);
    // Nothing the search reads has changed since it found islands_: they are this step's too.
    const IslandReuse reuse = islandReuse.load(std::memory_order_relaxed);
    const std::uint64_t revision = storage.islandRevision.count();
    const bool keep = searched_ && searchedAt_ == revision;
    if (keep) unchangedSteps.fetch_add(1, std::memory_order_relaxed);
    if (!keep || reuse != IslandReuse::Keep) {
        if (keep && reuse == IslandReuse::Verify) verified_ = islands_;
        builder_.build(storage, islands_);
        if (keep && reuse == IslandReuse::Verify && !sameIslands(verified_, islands_)) ++misKept;
        searched_ = true;
        searchedAt_ = revision;
    }
    // Plans are kept with their islands, under Keep only (the others plan every step).
    const std::uint64_t planRevision =
        reuse == IslandReuse::Keep ? revision : IslandWorkspace::kNeverPlanned;
    reserveWorkspaces();
    const int islandCount = static_cast<int>(islands_.ranges.size());
    resizeBuffer(reports_, static_cast<std::size_t>(islandCount));
    // A coloured island is solved by every worker together, one island at a time; the others
    // are shared out among the workers whole. Sharing out costs a hand-off per step: worth it
    // only with enough bodies to solve.
    const bool teams = pool_.activeWorkers() > 1;
    smallIslands_.clear();
    for (int i = 0; i < islandCount; ++i) {
        if (!teams || !isColored(islands_.view(i))) {
            smallIslands_.push_back(i);
            continue;
        }
        IslandWorkspace& workspace = workspaces_[0];
        planIsland(islands_, i, 1, workspace, storage, context, pool_.activeWorkers(),
                   planRevision);
        pool_.region([&](int member) {
            IslandReport report =
                solveIsland(Team(pool_, member), islands_, i, workspace, storage, context);
            if (member == 0) reports_[i] = report;
        });
    }
    runs_.clear();
    bundleIslands(islands_, smallIslands_, runs_);
    const int runCount = static_cast<int>(runs_.size());
    const int runsPerChunk = islands_.bodies.size() < kParallelBodies ? runCount : 1;
    pool_.parallelFor(runCount, runsPerChunk, [&](int begin, int end, int worker) {
        for (int k = begin; k < end; ++k) {
            const IslandRun run = runs_[static_cast<std::size_t>(k)];
            IslandReport* reports = &reports_[static_cast<std::size_t>(run.first)];
            if (run.count == 1 && isLoneBody(islands_.view(run.first))) {
                *reports = solveLoneBody(islands_, run.first, storage.bodies, context);
            } else {
                solveIslands(islands_, run.first, run.count, workspaces_[worker], storage, context,
                             planRevision, reports);
            }
        }
    });

    StepTotals totals;
    bool changed = false;  // an island fell asleep or let a joint go: the next step searches
    for (int i = 0; i < islandCount; ++i) {
        const IslandReport& report = reports_[i];
        changed = changed || report.fellAsleep || report.letGoJoints > 0;
        const IslandSet::Range& r = islands_.ranges[i];
        ++totals.islands;
        totals.bodies += r.bodyEnd - r.bodyBegin;
        totals.joints += r.jointEnd - r.jointBegin;
        totals.translationClamps += report.translationClamps;
        totals.rotationClamps += report.rotationClamps;
        totals.letGoJoints += report.letGoJoints;
        totals.edgeBodies += report.edgeBodies;
        totals.discardedBodies += report.discardedBodies;
        totals.positionIterations = std::max(totals.positionIterations, report.positionIterations);
        totals.extraPositionSolves += report.extraPositionSolves;
    }
    if (changed) storage.islandRevision.bump();
    return totals;
}

}  // namespace pivot
