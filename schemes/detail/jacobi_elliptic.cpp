#include "schemes/detail/jacobi_elliptic.hpp"

#include <array>
#include <cmath>

namespace rotbench {

JacobiElliptic jacobi_elliptic(double u, double m, double m1) {
    if (m1 <= 0.0) {  // m = 1: the separatrix limit
        const double sech = 1.0 / std::cosh(u);
        return {std::tanh(u), sech, sech};
    }
    if (m <= 0.0 && m > -1e-300) return {std::sin(u), std::cos(u), 1.0};
    // Descending AGM: a_{k+1} = (a_k + b_k)/2, b_{k+1} = sqrt(a_k b_k), c_{k+1} = (a_k - b_k)/2.
    constexpr int max_levels = 16;  // quadratic convergence: 16 levels reach c ~ 0 from any m in [0, 1)
    std::array<double, max_levels + 1> a{}, c{};
    a[0] = 1.0;
    double b = std::sqrt(m1);
    int n = 0;
    while (n < max_levels) {
        const double a_next = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = std::sqrt(a[n] * b);
        a[++n] = a_next;
        if (std::abs(c[n]) <= 1e-17 * a[n]) break;
    }
    // phi_n = 2^n a_n u, then back: phi_{k-1} = (phi_k + asin(c_k/a_k sin phi_k)) / 2.
    double phi = std::ldexp(a[n] * u, n);
    for (int k = n; k > 0; --k) phi = 0.5 * (phi + std::asin(c[k] / a[k] * std::sin(phi)));
    const double sn = std::sin(phi), cn = std::cos(phi);
    return {sn, cn, std::sqrt(cn * cn + m1 * sn * sn)};  // dn^2 = 1 - m sn^2, without cancellation
}

}  // namespace rotbench
