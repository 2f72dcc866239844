// Closed-form motion of a torque-free rigid body with any principal moments.
//
// Angular velocity: Jacobi elliptic functions (references/jacobi_elliptic.hpp). In a canonical principal frame
// (a, b, s), where s is the axis the angular momentum circulates about (largest moment
// when G^2 > 2E I_mid, smallest otherwise) and b the intermediate one,
//     w_a = A_a cn u,  w_b = A_b sn u,  w_s = A_s dn u,  u = u0 + lambda t
// (Landau & Lifshitz, Mechanics, sec. 37). The frame is reached from the body frame by a
// proper signed permutation chosen so that w_a(0) >= 0 and w_s(0) > 0.
// Orientation: ZXZ Euler angles about the fixed angular momentum L. Nutation and spin
// are algebraic in L'(t); the precession angle is
//     phi = G t / I_a + G (1/I_b - 1/I_a) (1 - n) / lambda * [S(u) - S(u0)],
//     S(u) = int sn^2/(1 - n sn^2) du = (Pi(n; am u | m) - u) / n,  n = I_s (I_b - I_a) / (I_a (I_b - I_s)),
// evaluated as (1/3) sin^3 R_J(cos^2, cos^2 + m' sin^2, 1, 1 - n sin^2) (Carlson; DLMF 19.25.14),
// which has no cancellation for small n. Arguments are reduced modulo 2K, with
// K = R_F(0, m', 1) and m' = 1 - k^2 computed from the moments directly, so long runs
// and states near the separatrix (m' -> 0) stay accurate.
// Special cases: rotation about a principal axis (including any rotation of a sphere)
// is steady; a symmetric top (two equal moments) is a space-fixed plus a body-fixed
// constant rotation; the separatrix (m' = 0) is the limit with K = infinity.
#pragma once

#include "schemes/bodies.hpp"

namespace rotbench {

class FreeRigidBody {
public:
    FreeRigidBody(const Vec3& inertia, const Quat& q0, const Vec3& omega0_body);

    Vec3 omega_body(double t) const;
    Vec3 omega_world(double t) const { return orientation(t) * omega_body(t); }
    Quat orientation(double t) const;

    bool steady() const { return steady_; }
    double parameter() const { return m_; }               // k^2
    double complementary_parameter() const { return m1_; }  // 1 - k^2
    // Period of the body-frame motion: 4K/|lambda| (2K/|lambda| for dn); infinite at the separatrix.
    double period() const;

private:
    struct Elliptic {
        double sn, cn, dn;
        long long half_periods;  // u = u_r + 2K j
        double u_reduced;
    };
    Elliptic elliptic(double t) const;
    double s_integral(double u_reduced, double sn_r, double cn_r, long long half_periods) const;

    bool steady_ = false;
    Vec3 omega_steady_world_;
    bool symmetric_ = false;
    Vec3 space_rate_, body_rate_, omega0_body_;  // L / A (world), (1/C - 1/A) L_k e_k (body), w(0) (body)
    Quat q0_;
    Eigen::Matrix3d to_canonical_;  // P: body -> canonical (a, b, s) coordinates, det +1
    Quat q_canonical_;              // quaternion of P
    Vec3 moments_;                  // (I_a, I_b, I_s)
    Vec3 amplitude_;                // (A_a, A_b, A_s)
    double m_ = 0, m1_ = 1, K_ = 0, lambda_ = 0, u0_ = 0, n_ = 0, G_ = 0;
    double s0_ = 0, s_complete_ = 0, precession_factor_ = 0;
    Quat q_space_;  // q_A: fixed rotation taking e_z to L / |L|
};

}  // namespace rotbench
