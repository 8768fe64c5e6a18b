// The arrays the island solver works on. Constraints never touch Body objects while solving:
// they read and write these, by solver index, so each stage is a tight loop over contiguous
// memory (and, later, can be split across threads by graph colour).
#pragma once

#include "pivot/math.h"
#include "pivot/world.h"

namespace pivot {

struct SolverVelocity {
    Vec2 v;
    float w = 0.0f;
};

struct SolverPosition {
    Vec2 c;  // centre of mass
    float a = 0.0f;
};

/// Settings of one World::step, shared by every island.
struct StepContext {
    float dt = 0.0f;
    float invDt = 0.0f;
    float dtRatio = 0.0f;  // min(dt / previous dt, 1), scales warm-start impulses
    Vec2 gravity;
    int velocityIterations = 0;
    int positionIterations = 0;
    bool warmStarting = true;
    bool enableSleep = true;
    ContactCorrection contactCorrection = ContactCorrection::NGS;
    float contactBiasFactor = 0.0f;
    float restitutionThreshold = 0.0f;
    float jointLetGoSeparation = 0.0f;  // WorldDef's; 0: never
};

}  // namespace pivot
