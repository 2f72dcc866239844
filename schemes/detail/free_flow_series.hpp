// One step of the exact torque-free rotation, by its Taylor series summed to round-off.
//
// The closed form (free_rigid_body.hpp) builds the whole motion: the canonical frame, K,
// the initial phase and three integrals of the third kind, most of it for one step only.
// A step needs less. In the body frame the momentum obeys Euler's equations,
//     dl/dt = l x w,  w = l / I,
// whose Taylor coefficients follow from one another by Cauchy products (w' is quadratic in
// w). For the orientation, take the rotation B(t) that turns n0 = l(0)/G the shortest way
// onto n(t) = l(t)/G; then q(t) B(t) carries n0 to the fixed L/G, so
//     q(t) = q(0) R(alpha(t), n0) B(t)^-1,
//     d alpha/dt = (w.n0 + (B's angular velocity).n)  = (2E + G w.n0) / (G + l.n0),
// with 2E = l.w and G = |l| constant, regular while l does not turn half a circle. Both series
// are summed until two consecutive terms fall below a sixteenth of an ulp of 1 (the step's
// angle and the direction n); the terms of an analytic function decay geometrically, so what
// is left is smaller still. A step too long for that within `max_order` terms is reported
// unconverged: the caller takes the closed form.
//
// A template on the scalar: a pack runs every lane to the order its last lane needs, and
// each lane sums only its own terms, so a body stepped in a pack gets the bits it gets alone.
#pragma once

#include "schemes/quaternion.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace rotbench {

inline constexpr int free_flow_series_max_order = 24;

namespace detail {
inline constexpr auto reciprocals = [] {
    std::array<double, free_flow_series_max_order + 2> r{};
    for (std::size_t k = 1; k < r.size(); ++k) r[k] = 1.0 / double(k);
    return r;
}();
}  // namespace detail

template <class S>
using LaneMask = decltype(S() <= S());  // bool for one body

template <class S>
struct FreeFlowStep {
    QuatT<S> q;              // q(dt), where converged
    LaneMask<S> converged;   // per lane
};

// q(dt) for bodies at orientation q (unit) with body-frame angular momentum l and principal
// moments `inertia`.
template <class S>
FreeFlowStep<S> free_flow_series(const Vec3T<S>& inertia, const QuatT<S>& q, const Vec3T<S>& l0, double dt) {
    using std::abs, std::max, std::sqrt;
    constexpr int max_order = free_flow_series_max_order;
    constexpr double tolerance = std::numeric_limits<double>::epsilon() / 16.0;
    constexpr const auto& reciprocal = detail::reciprocals;  // 1/k
    const S G_raw = sqrt(l0.squaredNorm());
    const auto at_rest = G_raw == S(0.0);
    const S G = select(at_rest, S(1.0), G_raw);  // a body at rest does not move (selected at the end)

    // Euler's equations as w'_x = c_x w_y w_z (cyclic), and the Taylor coefficients w_k, f_k
    // of w(t) and of d alpha/dt = N/D, N = 2E + G w.n0, D = G + l.n0 (header).
    // Reciprocals once, products after: a pack divides at a quarter of the rate it multiplies.
    const Vec3T<S> inverse_inertia = inertia.cwiseInverse();
    const S inverse_G = 1.0 / G;
    const Vec3T<S> c = Vec3T<S>(inertia.y() - inertia.z(), inertia.z() - inertia.x(), inertia.x() - inertia.y())
                           .cwiseProduct(inverse_inertia);
    const Vec3T<S> n0 = l0 * inverse_G;
    const Vec3T<S> in0 = inertia.cwiseProduct(n0);  // l.n0 = w.(I n0)
    std::array<Vec3T<S>, max_order + 1> w;
    std::array<S, max_order + 1> d, f;
    std::array<LaneMask<S>, max_order + 1> summed;  // lanes whose sum takes term k
    w[0] = l0.cwiseProduct(inverse_inertia);
    const S two_e = l0.dot(w[0]);
    d[0] = G + w[0].dot(in0);
    const S inverse_d0 = 1.0 / d[0];
    f[0] = (two_e + G * w[0].dot(n0)) * inverse_d0;
    summed[0] = all_true<S>();

    LaneMask<S> open = all_true<S>();  // lanes still summing terms
    LaneMask<S> small_before = !open;
    double h_k = 1.0;  // dt^k
    int order = 0;
    while (order < max_order && any_lane(open)) {
        const int k = ++order;
        Vec3T<S> sum = Vec3T<S>::Zero();
        for (int j = 0; j < k; ++j) {
            const Vec3T<S>& a = w[j];
            const Vec3T<S>& b = w[k - 1 - j];
            sum += Vec3T<S>(a.y() * b.z(), a.z() * b.x(), a.x() * b.y());
        }
        w[k] = c.cwiseProduct(sum) * reciprocal[k];
        d[k] = w[k].dot(in0);
        S numerator = G * w[k].dot(n0);
        for (int j = 1; j <= k; ++j) numerator -= d[j] * f[k - j];
        f[k] = numerator * inverse_d0;

        h_k *= dt;
        const Vec3T<S> l_k = inertia.cwiseProduct(w[k]);
        const S term = max(max(abs(l_k.x()), abs(l_k.y())), abs(l_k.z())) * inverse_G * abs(h_k);
        const LaneMask<S> small = max(term, abs(f[k]) * (abs(h_k * dt) * reciprocal[k + 1])) <= S(tolerance);
        summed[k] = open;
        open = open & !(small & small_before);
        small_before = small;
    }

    // Each lane's own terms, from the smallest up (Horner's rule); the others add zeros.
    Vec3T<S> w_end = Vec3T<S>::Zero();
    S rate(0.0);
    for (int k = order; k >= 0; --k) {
        w_end = select(summed[k], Vec3T<S>(w[k] + dt * w_end), w_end);
        rate = select(summed[k], S(f[k] * reciprocal[k + 1] + dt * rate), rate);
    }
    const Vec3T<S> l_end = inertia.cwiseProduct(w_end);
    const Vec3T<S> n_end = l_end * (1.0 / sqrt(l_end.squaredNorm()));
    const S cos_turn = n_end.dot(n0);

    const QuatT<S> spin = rotation_from_vector<S>((dt * rate) * n0);  // R(alpha, n0)
    const Vec3T<S> axis = n_end.cross(n0);
    const QuatT<S> half_turn(1.0 + cos_turn, axis.x(), axis.y(), axis.z());
    const QuatT<S> back(half_turn.coeffs() * (1.0 / sqrt(half_turn.squaredNorm())));  // B^-1: n_end -> n0
    const QuatT<S> moved = q * spin * back;
    // d alpha/dt is singular where l reverses: a step that turns it that far is the closed form's.
    const LaneMask<S> summed_to_round_off = !open;
    return {select(at_rest, q, moved), LaneMask<S>((summed_to_round_off & (cos_turn > S(-0.5))) | at_rest)};
}

}  // namespace rotbench
