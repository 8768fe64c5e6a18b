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
    std::uint64_t bundled = 0;
    int total = 0;  // the open run's joints and contacts; runs.back() is open while bundleable
    bool open = false;
    for (const int island : islands) {
        const IslandView view = set.view(island);
        const int constraints = view.jointCount + view.contactCount;
        const bool joins = on && bundles(view);
        if (open && joins && runs.back().count < kMostBundleMembers &&
            island == runs.back().first + runs.back().count &&
            total + constraints <= kMostBundleConstraints) {
            ++runs.back().count;
            total += constraints;
            continue;
        }
        if (open && runs.back().count > 1) bundled += static_cast<std::uint64_t>(runs.back().count);
        runs.push_back({island, 1});
        open = joins;
        total = constraints;
    }
    if (open && runs.back().count > 1) bundled += static_cast<std::uint64_t>(runs.back().count);
    if (bundled > 0) bundledIslands.fetch_add(bundled, std::memory_order_relaxed);
}

}  // namespace pivot
