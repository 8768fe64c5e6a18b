// The world-wide settings (WorldDef's numbers, flags and policies, minus what is fixed at
// creation: workers, task system, broad-phase boxes) and the one rule each must keep. The rule
// of a setting is used wherever a value of it comes in: WorldDef, its setter, and a snapshot
// being restored, so that every value the world reports is one its setter would take.
#pragma once

#include <string>

#include "pivot/world.h"

namespace pivot {

struct WorldSettings {
    Vec2 gravity;
    PositionSolver defaultPositionSolver = PositionSolver::FullNGS;
    bool warmStarting = true;
    ContactCorrection contactCorrection = ContactCorrection::NGS;
    float contactBiasFactor = kDefaultContactBias;
    float contactHertz = kDefaultContactHertz;  // ContactCorrection::Soft's spring
    float contactDampingRatio = kDefaultContactDampingRatio;
    float contactPushSpeed = kDefaultContactPushSpeed;
    float restitutionThreshold = kRestitutionThreshold;
    bool enableSleep = true;
    bool enableContinuous = true;
    ContinuousCollision continuousCollision = ContinuousCollision::Substeps;
    float jointLetGoSeparation = 0.0f;                    // m; 0: never
    int substepCount = kDefaultSubstepCount;              // [1, kMaxSubsteps]
    int velocityIterations = kDefaultVelocityIterations;  // [0, kMaxIterations], per substep
    int positionIterations = kDefaultPositionIterations;
    float hitEventThreshold = kDefaultHitEventThreshold;  // m/s

    /// The settings a WorldDef asks for (unchecked: checkSettings).
    static WorldSettings of(const WorldDef& def);
};

// Each setting's rule: pivot::Error naming `call` and `field` when `value` breaks it. Settings
// not listed (warmStarting, enableSleep, enableContinuous) take any value of their type.
void checkGravity(const char* call, const std::string& field, Vec2 value);
void checkDefaultPositionSolver(const char* call, const std::string& field, PositionSolver value);
void checkContactCorrection(const char* call, const std::string& field, ContactCorrection value);
void checkContactBiasFactor(const char* call, const std::string& field, float value);
void checkContactHertz(const char* call, const std::string& field, float value);
void checkContactDampingRatio(const char* call, const std::string& field, float value);
void checkContactPushSpeed(const char* call, const std::string& field, float value);
void checkRestitutionThreshold(const char* call, const std::string& field, float value);
void checkContinuousCollision(const char* call, const std::string& field,
                              ContinuousCollision value);
void checkJointLetGoSeparation(const char* call, const std::string& field, float value);
void checkSubstepCount(const char* call, const std::string& field, int value);
void checkIterations(const char* call, const std::string& field, int value);
void checkHitEventThreshold(const char* call, const std::string& field, float value);

/// Every setting by its rule, each field named `prefix` + its WorldDef name ("def.gravity").
void checkSettings(const char* call, const std::string& prefix, const WorldSettings& settings);

}  // namespace pivot
