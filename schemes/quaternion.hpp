// Quaternion and frame helpers shared by every scheme (seed 000, section 2.3).
// Convention: q maps body to world, v_world = q v_body q^-1 (seed eq. 12).
//
// Each helper is a template on the scalar S (double, or a pack of bodies: schemes/simd.hpp).
// S is deduced from the quaternion or the first vector only (std::type_identity_t marks the
// others), so that Eigen expressions convert to vectors as they would for a plain function.
#pragma once

#include "schemes/bodies.hpp"

#include <cmath>
#include <type_traits>

namespace rotbench {

template <class S>
using Vec3Of = std::type_identity_t<Vec3T<S>>;  // a parameter that takes part in no deduction

// v' = q v q^-1 with q^-1 = q*/|q|^2 (seed eqs. 11-12), expanded as in eq. 13. Dividing by
// |q|^2 keeps this an exact rotation when round-off has moved |q| off 1; the unit-only
// shortcut (Eigen's q * v) returns R v - (|q|^2 - 1) v instead, and a scheme that goes
// world -> body -> world every step then shrinks w by that factor at each step.
template <class S>
ROTBENCH_INLINE Vec3T<S> rotate(const QuatT<S>& q, const Vec3Of<S>& v) {
    const Vec3T<S> t = q.vec().cross(v);
    return v + (2.0 / q.squaredNorm()) * (q.w() * t + q.vec().cross(t));
}
template <class S>
ROTBENCH_INLINE Vec3T<S> to_world(const QuatT<S>& q, const Vec3Of<S>& v_body) { return rotate(q, v_body); }
template <class S>
ROTBENCH_INLINE Vec3T<S> to_body(const QuatT<S>& q, const Vec3Of<S>& v_world) { return rotate<S>(q.conjugate(), v_world); }

// cos h and sin(h)/h as their Taylor series in x = h^2, both even in h: for |h| <= 1/2 the
// terms after x^7 sum to less than h^16/16! < 8e-19, far below an ulp of either value
// (both exceed 0.87 there). Summed by Estrin's scheme (pairs of terms, then pairs of pairs
// with x^2 and x^4), whose dependent chain is three multiply-adds long where Horner's rule
// is seven: the map lies on the critical path of every step. The round-off is about an ulp:
// as accurate as sincos, with no call, no square root and no division. With x as an
// argument they take doubles and packs alike, with the same operations in the same order,
// so a body stepped in a pack gets the same bits as one stepped alone.
inline constexpr double exp_map_series_max_h2 = 0.25;
template <class S>
ROTBENCH_INLINE S even_series(const S& x, const S& x2, const S& x4, const double (&c)[8]) {
    return ((c[0] + c[1] * x) + x2 * (c[2] + c[3] * x)) + x4 * ((c[4] + c[5] * x) + x2 * (c[6] + c[7] * x));
}
inline constexpr double cos_coefficients[8] = {1.0,         -1.0 / 2,        1.0 / 24,          -1.0 / 720,
                                               1.0 / 40320, -1.0 / 3628800, 1.0 / 479001600.0, -1.0 / 87178291200.0};
inline constexpr double sinc_coefficients[8] = {1.0,          -1.0 / 6,          1.0 / 120,           -1.0 / 5040,
                                                1.0 / 362880, -1.0 / 39916800, 1.0 / 6227020800.0, -1.0 / 1307674368000.0};

// The rotation by the angle |theta| about theta: the exponential map, exp(theta/2) as a
// quaternion (cos h, sin(h)/h theta/2) with h = |theta|/2. A step turns a body by far less
// than a radian, so the series above serve it; sin and cos take over beyond |theta| = 1 rad.
template <class S = double>
ROTBENCH_INLINE QuatT<S> rotation_from_vector(const Vec3Of<S>& theta) {
    const S h2 = 0.25 * theta.squaredNorm();
    const S h4 = h2 * h2, h8 = h4 * h4;
    S cos_half = even_series(h2, h4, h8, cos_coefficients), sinc_half = even_series(h2, h4, h8, sinc_coefficients);
    const auto large = h2 > exp_map_series_max_h2;
    if (any_lane(large)) {
        using std::sqrt;
        const S half = sqrt(h2);
        const auto sin_cos_half = sin_cos(half);  // not a structured binding: clang 14 cannot capture one
        cos_half = select(large, sin_cos_half.second, cos_half);
        sinc_half = select(large, sin_cos_half.first / half, sinc_half);
    }
    const Vec3T<S> v = (0.5 * sinc_half) * theta;
    return QuatT<S>(cos_half, v.x(), v.y(), v.z());
}

// Incremental rotation q(omega, dt) for a constant angular velocity over dt (seed eq. 17).
template <class S = double>
ROTBENCH_INLINE QuatT<S> rotation_increment(const Vec3Of<S>& omega, double dt) { return rotation_from_vector<S>(dt * omega); }

// The Cayley map cay(x) = (1 - x^/2)^-1 (1 + x^/2): the rotation by 2 atan(|x|/2) about x,
// a rational stand-in for the exponential map that agrees with it to O(|x|^3).
template <class S = double>
ROTBENCH_INLINE QuatT<S> cayley_rotation(const Vec3Of<S>& x) {
    using std::sqrt;
    const S scale = 1.0 / sqrt(1.0 + 0.25 * x.squaredNorm());
    const Vec3T<S> v = (0.5 * scale) * x;
    return QuatT<S>(scale, v.x(), v.y(), v.z());
}

// The quaternion product (0, w) q, as a 4-vector in Eigen's coefficient order (x, y, z, w).
// Written out, since a product with a pure quaternion takes 12 multiplications where a
// general one (Eigen's) takes 16; summed in the order Eigen sums, so the bits are Eigen's.
template <class S>
ROTBENCH_INLINE Eigen::Matrix<S, 4, 1> pure_times(const Vec3Of<S>& omega, const QuatT<S>& q) {
    const S wx = omega.x(), wy = omega.y(), wz = omega.z();
    return Eigen::Matrix<S, 4, 1>((wx * q.w() + wy * q.z()) - wz * q.y(), (wy * q.w() + wz * q.x()) - wx * q.z(),
                                  (wz * q.w() + wx * q.y()) - wy * q.x(), -(wx * q.x() + wy * q.y()) - wz * q.z());
}

// dq/dt = 1/2 w q for the world angular velocity w (seed eq. 15), as a 4-vector. A step
// h dq/dt is better written (h/2) pure_times(w, q): the same bits (halving is exact), four
// multiplications fewer.
template <class S>
ROTBENCH_INLINE Eigen::Matrix<S, 4, 1> quaternion_rate(const QuatT<S>& q, const Vec3Of<S>& omega) {
    return 0.5 * pure_times<S>(omega, q);
}

// Per lane: `if_true` where the condition holds, `if_false` elsewhere.
template <class S, class Condition>
ROTBENCH_INLINE QuatT<S> select(const Condition& condition, const QuatT<S>& if_true, const QuatT<S>& if_false) {
    return QuatT<S>(select(condition, if_true.w(), if_false.w()), select(condition, if_true.x(), if_false.x()),
                    select(condition, if_true.y(), if_false.y()), select(condition, if_true.z(), if_false.z()));
}

// q / |q|, as a multiplication by 1/|q| (one division where q / |q| takes four). No
// zero-norm branch: no scheme's q reaches zero, and a NaN is caught as a blow-up.
template <class S>
ROTBENCH_INLINE QuatT<S> normalized(const QuatT<S>& q) {
    using std::sqrt;
    const S inverse_norm = 1.0 / sqrt(q.squaredNorm());
    return QuatT<S>(q.coeffs() * inverse_norm);
}

// Angular acceleration in the body frame from Euler's equations (seed eqs. 6, 34):
// I' dw'/dt = T' - w' x (I' w'). It multiplies by I'^-1 rather than divides by I': the
// inverse depends on the moments alone and is computed while the rest of the step runs,
// where a division at the end would lengthen the step's chain of dependent operations.
template <class S>
ROTBENCH_INLINE Vec3T<S> euler_acceleration(const Vec3T<S>& omega_body, const Vec3Of<S>& torque_body, const Vec3Of<S>& inertia) {
    return (torque_body - omega_body.cross(inertia.cwiseProduct(omega_body))).cwiseProduct(inertia.cwiseInverse());
}

// w = I(q)^-1 H with the world inertia tensor I(q) = R(q) I' R(q)^T (seed eqs. 16, 45):
// taken to the body frame, multiplied by the inverse principal moments (as above), taken back.
template <class S>
ROTBENCH_INLINE Vec3T<S> omega_from_momentum(const QuatT<S>& q, const Vec3Of<S>& inertia, const Vec3Of<S>& momentum_world) {
    return to_world<S>(q, to_body(q, momentum_world).cwiseProduct(inertia.cwiseInverse()));
}

template <class S>
ROTBENCH_INLINE Vec3T<S> momentum_from_omega(const QuatT<S>& q, const Vec3Of<S>& inertia, const Vec3Of<S>& omega_world) {
    return to_world<S>(q, inertia.cwiseProduct(to_body(q, omega_world)));
}

// The body axes in the world, the columns of R(q) (seed eq. 10). A scheme that changes
// frames several times at one orientation builds them once: then w = I(q)^-1 L costs two
// matrix-vector products instead of four quaternion rotations (LAMMPS's fix rigid keeps them
// so). For a q just normalised (`unit`), |q|^2 is 1 to round-off and is not divided by;
// otherwise the axes are divided by |q|^2, so that they are orthonormal whatever |q|. A
// scheme that carries w itself through its frame changes from step to step (direct, zvw)
// keeps the rotations above: there the matrix's round-off accumulates (docs/performance.md).
template <class S>
struct BodyAxesT {
    Vec3T<S> x, y, z;
};
template <bool unit = false, class S>
ROTBENCH_INLINE BodyAxesT<S> body_axes(const QuatT<S>& q) {
    const S w = q.w(), x = q.x(), y = q.y(), z = q.z();
    const S ww = w * w, xx = x * x, yy = y * y, zz = z * z;
    BodyAxesT<S> a{Vec3T<S>(ww + xx - yy - zz, 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)),
                   Vec3T<S>(2.0 * (x * y - w * z), ww - xx + yy - zz, 2.0 * (y * z + w * x)),
                   Vec3T<S>(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), ww - xx - yy + zz)};
    if constexpr (!unit) {
        const S s = 1.0 / q.squaredNorm();
        a.x *= s, a.y *= s, a.z *= s;
    }
    return a;
}
// R^T v and R v through the axes.
template <class S>
ROTBENCH_INLINE Vec3T<S> to_body(const BodyAxesT<S>& a, const Vec3Of<S>& v_world) {
    return Vec3T<S>(a.x.dot(v_world), a.y.dot(v_world), a.z.dot(v_world));
}
template <class S>
ROTBENCH_INLINE Vec3T<S> to_world(const BodyAxesT<S>& a, const Vec3Of<S>& v_body) {
    return v_body.x() * a.x + v_body.y() * a.y + v_body.z() * a.z;
}
// w = R diag(1/I') R^T L through the axes, given the inverse principal moments (computed
// once for the several frame changes of a step, off its chain of dependent operations).
template <class S>
ROTBENCH_INLINE Vec3T<S> omega_from_momentum(const BodyAxesT<S>& a, const Vec3Of<S>& inverse_inertia,
                                             const Vec3Of<S>& momentum_world) {
    return to_world(a, to_body(a, momentum_world).cwiseProduct(inverse_inertia));
}

// Rotation angle (rad, in [0, pi]) that takes orientation b to orientation a.
inline double rotation_angle_between(const Quat& a, const Quat& b) {
    const Quat d = b.conjugate() * a;
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

}  // namespace rotbench
