// Checks shared by the World facade's files.
#pragma once

#include <string>

#include "pivot/joint.h"
#include "pivot/world.h"
#include "validation.h"

namespace pivot {

inline void checkSolver(const char* call, const char* field, PositionSolver solver) {
    int value = static_cast<int>(solver);
    if (value < 0 || value >= kPositionSolverCount) {
        fail(call,
             std::string(field) + " is not a PositionSolver (got " + std::to_string(value) + ")");
    }
}

inline void checkBodyType(const char* call, const char* field, BodyType type) {
    int value = static_cast<int>(type);
    if (value < 0 || value > static_cast<int>(BodyType::Dynamic)) {
        fail(call, std::string(field) + " is not a BodyType (got " + std::to_string(value) + ")");
    }
}

inline void checkContactCorrection(const char* call, const char* field,
                                   ContactCorrection correction) {
    int value = static_cast<int>(correction);
    if (value < 0 || value > static_cast<int>(ContactCorrection::NGS)) {
        fail(call, std::string(field) + " is not a ContactCorrection (got " +
                       std::to_string(value) + ")");
    }
}

inline void checkLimit(const char* call, const std::string& field, const JointLimit& limit) {
    requireMagnitude(call, (field + ".lower").c_str(), limit.lower);
    requireMagnitude(call, (field + ".upper").c_str(), limit.upper);
    if (limit.lower > limit.upper) {
        fail(call, field + ".lower must be <= " + field + ".upper (got " +
                       formatFloat(limit.lower) + " > " + formatFloat(limit.upper) + ")");
    }
}

inline void checkMotor(const char* call, const std::string& field, const JointMotor& motor) {
    requireMagnitude(call, (field + ".speed").c_str(), motor.speed);
    requireNonNegative(call, (field + ".maxTorque").c_str(), motor.maxTorque);
}

inline void checkBiasFactor(const char* call, const char* field, float bias) {
    requireInRange(call, field, bias, 0.0f, 1.0f);
}

}  // namespace pivot
