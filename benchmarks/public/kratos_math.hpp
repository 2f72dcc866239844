// The arithmetic of Kratos DEMApplication's rigid-body rotation steps (its Quaternion class and
// GeometryFunctions), written anew for the cost table's side-by-side comparison: plain arrays,
// vectors rotated by the unit-quaternion shortcut, quaternions normalised by four divisions,
// an incremental rotation whose small-angle branch uses the series the seed's authors used
// (1 + theta^2/2 for the cosine: docs/findings.md), and the world inverse inertia tensor built
// by rotating the body tensor's columns and then its rows. No Kratos code: the same
// operations in the same order, as read in its sources.
#pragma once

#include "schemes/scheme.hpp"

#include <cmath>
#include <limits>

namespace rotbench::kratos_style {

struct Quaternion4 {
    double w, x, y, z;
};

inline Quaternion4 of(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
inline Quat to_quat(const Quaternion4& q) { return Quat(q.w, q.x, q.y, q.z); }

// v' = q v q* for a unit q: two cross products with q's vector part (Quaternion::RotateVector3).
inline void rotate(const Quaternion4& q, const double a[3], double out[3]) {
    const double b0 = 2.0 * (q.y * a[2] - q.z * a[1]), b1 = 2.0 * (q.z * a[0] - q.x * a[2]), b2 = 2.0 * (q.x * a[1] - q.y * a[0]);
    const double c0 = q.y * b2 - q.z * b1, c1 = q.z * b0 - q.x * b2, c2 = q.x * b1 - q.y * b0;
    out[0] = a[0] + b0 * q.w + c0;
    out[1] = a[1] + b1 * q.w + c1;
    out[2] = a[2] + b2 * q.w + c2;
}
inline void to_local(const Quaternion4& q, const double a[3], double out[3]) { rotate({q.w, -q.x, -q.y, -q.z}, a, out); }

inline void normalise(Quaternion4& q) {
    double n = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (n > 0.0 && n != 1.0) {
        n = std::sqrt(n);
        q.x /= n, q.y /= n, q.z /= n, q.w /= n;
    }
}

inline Quaternion4 product(const Quaternion4& a, const Quaternion4& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// exp(rotation / 2) q: the increment by the rotation vector, normalised, then the product
// (GeometryFunctions::UpdateOrientation).
inline Quaternion4 turned(const Quaternion4& q, const double rotation[3]) {
    const double t[3] = {0.5 * rotation[0], 0.5 * rotation[1], 0.5 * rotation[2]};
    const double mag = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    Quaternion4 d;
    if (mag * mag * mag * mag / 24.0 < std::numeric_limits<double>::epsilon()) {
        const double aux = 1.0 - mag * mag / 6.0;
        d = {1.0 + mag * mag * 0.5, t[0] * aux, t[1] * aux, t[2] * aux};
    } else {
        const double aux = std::sin(mag) / mag;
        d = {std::cos(mag), t[0] * aux, t[1] * aux, t[2] * aux};
    }
    normalise(d);
    return product(d, q);
}

// I(q)^-1 = R diag(1/I') R^T, by rotating the columns of diag(1/I') and then the rows of the
// result (GeometryFunctions::QuaternionTensorLocal2Global): six rotations.
inline void world_inverse_tensor(const Quaternion4& q, const double inertia[3], double out[3][3]) {
    double columns[3][3];
    for (int k = 0; k < 3; ++k) {
        double e[3] = {0.0, 0.0, 0.0};
        e[k] = 1.0 / inertia[k];
        rotate(q, e, columns[k]);
    }
    for (int i = 0; i < 3; ++i) {
        const double row[3] = {columns[0][i], columns[1][i], columns[2][i]};
        rotate(q, row, out[i]);
    }
}

inline void times(const double m[3][3], const double v[3], double out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

// Euler's equations in the body frame, component by component with a division each.
inline void euler_acceleration(const double w[3], const double inertia[3], const double torque[3], double out[3]) {
    for (int j = 0; j < 3; ++j) {
        const int k = (j + 1) % 3, l = (j + 2) % 3;
        out[j] = (torque[j] - (w[k] * inertia[l] * w[l] - w[l] * inertia[k] * w[k])) / inertia[j];
    }
}

}  // namespace rotbench::kratos_style
