#include "bench/memory.h"

#include <malloc.h>

#include <cstdio>

#include "bench/suite/suite.h"

namespace pivot::bench {

namespace {

// Bytes held by the program's live allocations: small blocks in the arenas and large ones that
// malloc maps on their own.
long long heapBytes() {
    const struct mallinfo2 info = mallinfo2();
    return static_cast<long long>(info.uordblks + info.hblkhd);
}

MemoryRow measure(const EngineKind& kind) {
    constexpr int kSide = 100, kCount = kSide * kSide;
    MemoryRow row;
    row.engine = kind.isPivot ? "pivot2d" : kind.name;
    WorldSettings settings;
    {
        std::unique_ptr<Engine> engine = kind.make(settings);
        const long long start = heapBytes();
        for (int i = 0; i < kCount; ++i) {
            BodySpec body;
            body.position = {static_cast<float>(i % kSide), static_cast<float>(i / kSide)};
            engine->body(body);
        }
        const long long withBodies = heapBytes();
        for (int i = 0; i < kCount; ++i) engine->circle(i, {}, 0.25f, Material{});
        const long long withShapes = heapBytes();
        for (int i = 1; i < kCount; ++i) {
            PinSpec pin;
            pin.bodyA = i - 1;
            pin.bodyB = i;
            pin.pivot = {static_cast<float>(i % kSide) - 0.5f, static_cast<float>(i / kSide)};
            engine->pin(pin);
        }
        const long long withJoints = heapBytes();
        row.perBody = static_cast<double>(withBodies - start) / kCount;
        row.perShape = static_cast<double>(withShapes - withBodies) / kCount;
        row.perJoint = static_cast<double>(withJoints - withShapes) / (kCount - 1);
    }
    // Contacts: the 40-row pyramid over its first two steps, which also size the solver's
    // reusable buffers (counted here too).
    for (const SuiteScene& scene : suiteScenes()) {
        if (scene.name != "pyramid_40") continue;
        std::unique_ptr<Engine> engine = kind.make(settings);
        scene.build(*engine);
        const long long before = heapBytes();
        engine->step();
        engine->step();
        row.contacts = engine->contactCount();
        row.perContact =
            row.contacts > 0 ? static_cast<double>(heapBytes() - before) / row.contacts : 0.0;
    }
    return row;
}

}  // namespace

std::vector<MemoryRow> measureMemory(const std::vector<EngineKind>& kinds) {
    std::vector<MemoryRow> rows;
    bool pivotDone = false;
    for (const EngineKind& kind : kinds) {
        if (kind.isPivot && pivotDone) continue;
        pivotDone |= kind.isPivot;
        rows.push_back(measure(kind));
    }
    return rows;
}

void printMemory(const std::vector<MemoryRow>& rows) {
    std::printf(
        "\nheap bytes (glibc's count of live allocations): per dynamic body, per circle shape "
        "on it,\nper revolute joint, and per contact over the first two steps of pyramid_40 "
        "(the solver's\nreusable buffers included):\n");
    std::printf("%-12s %9s %9s %9s %9s %9s\n", "engine", "body", "shape", "joint", "contact",
                "contacts");
    for (const MemoryRow& row : rows) {
        std::printf("%-12s %9.0f %9.0f %9.0f %9.0f %9d\n", row.engine.c_str(), row.perBody,
                    row.perShape, row.perJoint, row.perContact, row.contacts);
    }
}

}  // namespace pivot::bench
