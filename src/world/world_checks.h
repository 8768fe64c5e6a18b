// Checks shared by the World facade's files.
#pragma once

#include <string>

#include "core/validation.h"
#include "model/body.h"
#include "pivot/joint.h"
#include "pivot/world.h"

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
    requireWithin(call, (field + ".speed").c_str(), motor.speed, kMaxAngularSpeed,
                  "kMaxAngularSpeed");
    requireNonNegative(call, (field + ".maxTorque").c_str(), motor.maxTorque);
}

/// A call that changes a body's mass moves its centre of mass, and the centre's velocity moves
/// with it (w x the shift): a body spinning with a shape 1e5 m out can end past kMaxSpeed. Such
/// a call is refused, so that the body's velocity stays one the API accepts.
inline void requireMotionAfterMassChange(const char* call, const Body& after, const Body& before) {
    const Vec2 v = after.linearVelocity;
    if (!(std::fabs(v.x) <= kMaxSpeed && std::fabs(v.y) <= kMaxSpeed)) {
        fail(call, "this call would move the body's centre of mass by " +
                       formatVec2(after.center - before.center) +
                       " m, which at its angular velocity of " +
                       formatFloat(before.angularVelocity) +
                       " rad/s would give the centre a velocity of " + formatVec2(v) +
                       " m/s, beyond +-kMaxSpeed (" + formatFloat(kMaxSpeed) +
                       "); slow its rotation first");
    }
}

inline void checkBiasFactor(const char* call, const char* field, float bias) {
    requireInRange(call, field, bias, 0.0f, 1.0f);
}

}  // namespace pivot
