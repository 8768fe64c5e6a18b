#include "solver/island_bundles.h"

#include <atomic>

namespace pivot {

namespace {
std::atomic<bool> bundling{true};
std::atomic<std::uint64_t> bundledIslands{0};
}  // namespace

void setIslandBundling(bool enabled) {
    bundling = enabled;
}

std::uint64_t islandsSolvedInBundles() {
    return bundledIslands.load();
}

void bundleIslands(const IslandSet& set, const std::vector<int>& islands,
                   std::vector<IslandRun>& runs) {
    const bool on = bundling.load(std::memory_order_relaxed);
    const auto constraints = [&](int i) {
        const IslandSet::Range& r = set.ranges[static_cast<std::size_t>(i)];
        return (r.jointEnd - r.jointBegin) + (r.contactEnd - r.contactBegin);
    };
    std::uint64_t bundled = 0;
    const std::size_t count = islands.size();
    for (std::size_t k = 0; k < count;) {
        const int first = islands[k];
        IslandRun run{first, 1};
        ++k;
        if (on && bundles(set.view(first))) {
            int total = constraints(first);
            while (k < count && run.count < kMostBundleMembers && islands[k] == first + run.count &&
                   bundles(set.view(islands[k])) &&
                   total + constraints(islands[k]) <= kMostBundleConstraints) {
                total += constraints(islands[k]);
                ++run.count;
                ++k;
            }
        }
        if (run.count > 1) bundled += static_cast<std::uint64_t>(run.count);
        runs.push_back(run);
    }
    if (bundled > 0) bundledIslands.fetch_add(bundled, std::memory_order_relaxed);
}

}  // namespace pivot
