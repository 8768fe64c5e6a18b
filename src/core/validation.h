// Checks on public input. Each throws pivot::Error with a message of the form
//   "<call>: <field> <problem> (got <value>)"
// so the caller sees which argument of which call was wrong, and with what value. The limits
// they enforce are in include/pivot/constants.h ("Input limits").
#pragma once

#include <string>

#include "pivot/error.h"
#include "pivot/math.h"

namespace pivot {

/// Shortest text that reads back as the same float (nan and inf spelled out).
std::string formatFloat(float value);
std::string formatVec2(Vec2 value);

[[noreturn]] void fail(const char* call, const std::string& problem);

/// Finite, and 0 or a normal float: denormals (below 1.2e-38 in magnitude) are refused, since
/// arithmetic on them is slow on most CPUs and no physical quantity needs them.
void requireFinite(const char* call, const char* field, float value);
void requireFinite(const char* call, const char* field, Vec2 value);
/// Finite and |value| <= kMaxMagnitude (speeds, forces, angles, ...).
void requireMagnitude(const char* call, const char* field, float value);
void requireMagnitude(const char* call, const char* field, Vec2 value);
/// Finite and every component within [-kMaxCoordinate, kMaxCoordinate] (positions, points).
void requireCoordinate(const char* call, const char* field, Vec2 value);
/// Finite, >= 0 and <= kMaxMagnitude.
void requireNonNegative(const char* call, const char* field, float value);
/// Finite, > 0 and <= kMaxMagnitude.
void requirePositive(const char* call, const char* field, float value);
/// Finite and every component within [-limit, limit]; `limitName` names the constant.
void requireWithin(const char* call, const char* field, float value, float limit,
                   const char* limitName);
void requireWithin(const char* call, const char* field, Vec2 value, float limit,
                   const char* limitName);
/// Finite and within [lo, hi].
void requireInRange(const char* call, const char* field, float value, float lo, float hi);
/// A unit rotation: finite, with |s^2 + c^2 - 1| <= kMaxRotationError.
void requireRotation(const char* call, const char* field, Rot value);
/// A position within kMaxCoordinate (requireCoordinate) and a unit rotation (requireRotation).
void requireTransform(const char* call, const char* field, const Transform& value);
/// 0, or within [kMinDensity, kMaxDensity].
void requireDensity(const char* call, const char* field, float value);

}  // namespace pivot
