#include "core/validation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "pivot/constants.h"

namespace pivot {

std::string formatFloat(float value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    // Nine significant digits always read back exactly; fewer usually do, and are what the
    // caller typed (0.005 rather than 0.00499999989).
    char buffer[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(value));
        if (std::strtof(buffer, nullptr) == value) break;
    }
    return buffer;
}

std::string formatVec2(Vec2 value) {
    return "(" + formatFloat(value.x) + ", " + formatFloat(value.y) + ")";
}

void fail(const char* call, const std::string& problem) {
    throw Error(std::string(call) + ": " + problem);
}

namespace {
bool isDenormal(float value) {
    return std::fpclassify(value) == FP_SUBNORMAL;
}
}  // namespace

void requireFinite(const char* call, const char* field, float value) {
    if (!std::isfinite(value)) {
        fail(call, std::string(field) + " must be finite (got " + formatFloat(value) + ")");
    }
    if (isDenormal(value)) {
        fail(call, std::string(field) + " must be 0 or a normal float, not a denormal (got " +
                       formatFloat(value) + ")");
    }
}

void requireFinite(const char* call, const char* field, Vec2 value) {
    if (!isFinite(value)) {
        fail(call, std::string(field) + " must be finite (got " + formatVec2(value) + ")");
    }
    if (isDenormal(value.x) || isDenormal(value.y)) {
        fail(call, std::string(field) + " must be 0 or a normal float, not a denormal (got " +
                       formatVec2(value) + ")");
    }
}

void requireMagnitude(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (std::fabs(value) > kMaxMagnitude) {
        fail(call, std::string(field) + " must be within +-kMaxMagnitude (" +
                       formatFloat(kMaxMagnitude) + ") (got " + formatFloat(value) + ")");
    }
}

void requireMagnitude(const char* call, const char* field, Vec2 value) {
    requireFinite(call, field, value);
    if (std::fabs(value.x) > kMaxMagnitude || std::fabs(value.y) > kMaxMagnitude) {
        fail(call, std::string(field) + " must be within +-kMaxMagnitude (" +
                       formatFloat(kMaxMagnitude) + ") (got " + formatVec2(value) + ")");
    }
}

void requireWithin(const char* call, const char* field, float value, float limit,
                   const char* limitName) {
    requireFinite(call, field, value);
    if (std::fabs(value) > limit) {
        fail(call, std::string(field) + " must be within +-" + limitName + " (" +
                       formatFloat(limit) + ") (got " + formatFloat(value) + ")");
    }
}

void requireWithin(const char* call, const char* field, Vec2 value, float limit,
                   const char* limitName) {
    requireFinite(call, field, value);
    if (std::fabs(value.x) > limit || std::fabs(value.y) > limit) {
        fail(call, std::string(field) + " must be within +-" + limitName + " (" +
                       formatFloat(limit) + ") (got " + formatVec2(value) + ")");
    }
}

void requireCoordinate(const char* call, const char* field, Vec2 value) {
    requireFinite(call, field, value);
    if (std::fabs(value.x) > kMaxCoordinate || std::fabs(value.y) > kMaxCoordinate) {
        fail(call, std::string(field) + " must be within +-kMaxCoordinate (" +
                       formatFloat(kMaxCoordinate) + " m) (got " + formatVec2(value) + ")");
    }
}

void requireNonNegative(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (value < 0.0f) {
        fail(call, std::string(field) + " must be >= 0 (got " + formatFloat(value) + ")");
    }
    requireMagnitude(call, field, value);
}

void requirePositive(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (value <= 0.0f) {
        fail(call, std::string(field) + " must be > 0 (got " + formatFloat(value) + ")");
    }
    requireMagnitude(call, field, value);
}

void requireInRange(const char* call, const char* field, float value, float lo, float hi) {
    requireFinite(call, field, value);
    if (value < lo || value > hi) {
        fail(call, std::string(field) + " must be in [" + formatFloat(lo) + ", " + formatFloat(hi) +
                       "] (got " + formatFloat(value) + ")");
    }
}

void requireRotation(const char* call, const char* field, Rot value) {
    const std::string name(field);
    requireFinite(call, (name + ".s").c_str(), value.s);
    requireFinite(call, (name + ".c").c_str(), value.c);
    // In double: s and c up to 3.4e38 square beyond float range.
    const double error = double(value.s) * value.s + double(value.c) * value.c - 1.0;
    if (!(std::fabs(error) <= kMaxRotationError)) {
        fail(call, name + " must be a unit rotation, s^2 + c^2 within kMaxRotationError (" +
                       formatFloat(kMaxRotationError) + ") of 1: build it with Rot(angle) (got s " +
                       formatFloat(value.s) + ", c " + formatFloat(value.c) + ")");
    }
}

void requireTransform(const char* call, const char* field, const Transform& value) {
    const std::string name(field);
    requireCoordinate(call, (name + ".p").c_str(), value.p);
    requireRotation(call, (name + ".q").c_str(), value.q);
}

void requireDensity(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (value < 0.0f) {
        fail(call, std::string(field) + " must be >= 0 (got " + formatFloat(value) + ")");
    }
    if (value != 0.0f && (value < kMinDensity || value > kMaxDensity)) {
        fail(call, std::string(field) + " must be 0 or in [kMinDensity, kMaxDensity] = [" +
                       formatFloat(kMinDensity) + ", " + formatFloat(kMaxDensity) +
                       "] kg/m^2 (got " + formatFloat(value) + ")");
    }
}

}  // namespace pivot
