#include "world/world_settings.h"

#include "core/validation.h"
#include "world/world_checks.h"

namespace pivot {

WorldSettings WorldSettings::of(const WorldDef& def) {
    WorldSettings s;
    s.gravity = def.gravity;
    s.defaultPositionSolver = def.defaultPositionSolver;
    s.warmStarting = def.warmStarting;
    s.contactCorrection = def.contactCorrection;
    s.contactBiasFactor = def.contactBiasFactor;
    s.contactHertz = def.contactHertz;
    s.contactDampingRatio = def.contactDampingRatio;
    s.contactPushSpeed = def.contactPushSpeed;
    s.restitutionThreshold = def.restitutionThreshold;
    s.enableSleep = def.enableSleep;
    s.enableContinuous = def.enableContinuous;
    s.continuousCollision = def.continuousCollision;
    s.jointLetGoSeparation = def.jointLetGoSeparation;
    s.substepCount = def.substepCount;
    s.velocityIterations = def.velocityIterations;
    s.positionIterations = def.positionIterations;
    s.hitEventThreshold = def.hitEventThreshold;
    return s;
}

void checkGravity(const char* call, const std::string& field, Vec2 value) {
    requireWithin(call, field.c_str(), value, kMaxGravity, "kMaxGravity");
}

void checkDefaultPositionSolver(const char* call, const std::string& field, PositionSolver value) {
    checkSolver(call, field.c_str(), value);
}

void checkContactCorrection(const char* call, const std::string& field, ContactCorrection value) {
    const int raw = static_cast<int>(value);
    if (raw < 0 || raw > static_cast<int>(ContactCorrection::Soft)) {
        fail(call, field + " is not a ContactCorrection (got " + std::to_string(raw) + ")");
    }
}

void checkContactBiasFactor(const char* call, const std::string& field, float value) {
    requireInRange(call, field.c_str(), value, 0.0f, 1.0f);
}

void checkContactHertz(const char* call, const std::string& field, float value) {
    requirePositive(call, field.c_str(), value);
}

void checkContactDampingRatio(const char* call, const std::string& field, float value) {
    requireNonNegative(call, field.c_str(), value);
}

void checkContactPushSpeed(const char* call, const std::string& field, float value) {
    requirePositive(call, field.c_str(), value);
}

void checkRestitutionThreshold(const char* call, const std::string& field, float value) {
    requireNonNegative(call, field.c_str(), value);
}

void checkContinuousCollision(const char* call, const std::string& field,
                              ContinuousCollision value) {
    const int raw = static_cast<int>(value);
    if (raw < 0 || raw > static_cast<int>(ContinuousCollision::FastBodies)) {
        fail(call, field + " is not a ContinuousCollision (got " + std::to_string(raw) + ")");
    }
}

void checkJointLetGoSeparation(const char* call, const std::string& field, float value) {
    requireNonNegative(call, field.c_str(), value);
}

void checkSubstepCount(const char* call, const std::string& field, int value) {
    if (value < 1 || value > kMaxSubsteps) {
        fail(call, field + " must be in [1, kMaxSubsteps = " + std::to_string(kMaxSubsteps) +
                       "] (got " + std::to_string(value) + ")");
    }
}

void checkIterations(const char* call, const std::string& field, int value) {
    if (value < 0 || value > kMaxIterations) {
        fail(call, field + " must be in [0, kMaxIterations = " + std::to_string(kMaxIterations) +
                       "] (got " + std::to_string(value) + ")");
    }
}

void checkHitEventThreshold(const char* call, const std::string& field, float value) {
    requireInRange(call, field.c_str(), value, 0.0f, kMaxSpeed);
}

void checkSettings(const char* call, const std::string& prefix, const WorldSettings& s) {
    checkGravity(call, prefix + "gravity", s.gravity);
    checkDefaultPositionSolver(call, prefix + "defaultPositionSolver", s.defaultPositionSolver);
    checkContactCorrection(call, prefix + "contactCorrection", s.contactCorrection);
    checkContactBiasFactor(call, prefix + "contactBiasFactor", s.contactBiasFactor);
    checkContactHertz(call, prefix + "contactHertz", s.contactHertz);
    checkContactDampingRatio(call, prefix + "contactDampingRatio", s.contactDampingRatio);
    checkContactPushSpeed(call, prefix + "contactPushSpeed", s.contactPushSpeed);
    checkRestitutionThreshold(call, prefix + "restitutionThreshold", s.restitutionThreshold);
    checkContinuousCollision(call, prefix + "continuousCollision", s.continuousCollision);
    checkJointLetGoSeparation(call, prefix + "jointLetGoSeparation", s.jointLetGoSeparation);
    checkSubstepCount(call, prefix + "substepCount", s.substepCount);
    checkIterations(call, prefix + "velocityIterations", s.velocityIterations);
    checkIterations(call, prefix + "positionIterations", s.positionIterations);
    checkHitEventThreshold(call, prefix + "hitEventThreshold", s.hitEventThreshold);
}

}  // namespace pivot
