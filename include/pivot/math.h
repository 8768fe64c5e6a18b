// 2D vector maths used by the public API and the solver: Vec2, Rot, Transform, AABB, Mat22.
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

/// An axis-aligned box: every point p with lower <= p <= upper, component by component.
struct AABB {
    Vec2 lower;
    Vec2 upper;
};

/// A 2x2 matrix stored by columns.
struct Mat22 {
    Vec2 cx;
    Vec2 cy;

    /// What Cramer's rule needs: a matrix and the inverse of its determinant (0 when singular),
    /// such that A^-1 = invDet * adj(matrix). Usually the matrix is A itself. Entries of 1e19 and
    /// more (a light body's inverse inertia times a long lever arm squared) overflow the
    /// determinant's products; then the matrix is A / s, s its largest entry, whose entries are
    /// at most 1, and invDet = 1 / (s det(A / s)). An ordinary matrix never takes that path, so
    /// its results keep their bits.
    struct Cramer {
        float a11, a12, a21, a22;
        float invDet;
    };
    Cramer cramer() const {
        Cramer k{cx.x, cy.x, cx.y, cy.y, 0.0f};
        const float p = k.a11 * k.a22, q = k.a12 * k.a21;
        if (!std::isfinite(p) || !std::isfinite(q)) return rescaledCramer();
        const float det = p - q;
        k.invDet = det != 0.0f ? 1.0f / det : det;
        return k;
    }
    /// cramer's rare path, apart so that the common one is small enough to be inlined.
    Cramer rescaledCramer() const {
        const float scale = 1.0f / largestEntry();
        Cramer k{scale * cx.x, scale * cy.x, scale * cx.y, scale * cy.y, 0.0f};
        const float det = k.a11 * k.a22 - k.a12 * k.a21;
        k.invDet = det != 0.0f ? scale / det : det;
        return k;
    }

    /// Solve A x = b by Cramer's rule; a singular matrix gives x = 0, which to a constraint
    /// means "no impulse" (both bodies immovable along that direction).
    Vec2 solve(Vec2 b) const {
        const Cramer k = cramer();
        return {k.invDet * (k.a22 * b.x - k.a12 * b.y), k.invDet * (k.a11 * b.y - k.a21 * b.x)};
    }

    /// The inverse; a singular matrix gives the zero matrix (see solve).
    Mat22 inverse() const {
        const Cramer k = cramer();
        return {{k.invDet * k.a22, -k.invDet * k.a21}, {-k.invDet * k.a12, k.invDet * k.a11}};
    }

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
