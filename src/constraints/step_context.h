// The settings of one World::step that every island and constraint reads.
#pragma once

#include "pivot/math.h"
#include "pivot/solvers.h"

namespace pivot {

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
