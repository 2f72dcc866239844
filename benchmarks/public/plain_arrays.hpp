// The plain-array plumbing both MD codes' counterparts (LAMMPS's, HOOMD-blue's) step with: a
// body's orientation and moments as their arrays hold them, a 3-vector dot product, and a
// quaternion normalised by a multiply with 1/sqrt, as both codes normalise.
#pragma once

#include "schemes/scheme.hpp"

#include <cmath>

namespace rotbench::public_codes {

inline void unpack(const RigidBody& b, double q[4], double inertia[3]) {
    q[0] = b.q.w(), q[1] = b.q.x(), q[2] = b.q.y(), q[3] = b.q.z();
    inertia[0] = b.inertia.x(), inertia[1] = b.inertia.y(), inertia[2] = b.inertia.z();
}

inline void normalise(double q[4]) {
    const double s = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int i = 0; i < 4; ++i) q[i] *= s;
}

inline double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace rotbench::public_codes
