// 2D vector maths used by the public API and the solver: Vec2, Rot, Transform, Mat22.
// Everything is inline and single precision, like the engines pivot2d is compared with,
// so that the same sequence of float operations gives the same bits.
#pragma once

#include <cmath>

namespace pivot {

struct Vec2 {
    float x = 0.0f;
    float y = 0.0f;

    constexpr Vec2() = default;
    constexpr Vec2(float xIn, float yIn) : x(xIn), y(yIn) {}

    constexpr Vec2 operator-() const { return {-x, -y}; }
    constexpr Vec2& operator+=(Vec2 v) {
        x += v.x;
        y += v.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 v) {
        x -= v.x;
        y -= v.y;
        return *this;
    }
    constexpr Vec2& operator*=(float s) {
        x *= s;
        y *= s;
        return *this;
    }
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator*(float s, Vec2 v) {
    return {s * v.x, s * v.y};
}
constexpr Vec2 operator*(Vec2 v, float s) {
    return {s * v.x, s * v.y};
}
constexpr bool operator==(Vec2 a, Vec2 b) {
    return a.x == b.x && a.y == b.y;
}
constexpr bool operator!=(Vec2 a, Vec2 b) {
    return !(a == b);
}

constexpr float dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
/// The z component of the 3D cross product of two vectors in the plane.
constexpr float cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
/// w x v for an angular velocity w (about z) and a vector v: the velocity of point v.
constexpr Vec2 cross(float w, Vec2 v) {
    return {-w * v.y, w * v.x};
}
/// v x w: the negative of cross(w, v).
constexpr Vec2 cross(Vec2 v, float w) {
    return {w * v.y, -w * v.x};
}
/// The vector turned a quarter turn counter-clockwise.
constexpr Vec2 leftPerp(Vec2 v) {
    return {-v.y, v.x};
}
constexpr float lengthSquared(Vec2 v) {
    return dot(v, v);
}
inline float length(Vec2 v) {
    return std::sqrt(dot(v, v));
}
inline float distance(Vec2 a, Vec2 b) {
    return length(b - a);
}
inline bool isFinite(float f) {
    return std::isfinite(f);
}
inline bool isFinite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// A rotation stored as its sine and cosine.
struct Rot {
    float s = 0.0f;
    float c = 1.0f;

    constexpr Rot() = default;
    explicit Rot(float angle) : s(std::sin(angle)), c(std::cos(angle)) {}

    float angle() const { return std::atan2(s, c); }
};

/// Rotate v by q.
constexpr Vec2 rotate(Rot q, Vec2 v) {
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
/// Rotate v by the inverse of q.
constexpr Vec2 inverseRotate(Rot q, Vec2 v) {
    return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}

/// A rigid frame: rotation then translation.
struct Transform {
    Vec2 p;
    Rot q;
};

constexpr Vec2 transformPoint(const Transform& t, Vec2 v) {
    return rotate(t.q, v) + t.p;
}
constexpr Vec2 inverseTransformPoint(const Transform& t, Vec2 v) {
    return inverseRotate(t.q, v - t.p);
}

/// A 2x2 matrix stored by columns.
struct Mat22 {
    Vec2 cx;
    Vec2 cy;

    /// Solve A x = b by Cramer's rule; a singular matrix gives x = 0, which to a constraint
    /// means "no impulse" (both bodies immovable along that direction).
    Vec2 solve(Vec2 b) const {
        float a11 = cx.x, a12 = cy.x, a21 = cx.y, a22 = cy.y;
        const float p = a11 * a22, q = a12 * a21;
        float det = p - q;
        float scale = 1.0f;
        if (!isFiniteValue(p) || !isFiniteValue(q)) {
            scale = 1.0f / largestEntry();
            a11 *= scale, a12 *= scale, a21 *= scale, a22 *= scale;
            det = a11 * a22 - a12 * a21;
        }
        if (det != 0.0f) {
            det = scale / det;
        }
        return {det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x)};
    }

    /// The inverse; a singular matrix gives the zero matrix (see solve).
    Mat22 inverse() const {
        float a = cx.x, b = cy.x, c = cx.y, d = cy.y;
        const float p = a * d, q = b * c;
        float det = p - q;
        float scale = 1.0f;
        if (!isFiniteValue(p) || !isFiniteValue(q)) {
            scale = 1.0f / largestEntry();
            a *= scale, b *= scale, c *= scale, d *= scale;
            det = a * d - b * c;
        }
        if (det != 0.0f) {
            det = scale / det;
        }
        return {{det * d, -det * c}, {-det * b, det * a}};
    }

    // Entries of 1e19 and more (a light body's inverse inertia times a long lever arm squared)
    // overflow the determinant. The matrix is then divided by its largest entry s first:
    // K^-1 = (K/s)^-1 / s, and (K/s) has entries of at most 1, so its determinant is finite. An
    // ordinary matrix never takes that path (scale stays 1, and x / 1 is x), so its results
    // keep their bits.
    static bool isFiniteValue(float x) { return std::isfinite(x); }
    constexpr float largestEntry() const {
        const float a = cx.x < 0.0f ? -cx.x : cx.x, b = cy.x < 0.0f ? -cy.x : cy.x;
        const float c = cx.y < 0.0f ? -cx.y : cx.y, d = cy.y < 0.0f ? -cy.y : cy.y;
        const float ab = a > b ? a : b, cd = c > d ? c : d;
        return ab > cd ? ab : cd;
    }
};

/// The matrix times a vector.
constexpr Vec2 operator*(const Mat22& m, Vec2 v) {
    return {m.cx.x * v.x + m.cy.x * v.y, m.cx.y * v.x + m.cy.y * v.y};
}

constexpr float kPi = 3.14159265359f;

}  // namespace pivot
