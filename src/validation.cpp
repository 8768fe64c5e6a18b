#include "validation.h"

#include <cmath>
#include <cstdio>

namespace pivot {

std::string formatFloat(float value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(value));
    return buffer;
}

std::string formatVec2(Vec2 value) {
    return "(" + formatFloat(value.x) + ", " + formatFloat(value.y) + ")";
}

void fail(const char* call, const std::string& problem) {
    throw Error(std::string(call) + ": " + problem);
}

void requireFinite(const char* call, const char* field, float value) {
    if (!std::isfinite(value)) {
        fail(call, std::string(field) + " must be finite (got " + formatFloat(value) + ")");
    }
}

void requireFinite(const char* call, const char* field, Vec2 value) {
    if (!isFinite(value)) {
        fail(call, std::string(field) + " must be finite (got " + formatVec2(value) + ")");
    }
}

void requireNonNegative(const char* call, const char* field, float value) {
    requireFinite(call, field, value);
    if (value < 0.0f) {
        fail(call, std::string(field) + " must be >= 0 (got " + formatFloat(value) + ")");
    }
}

void requireInRange(const char* call, const char* field, float value, float lo, float hi) {
    requireFinite(call, field, value);
    if (value < lo || value > hi) {
        fail(call, std::string(field) + " must be in [" + formatFloat(lo) + ", " + formatFloat(hi) +
                       "] (got " + formatFloat(value) + ")");
    }
}

}  // namespace pivot
