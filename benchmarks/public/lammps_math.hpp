// The arithmetic of LAMMPS's rigid-body steps (MathExtra, fix rigid, fix rigid/nve), written
// anew for the side-by-side cost comparison: plain arrays, a body's principal axes kept as
// the three columns of its rotation matrix (ex, ey, ez), angular velocity from angular
// momentum through those axes, quaternions normalised by a multiply with 1/sqrt. No LAMMPS
// code: the same operations in the same order, as read in its sources.
#pragma once

#include "benchmarks/public/plain_arrays.hpp"

namespace rotbench::lammps_style {

using public_codes::dot3, public_codes::normalise, public_codes::unpack;

struct Axes {
    double ex[3], ey[3], ez[3];  // body axes in the world: the columns of R(q)
};

// R(q) of a unit quaternion (w, x, y, z), column by column.
inline Axes axes_of(const double q[4]) {
    Axes a;
    a.ex[0] = q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3];
    a.ex[1] = 2.0 * (q[1] * q[2] + q[0] * q[3]);
    a.ex[2] = 2.0 * (q[1] * q[3] - q[0] * q[2]);
    a.ey[0] = 2.0 * (q[1] * q[2] - q[0] * q[3]);
    a.ey[1] = q[0] * q[0] - q[1] * q[1] + q[2] * q[2] - q[3] * q[3];
    a.ey[2] = 2.0 * (q[2] * q[3] + q[0] * q[1]);
    a.ez[0] = 2.0 * (q[1] * q[3] + q[0] * q[2]);
    a.ez[1] = 2.0 * (q[2] * q[3] - q[0] * q[1]);
    a.ez[2] = q[0] * q[0] - q[1] * q[1] - q[2] * q[2] + q[3] * q[3];
    return a;
}

// w = R diag(1/I) R^T m: the world angular velocity of world angular momentum m.
inline void omega_from_momentum(const double m[3], const Axes& a, const double inertia[3], double w[3]) {
    const double wb[3] = {dot3(m, a.ex) / inertia[0], dot3(m, a.ey) / inertia[1], dot3(m, a.ez) / inertia[2]};
    for (int i = 0; i < 3; ++i) w[i] = wb[0] * a.ex[i] + wb[1] * a.ey[i] + wb[2] * a.ez[i];
}

inline void momentum_from_omega(const double w[3], const Axes& a, const double inertia[3], double m[3]) {
    const double mb[3] = {dot3(w, a.ex) * inertia[0], dot3(w, a.ey) * inertia[1], dot3(w, a.ez) * inertia[2]};
    for (int i = 0; i < 3; ++i) m[i] = mb[0] * a.ex[i] + mb[1] * a.ey[i] + mb[2] * a.ez[i];
}

// (0, a) (x) b: the quaternion product of a pure vector and a quaternion.
inline void vector_times_quaternion(const double a[3], const double b[4], double c[4]) {
    c[0] = -a[0] * b[1] - a[1] * b[2] - a[2] * b[3];
    c[1] = b[0] * a[0] + a[1] * b[3] - a[2] * b[2];
    c[2] = b[0] * a[1] + a[2] * b[1] - a[0] * b[3];
    c[3] = b[0] * a[2] + a[0] * b[2] - a[1] * b[1];
}

// a (x) (0, b): a quaternion times a pure vector.
inline void quaternion_times_vector(const double a[4], const double b[3], double c[4]) {
    c[0] = -a[1] * b[0] - a[2] * b[1] - a[3] * b[2];
    c[1] = a[0] * b[0] + a[2] * b[2] - a[3] * b[1];
    c[2] = a[0] * b[1] + a[3] * b[0] - a[1] * b[2];
    c[3] = a[0] * b[2] + a[1] * b[1] - a[2] * b[0];
}

// The vector part of a* (x) b.
inline void conjugate_times_quaternion_vector(const double a[4], const double b[4], double c[3]) {
    c[0] = -a[1] * b[0] + a[0] * b[1] + a[3] * b[2] - a[2] * b[3];
    c[1] = -a[2] * b[0] - a[3] * b[1] + a[0] * b[2] + a[1] * b[3];
    c[2] = -a[3] * b[0] + a[2] * b[1] - a[1] * b[2] + a[0] * b[3];
}

}  // namespace rotbench::lammps_style
