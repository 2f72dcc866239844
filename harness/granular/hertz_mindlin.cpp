#include "harness/granular/hertz_mindlin.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rotbench {

HertzMindlin::HertzMindlin(const ContactMaterial& m) {
    if (!(m.young > 0.0) || !(m.poisson > -1.0 && m.poisson < 0.5) || !(m.restitution >= 0.0 && m.restitution <= 1.0))
        throw std::invalid_argument("HertzMindlin: E must be positive, nu in (-1, 0.5), e in [0, 1]");
    // Two bodies of one material: 1/E* = 2 (1 - nu^2)/E, 1/G* = 2 (2 - nu)/G, G = E / (2 (1 + nu)).
    modulus_ = m.young / (2.0 * (1.0 - m.poisson * m.poisson));
    shear_modulus_ = m.young / (4.0 * (2.0 - m.poisson) * (1.0 + m.poisson));
    if (m.restitution == 0.0) beta_ = -1.0;
    else {
        const double log_e = std::log(m.restitution);
        beta_ = log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
    }
}

Vec3 HertzMindlin::force(double overlap, const Vec3& n, const Vec3& v, double radius, double mass, Vec3& spring,
                         double elapsed, double friction) const {
    const double contact_radius = std::sqrt(radius * overlap);  // sqrt(R* d)
    const double normal_stiffness = 2.0 * modulus_ * contact_radius, tangential_stiffness = 8.0 * shear_modulus_ * contact_radius;
    const double damping = -2.0 * std::sqrt(5.0 / 6.0) * beta_;
    const double v_n = v.dot(n);
    const Vec3 v_t = v - v_n * n;
    const double f_n = std::max(0.0, 2.0 / 3.0 * normal_stiffness * overlap - damping * std::sqrt(normal_stiffness * mass) * v_n);
    // The spring turned into the present tangent plane (the contact rolls and the normal turns),
    // its length kept, then stretched by the tangential motion.
    const double before = spring.norm();
    spring -= spring.dot(n) * n;
    const double after = spring.norm();
    if (after > 0.0) spring *= before / after;
    spring += elapsed * v_t;
    Vec3 f_t = -tangential_stiffness * spring - damping * std::sqrt(tangential_stiffness * mass) * v_t;
    const double limit = friction * f_n, f_t_norm = f_t.norm();
    if (f_t_norm > limit) {  // sliding: the force at the Coulomb limit, the spring that gives it
        f_t *= limit / f_t_norm;  // f_t_norm > limit >= 0
        spring = -f_t / tangential_stiffness;
    }
    return f_n * n + f_t;
}

double HertzMindlin::normal_energy(double overlap, double radius) const {
    return 8.0 / 15.0 * modulus_ * std::sqrt(radius) * overlap * overlap * std::sqrt(overlap);
}

}  // namespace rotbench
