// A 3-vector and a 3x3 matrix stored by columns: the effective mass of a joint's block of
// three rows (the prismatic joint's line, angle and limit; the weld's point and angle).
#pragma once

#include <cmath>

#include "pivot/math.h"

namespace pivot {

struct Vec3 {
    float x = 0.0f;
    float y = 0.0f;
    float z = 0.0f;
};

constexpr Vec3 operator-(Vec3 v) {
    return {-v.x, -v.y, -v.z};
}
constexpr float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr Vec3 operator*(float s, Vec3 v) {
    return {s * v.x, s * v.y, s * v.z};
}
constexpr Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

struct Mat33 {
    Vec3 cx;
    Vec3 cy;
    Vec3 cz;

    /// Solve A x = b by Cramer's rule, det A = cx . (cy x cz); a singular matrix gives x = 0
    /// (no impulse). As Mat22::cramer, a matrix whose triple products overflow is solved as
    /// A / s, s its largest entry; an ordinary one never takes that path.
    Vec3 solve(Vec3 b) const {
        Mat33 a = *this;
        float scale = 1.0f;
        float det = dot(a.cx, cross(a.cy, a.cz));
        if (!std::isfinite(det)) {
            scale = 1.0f / largestEntry();
            a = {scale * cx, scale * cy, scale * cz};
            det = dot(a.cx, cross(a.cy, a.cz));
        }
        const float invDet = det != 0.0f ? scale / det : det;
        return {invDet * dot(b, cross(a.cy, a.cz)), invDet * dot(a.cx, cross(b, a.cz)),
                invDet * dot(a.cx, cross(a.cy, b))};
    }

    /// Solve the upper-left 2x2 block: A22 x = b.
    Vec2 solve22(Vec2 b) const { return Mat22{{cx.x, cx.y}, {cy.x, cy.y}}.solve(b); }

    /// The inverse of a symmetric matrix, by its cofactors over det A (only the upper triangle
    /// is read); a singular matrix gives the zero matrix. Overflow is handled as in solve.
    Mat33 symmetricInverse() const {
        Mat33 a = *this;
        float scale = 1.0f;
        float det = dot(a.cx, cross(a.cy, a.cz));
        if (!std::isfinite(det)) {
            scale = 1.0f / largestEntry();
            a = {scale * cx, scale * cy, scale * cz};
            det = dot(a.cx, cross(a.cy, a.cz));
        }
        const float k = det != 0.0f ? scale / det : det;
        const float a11 = a.cx.x, a12 = a.cy.x, a13 = a.cz.x;
        const float a22 = a.cy.y, a23 = a.cz.y, a33 = a.cz.z;
        Mat33 m;
        m.cx = {k * (a22 * a33 - a23 * a23), k * (a13 * a23 - a12 * a33),
                k * (a12 * a23 - a13 * a22)};
        m.cy = {m.cx.y, k * (a11 * a33 - a13 * a13), k * (a13 * a12 - a11 * a23)};
        m.cz = {m.cx.z, m.cy.z, k * (a11 * a22 - a12 * a12)};
        return m;
    }

    /// The inverse of the upper-left 2x2 block, the rest zero.
    Mat33 inverse22() const {
        const Mat22 inv = Mat22{{cx.x, cx.y}, {cy.x, cy.y}}.inverse();
        return {{inv.cx.x, inv.cx.y, 0.0f}, {inv.cy.x, inv.cy.y, 0.0f}, {}};
    }

    float largestEntry() const {
        float m = 0.0f;
        for (const Vec3& c : {cx, cy, cz}) {
            m = std::fmax(m, std::fmax(std::fabs(c.x), std::fmax(std::fabs(c.y), std::fabs(c.z))));
        }
        return m;
    }
};

/// A v, summed column by column.
constexpr Vec3 operator*(const Mat33& m, Vec3 v) {
    return {v.x * m.cx.x + v.y * m.cy.x + v.z * m.cz.x, v.x * m.cx.y + v.y * m.cy.y + v.z * m.cz.y,
            v.x * m.cx.z + v.y * m.cy.z + v.z * m.cz.z};
}

/// The upper-left 2x2 block times v.
constexpr Vec2 mul22(const Mat33& m, Vec2 v) {
    return {m.cx.x * v.x + m.cy.x * v.y, m.cx.y * v.x + m.cy.y * v.y};
}

}  // namespace pivot
