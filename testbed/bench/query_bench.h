// The query rows of pivot-bench: ray casts (closest hit) and box queries in a world of 10^4 mixed
// shapes, the same shapes, rays and boxes in pivot2d and in Box2D 2.4.1 (b2World::RayCast and
// QueryAABB), timed in the same run.
#pragma once

#include <string>
#include <vector>

namespace pivot::bench {

struct QueryRow {
    std::string name;      ///< ray_casts or aabb_queries
    double pivotMs = 0.0;  ///< median ms for the whole batch of queries
    double box2dMs = 0.0;
    long long pivotFound = 0;  ///< hits (rays) or shapes reported (boxes): a check on the work
    long long box2dFound = 0;
    long long pivotAllocations = 0;  ///< operator new calls during pivot2d's timed batches
};

/// 10^4 ray casts and 10^4 box queries per batch (a tenth of each with quick), `repeats` batches
/// per engine, alternating; medians.
std::vector<QueryRow> runQueryBench(bool quick, int repeats);

}  // namespace pivot::bench
