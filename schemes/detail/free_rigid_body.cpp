#include "schemes/detail/free_rigid_body.hpp"

#include "schemes/detail/jacobi_elliptic.hpp"
#include "schemes/quaternion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace rotbench {
namespace {

Quat about_x(double angle) { return Quat(std::cos(0.5 * angle), std::sin(0.5 * angle), 0.0, 0.0); }
Quat about_z(double angle) { return Quat(std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle)); }

// GSL's default error handler aborts the process, even from the _e functions; their
// status codes are checked here instead.
const bool gsl_handler_off = (gsl_set_error_handler_off(), true);

double carlson_rf(double x, double y, double z) {
    gsl_sf_result r;
    if (gsl_sf_ellint_RF_e(x, y, z, GSL_PREC_DOUBLE, &r) != GSL_SUCCESS) throw std::domain_error("R_F");
    return r.val;
}
double carlson_rj(double x, double y, double z, double p) {
    gsl_sf_result r;
    if (gsl_sf_ellint_RJ_e(x, y, z, p, GSL_PREC_DOUBLE, &r) != GSL_SUCCESS) throw std::domain_error("R_J");
    return r.val;
}

// Incomplete elliptic integral of the first kind F(phi | m) for |phi| <= pi/2, with the
// complementary parameter given separately (DLMF 19.25.5).
double elliptic_f(double phi, double m1) {
    const double s = std::sin(phi), c = std::cos(phi);
    return s * carlson_rf(c * c, c * c + m1 * s * s, 1.0);
}

}  // namespace

FreeRigidBody::FreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& omega0) : q0_(q0.normalized()) {
    const Vec3 l = inertia.cwiseProduct(omega0);
    G_ = l.norm();
    if (G_ == 0.0 || omega0.cross(l).norm() <= 1e-15 * omega0.norm() * G_) {
        steady_ = true;  // rotation about a principal axis (or at rest)
        omega_steady_world_ = to_world(q0_, omega0);
        return;
    }

    // A symmetric top, two equal moments A and the third, C, about body axis k: L is fixed in
    // space and its component L_k in the body, so w = L/A + (1/C - 1/A) L_k e_k is a constant
    // rate fixed in space plus one fixed in the body, and q(t) = exp(t L/A) q0 exp(t (1/C -
    // 1/A) L_k e_k) (Landau & Lifshitz sec. 33). No elliptic functions, which the general form
    // below spends most of its time in.
    for (int k = 0; k < 3; ++k) {
        const double a = inertia[(k + 1) % 3], c = inertia[k];
        if (a != inertia[(k + 2) % 3]) continue;
        symmetric_ = true;
        space_rate_ = to_world(q0_, l) / a;
        body_rate_ = Vec3::Unit(k) * ((1.0 / c - 1.0 / a) * l[k]);
        omega0_body_ = omega0;
        return;
    }

    // Order the axes; the sign of G^2 - 2E I_mid (written without cancellation) picks the
    // axis the momentum circulates about.
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return inertia[i] < inertia[j]; });
    const int lo = order[0], mid = order[1], hi = order[2];
    double to_separatrix = 0.0;
    for (int i = 0; i < 3; ++i) to_separatrix += inertia[i] * (inertia[i] - inertia[mid]) * omega0[i] * omega0[i];
    const int s = to_separatrix >= 0.0 ? hi : lo, a = to_separatrix >= 0.0 ? lo : hi, b = mid;

    // P = D Pi with Pi the permutation (a, b, s) and D signs making det P = +1, w_a >= 0, w_s > 0.
    Eigen::Matrix3d perm = Eigen::Matrix3d::Zero();
    perm(0, a) = perm(1, b) = perm(2, s) = 1.0;
    const double d_a = omega0[a] < 0.0 ? -1.0 : 1.0, d_s = omega0[s] < 0.0 ? -1.0 : 1.0;
    const double d_b = perm.determinant() * d_a * d_s;
    to_canonical_ = Eigen::Vector3d(d_a, d_b, d_s).asDiagonal() * perm;
    q_canonical_ = Quat(to_canonical_);
    const Vec3 nu = to_canonical_ * omega0;
    const double Ia = inertia[a], Ib = inertia[b], Is = inertia[s];
    moments_ = Vec3(Ia, Ib, Is);

    // Amplitudes and parameters from the initial state, each a sum of like-signed terms.
    const double na2 = nu.x() * nu.x(), nb2 = nu.y() * nu.y(), ns2 = nu.z() * nu.z();
    const double Aa2 = na2 + nb2 * Ib * (Ib - Is) / (Ia * (Ia - Is));
    const double Ab2 = nb2 + na2 * Ia * (Ia - Is) / (Ib * (Ib - Is));
    const double As2 = ns2 + nb2 * Ib * (Ib - Ia) / (Is * (Is - Ia));
    amplitude_ = Vec3(std::sqrt(Aa2), std::sqrt(Ab2), std::sqrt(As2));
    const double g2_minus_2e_ia = Ib * (Ib - Ia) * nb2 + Is * (Is - Ia) * ns2;  // G^2 - 2E I_a
    const double g2_minus_2e_ib = Ia * (Ia - Ib) * na2 + Is * (Is - Ib) * ns2;  // G^2 - 2E I_b
    const double e2_is_minus_g2 = Ia * (Is - Ia) * na2 + Ib * (Is - Ib) * nb2;  // 2E I_s - G^2
    m_ = (Ib - Ia) * e2_is_minus_g2 / ((Is - Ib) * g2_minus_2e_ia);
    m1_ = (Is - Ia) * g2_minus_2e_ib / ((Is - Ib) * g2_minus_2e_ia);
    if (m1_ < 0.0) m1_ = 0.0;  // round-off on the separatrix
    m_ = std::min(m_, 1.0);
    K_ = m1_ > 0.0 ? carlson_rf(0.0, m1_, 1.0) : std::numeric_limits<double>::infinity();
    lambda_ = (Is - Ib) * amplitude_.y() * amplitude_.z() / (Ia * amplitude_.x());

    // Initial phase: cn u0 = w_a / A_a >= 0, sn u0 = w_b / A_b, so |am u0| <= pi/2.
    const double phi0 = std::atan2(nu.y() / amplitude_.y(), nu.x() / amplitude_.x());
    u0_ = elliptic_f(phi0, m1_);

    n_ = Is * (Ib - Ia) / (Ia * (Ib - Is));
    precession_factor_ = G_ * (1.0 / Ib - 1.0 / Ia) * (1.0 - n_) / lambda_;
    s_complete_ = m1_ > 0.0 ? carlson_rj(0.0, m1_, 1.0, 1.0 - n_) / 3.0 : 0.0;
    const Elliptic e0 = elliptic(0.0);
    s0_ = s_integral(e0.u_reduced, e0.sn, e0.cn, e0.half_periods);

    // q0 = q_space Rz(0) Rx(theta0) Rz(psi0) q_P.
    const Vec3 l0 = moments_.cwiseProduct(nu);
    const double theta0 = std::atan2(std::hypot(l0.x(), l0.y()), l0.z()), psi0 = std::atan2(l0.x(), l0.y());
    q_space_ = q0_ * q_canonical_.conjugate() * about_z(psi0).conjugate() * about_x(theta0).conjugate();
}

FreeRigidBody::Elliptic FreeRigidBody::elliptic(double t) const {
    // u = u0 + lambda t, reduced by 2K j. Over 1000 periods |u| ~ 1e4, so the products
    // lambda t and 2K j are kept exact (fma gives each rounding error), and the reduced
    // argument loses only what the difference itself rounds.
    const double p = lambda_ * t, p_error = std::fma(lambda_, t, -p);
    long long j = 0;
    double ur = u0_ + p;
    if (std::isfinite(K_)) {
        j = std::llround((p + u0_) / (2.0 * K_));
        const double shift = 2.0 * K_ * static_cast<double>(j);
        const double shift_error = std::fma(2.0 * K_, static_cast<double>(j), -shift);
        ur = (p - shift) + (u0_ + (p_error - shift_error));
    }
    const JacobiElliptic e = jacobi_elliptic(ur, m_, m1_);
    return {e.sn, e.cn, e.dn, j, ur};
}

// S(u) = int_0^u sn^2/(1 - n sn^2) du for u = u_r + 2K j (S is odd, quasi-periodic).
double FreeRigidBody::s_integral(double, double sn_r, double cn_r, long long half_periods) const {
    const double c2 = cn_r * cn_r, s2 = sn_r * sn_r;
    const double partial = sn_r * s2 * carlson_rj(c2, c2 + m1_ * s2, 1.0, 1.0 - n_ * s2) / 3.0;
    return partial + (half_periods ? 2.0 * static_cast<double>(half_periods) * s_complete_ : 0.0);
}

Vec3 FreeRigidBody::omega_body(double t) const {
    if (steady_) return to_body(q0_, omega_steady_world_);
    if (symmetric_) return to_body(rotation_increment(body_rate_, t), omega0_body_);  // w precesses about e_k
    const Elliptic e = elliptic(t);
    const double sign = (e.half_periods % 2 == 0) ? 1.0 : -1.0;
    const Vec3 nu(amplitude_.x() * sign * e.cn, amplitude_.y() * sign * e.sn, amplitude_.z() * e.dn);
    return to_canonical_.transpose() * nu;
}

Quat FreeRigidBody::orientation(double t) const {
    if (steady_) return rotation_increment(omega_steady_world_, t) * q0_;
    if (symmetric_) return rotation_increment(space_rate_, t) * q0_ * rotation_increment(body_rate_, t);
    const Elliptic e = elliptic(t);
    const double sign = (e.half_periods % 2 == 0) ? 1.0 : -1.0;
    const Vec3 l = moments_.cwiseProduct(Vec3(amplitude_.x() * sign * e.cn, amplitude_.y() * sign * e.sn, amplitude_.z() * e.dn));
    const double theta = std::atan2(std::hypot(l.x(), l.y()), l.z()), psi = std::atan2(l.x(), l.y());
    const double phi = G_ * t / moments_.x() +
                       precession_factor_ * (s_integral(e.u_reduced, e.sn, e.cn, e.half_periods) - s0_);
    return q_space_ * about_z(phi) * about_x(theta) * about_z(psi) * q_canonical_;
}

double FreeRigidBody::period() const {
    if (steady_) return std::numeric_limits<double>::infinity();
    if (symmetric_) return 2.0 * std::numbers::pi / body_rate_.norm();
    return 4.0 * K_ / std::abs(lambda_);
}

}  // namespace rotbench
