// What Yade's aspherical steps (NewtonIntegrator: leapfrogAsphericalRotate and its Omelyan1998
// and delValle2023 variants) share, written anew for the cost table's counterparts.
#pragma once

#include "schemes/scheme.hpp"

namespace rotbench::yade_style {

// dq/dt = 1/2 q (0, w') for the body-frame angular velocity w' (Yade's DotQ).
inline Quat rate(const Vec3& omega_body, const Quat& q) {
    const Quat d = q * Quat(0.0, omega_body.x(), omega_body.y(), omega_body.z());
    return Quat(0.5 * d.coeffs());
}

// The Omelyan and SPIRAL steps keep L and count steps (scene->iter), and end alike: q
// normalised only every normalizeEvery steps (default 5000, counting from the first), then L
// and w from the new body-frame w' through the rotation matrix A of q^n (global to local).
struct LeapfrogMemory {
    Vec3 angmom;  // world, at the half step (Yade's state->angMom)
    long steps = 0;
};
inline constexpr long normalize_every = 5000;

inline void finish_leapfrog(RigidBody& b, LeapfrogMemory& m, const Eigen::Matrix3d& A, const Vec3& omega_body) {
    if (m.steps++ % normalize_every == 0) b.q.normalize();
    m.angmom = A.transpose() * omega_body.cwiseProduct(b.inertia);
    b.omega = A.transpose() * omega_body;
}

}  // namespace rotbench::yade_style
