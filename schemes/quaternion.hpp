// Quaternion and frame helpers shared by every scheme (seed 000, section 2.3).
// Convention: q maps body to world, v_world = q v_body q^-1 (seed eq. 12).
#pragma once

#include "schemes/bodies.hpp"

#include <cmath>

namespace rotbench {

// v' = q v q^-1 with q^-1 = q*/|q|^2 (seed eqs. 11-12), expanded as in eq. 13. Dividing by
// |q|^2 keeps this an exact rotation when round-off has moved |q| off 1; the unit-only
// shortcut (Eigen's q * v) returns R v - (|q|^2 - 1) v instead, and a scheme that goes
// world -> body -> world every step then shrinks w by that factor at each step.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
    const Vec3 t = q.vec().cross(v);
    return v + (2.0 / q.squaredNorm()) * (q.w() * t + q.vec().cross(t));
}
inline Vec3 to_world(const Quat& q, const Vec3& v_body) { return rotate(q, v_body); }
inline Vec3 to_body(const Quat& q, const Vec3& v_world) { return rotate(q.conjugate(), v_world); }

// The rotation by the angle |theta| about theta: the exponential map, exp(theta/2) as a
// quaternion. sin(x)/x is evaluated by its series near zero so that tiny or zero angles
// stay exact.
inline Quat rotation_from_vector(const Vec3& theta) {
    const double half = 0.5 * theta.norm();
    const double sinc = half < 1e-4 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
    const Vec3 v = (0.5 * sinc) * theta;
    return Quat(std::cos(half), v.x(), v.y(), v.z());
}

// Incremental rotation q(omega, dt) for a constant angular velocity over dt (seed eq. 17).
inline Quat rotation_increment(const Vec3& omega, double dt) { return rotation_from_vector(dt * omega); }

// The Cayley map cay(x) = (1 - x^/2)^-1 (1 + x^/2): the rotation by 2 atan(|x|/2) about x,
// a rational stand-in for the exponential map that agrees with it to O(|x|^3).
inline Quat cayley_rotation(const Vec3& x) {
    const double scale = 1.0 / std::sqrt(1.0 + 0.25 * x.squaredNorm());
    const Vec3 v = (0.5 * scale) * x;
    return Quat(scale, v.x(), v.y(), v.z());
}

// dq/dt = 1/2 w q for the world angular velocity w (seed eq. 15), as a 4-vector.
inline Eigen::Vector4d quaternion_rate(const Quat& q, const Vec3& omega) {
    return 0.5 * (Quat(0.0, omega.x(), omega.y(), omega.z()) * q).coeffs();
}

// Angular acceleration in the body frame from Euler's equations (seed eqs. 6, 34):
// I' dw'/dt = T' - w' x (I' w').
inline Vec3 euler_acceleration(const Vec3& omega_body, const Vec3& torque_body, const Vec3& inertia) {
    return (torque_body - omega_body.cross(inertia.cwiseProduct(omega_body))).cwiseQuotient(inertia);
}

// w = I(q)^-1 H with the world inertia tensor I(q) = R(q) I' R(q)^T (seed eqs. 16, 45):
// taken to the body frame, divided by the principal moments, taken back.
inline Vec3 omega_from_momentum(const Quat& q, const Vec3& inertia, const Vec3& momentum_world) {
    return to_world(q, to_body(q, momentum_world).cwiseQuotient(inertia));
}

inline Vec3 momentum_from_omega(const Quat& q, const Vec3& inertia, const Vec3& omega_world) {
    return to_world(q, inertia.cwiseProduct(to_body(q, omega_world)));
}

// Rotation angle (rad, in [0, pi]) that takes orientation b to orientation a.
inline double rotation_angle_between(const Quat& a, const Quat& b) {
    const Quat d = b.conjugate() * a;
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

}  // namespace rotbench
