// The memory rows of pivot-bench: heap bytes per body, shape, joint and contact in each engine,
// from worlds built to size through the same Builder calls. Counted by glibc's allocator
// statistics (mallinfo2), so every engine's allocations count alike: pivot2d's operator new,
// Box2D 2.4.1's b2Alloc and Box2D v3's b2_alloc all end in malloc.
#pragma once

#include <string>
#include <vector>

#include "bench/engines/engine.h"

namespace pivot::bench {

struct MemoryRow {
    std::string engine;
    double perBody = 0.0;     ///< a dynamic body without shapes
    double perShape = 0.0;    ///< a circle on such a body, with its broad-phase proxy
    double perJoint = 0.0;    ///< a revolute joint
    double perContact = 0.0;  ///< growth over a pyramid's first steps / its contacts
    int contacts = 0;
};

/// One row per engine kind (on one thread); pivot2d's set-ups build the same world, so only the
/// first of them is measured.
std::vector<MemoryRow> measureMemory(const std::vector<EngineKind>& kinds);

void printMemory(const std::vector<MemoryRow>& rows);

}  // namespace pivot::bench
