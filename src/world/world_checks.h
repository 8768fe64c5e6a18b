// Checks shared by the World facade's files.
#pragma once

#include <cmath>
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

inline void checkBroadPhaseBoxes(const char* call, const char* field, BroadPhaseBoxes boxes) {
    int value = static_cast<int>(boxes);
    if (value < 0 || value > static_cast<int>(BroadPhaseBoxes::Compact)) {
        fail(call,
             std::string(field) + " is not a BroadPhaseBoxes (got " + std::to_string(value) + ")");
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

inline void checkRestLength(const char* call, const char* field, float length) {
    requireFinite(call, field, length);
    if (!(length >= kLinearSlop && length <= kMaxCoordinate)) {
        fail(call, std::string(field) + " must be in [kLinearSlop, kMaxCoordinate] (" +
                       formatFloat(kLinearSlop) + " to " + formatFloat(kMaxCoordinate) +
                       " m) (got " + formatFloat(length) + ")");
    }
}

/// A gear ratio: |ratio| in [kMinGearRatio, 1 / kMinGearRatio].
inline void checkGearRatio(const char* call, const char* field, float ratio) {
    const float size = std::fabs(ratio);
    if (!(size >= kMinGearRatio && size <= 1.0f / kMinGearRatio)) {
        fail(call, std::string(field) +
                       " must be in [kMinGearRatio, 1 / kMinGearRatio] or that range negated (" +
                       formatFloat(kMinGearRatio) + " to " + formatFloat(1.0f / kMinGearRatio) +
                       "), got " + formatFloat(ratio));
    }
}

inline void checkPulleyLength(const char* call, const char* field, float length) {
    requireFinite(call, field, length);
    if (!(length >= kMinPulleyLength && length <= kMaxCoordinate)) {
        fail(call, std::string(field) + " must be in [kMinPulleyLength, kMaxCoordinate] (" +
                       formatFloat(kMinPulleyLength) + " to " + formatFloat(kMaxCoordinate) +
                       " m) (got " + formatFloat(length) + ")");
    }
}

inline void checkLengthLimit(const char* call, const std::string& field, const LengthLimit& limit) {
    requireInRange(call, (field + ".min").c_str(), limit.min, 0.0f, kMaxCoordinate);
    requireInRange(call, (field + ".max").c_str(), limit.max, 0.0f, kMaxCoordinate);
    if (limit.min > limit.max) {
        fail(call, field + ".min must be <= " + field + ".max (got " + formatFloat(limit.min) +
                       " > " + formatFloat(limit.max) + ")");
    }
}

inline void checkSpring(const char* call, const std::string& field, const JointSpring& spring) {
    requireNonNegative(call, (field + ".hertz").c_str(), spring.hertz);
    requireNonNegative(call, (field + ".dampingRatio").c_str(), spring.dampingRatio);
    if (spring.enabled && spring.hertz <= 0.0f) {
        fail(call, field + ".hertz must be > 0 when the spring is enabled (got " +
                       formatFloat(spring.hertz) + ")");
    }
}

inline void checkTranslationLimit(const char* call, const std::string& field,
                                  const TranslationLimit& limit) {
    requireInRange(call, (field + ".lower").c_str(), limit.lower, -kMaxCoordinate, kMaxCoordinate);
    requireInRange(call, (field + ".upper").c_str(), limit.upper, -kMaxCoordinate, kMaxCoordinate);
    if (limit.lower > limit.upper) {
        fail(call, field + ".lower must be <= " + field + ".upper (got " +
                       formatFloat(limit.lower) + " > " + formatFloat(limit.upper) + ")");
    }
}

inline void checkLinearMotor(const char* call, const std::string& field, const LinearMotor& motor) {
    requireWithin(call, (field + ".speed").c_str(), motor.speed, kMaxSpeed, "kMaxSpeed");
    requireNonNegative(call, (field + ".maxForce").c_str(), motor.maxForce);
}

/// An axis of any length the solver can normalise: finite, within kMaxMagnitude, and longer
/// than kLinearSlop (a shorter one has no reliable direction).
inline Vec2 checkedUnitAxis(const char* call, const char* field, Vec2 axis) {
    requireMagnitude(call, field, axis);
    const float len = length(axis);
    if (!(len > kLinearSlop)) {
        fail(call, std::string(field) + " must be longer than kLinearSlop (" +
                       formatFloat(kLinearSlop) + ") to give a direction (got " + formatVec2(axis) +
                       ")");
    }
    const float inv = 1.0f / len;  // normalised as Box2D's b2Vec2::Normalize does
    return {inv * axis.x, inv * axis.y};
}

inline void checkExtraPositionIterations(const char* call, const char* field, int count) {
    if (count < 0 || count > kMaxIterations) {
        fail(call, std::string(field) + " must be in [0, kMaxIterations = " +
                       std::to_string(kMaxIterations) + "] (got " + std::to_string(count) + ")");
    }
}

inline void checkBiasFactor(const char* call, const char* field, float bias) {
    requireInRange(call, field, bias, 0.0f, 1.0f);
}

inline void checkSoftness(const char* call, const char* field, const JointSoftness& softness) {
    const std::string name(field);
    requirePositive(call, (name + ".hertz").c_str(), softness.hertz);
    requireNonNegative(call, (name + ".dampingRatio").c_str(), softness.dampingRatio);
    requireNonNegative(call, (name + ".compliance").c_str(), softness.compliance);
}

}  // namespace pivot
