// The settings of one World::step that every island and constraint reads.
#pragma once

#include "pivot/math.h"
#include "pivot/solvers.h"

namespace pivot {

/// Settings of one World::step, shared by every island.
struct StepContext {
    // The length of one substep, h = step / substepCount (the step's with one substep): what
    // every constraint is built for, and what its impulses are per.
    float dt = 0.0f;
    float invDt = 0.0f;
    float dtRatio = 0.0f;  // min(h / previous h, 1), scales warm-start impulses
    int substepCount = 1;
    float stepDt = 0.0f;  // the whole step, s (sleep timers)
    Vec2 gravity;
    int velocityIterations = 0;
    int positionIterations = 0;
    bool warmStarting = true;
    bool enableSleep = true;
    ContactCorrection contactCorrection = ContactCorrection::NGS;
    float contactBiasFactor = 0.0f;
    float contactHertz = 0.0f;  // ContactCorrection::Soft's
    float contactDampingRatio = 0.0f;
    float contactPushSpeed = 0.0f;
    float restitutionThreshold = 0.0f;
    float jointLetGoSeparation = 0.0f;  // WorldDef's; 0: never
};

}  // namespace pivot
