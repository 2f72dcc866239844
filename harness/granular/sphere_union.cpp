#include "harness/granular/sphere_union.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <gsl/gsl_integration.h>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace rotbench {
namespace {

struct Moments {
    double mass = 0;
    Vec3 first = Vec3::Zero();                           // integral of x
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();    // integral of x x^T
};

// The parts of the ray centre + r u, 0 <= r <= radius, that the spheres `earlier` do not hold.
std::vector<std::pair<double, double>> kept_intervals(const Vec3& centre, double radius, const Vec3& u,
                                                      const std::vector<Sphere>& earlier) {
    std::vector<std::pair<double, double>> cut;
    for (const Sphere& s : earlier) {
        const Vec3 d = centre - s.centre;
        const double b = u.dot(d), disc = b * b - (d.squaredNorm() - s.radius * s.radius);
        if (disc <= 0.0) continue;
        const double root = std::sqrt(disc);
        const double lo = std::max(0.0, -b - root), hi = std::min(radius, -b + root);
        if (lo < hi) cut.emplace_back(lo, hi);
    }
    std::sort(cut.begin(), cut.end());
    std::vector<std::pair<double, double>> kept;
    double from = 0.0;
    for (const auto& [lo, hi] : cut) {
        if (lo > from) kept.emplace_back(from, lo);
        from = std::max(from, hi);
    }
    if (from < radius) kept.emplace_back(from, radius);
    return kept;
}

}  // namespace

MassProperties union_mass_properties(const std::vector<Sphere>& spheres, double density, int nodes) {
    if (spheres.empty() || nodes < 2) throw std::invalid_argument("union_mass_properties: no spheres, or fewer than 2 nodes");
    const std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> rule(
        gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(nodes)), &gsl_integration_glfixed_table_free);
    const int azimuths = 2 * nodes;
    const double azimuth_weight = 2.0 * std::numbers::pi / azimuths;
    // Positions relative to the first centre, so that a cluster far from the origin loses no digits.
    const Vec3 origin = spheres.front().centre;
    Moments sum;
    std::vector<Sphere> earlier;
    for (const Sphere& sphere : spheres) {
        const Vec3 c = sphere.centre - origin;
        std::vector<Sphere> overlapping;
        for (const Sphere& e : earlier)
            if ((e.centre - c).norm() < e.radius + sphere.radius) overlapping.push_back(e);
        Moments m;
        for (int a = 0; a < nodes; ++a) {
            double cos_theta = 0, weight = 0;
            gsl_integration_glfixed_point(-1.0, 1.0, static_cast<std::size_t>(a), &cos_theta, &weight, rule.get());
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
            for (int k = 0; k < azimuths; ++k) {
                const double phi = azimuth_weight * k;
                const Vec3 u(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
                const double w = weight * azimuth_weight;
                for (const auto& [lo, hi] : kept_intervals(c, sphere.radius, u, overlapping)) {
                    // Integrals of r^2, r^3, r^4 dr over [lo, hi].
                    const double r0 = (hi * hi * hi - lo * lo * lo) / 3.0;
                    const double r1 = (hi * hi * hi * hi - lo * lo * lo * lo) / 4.0;
                    const double r2 = (std::pow(hi, 5) - std::pow(lo, 5)) / 5.0;
                    m.mass += w * r0;
                    m.first += w * (r0 * c + r1 * u);
                    m.second += w * (r0 * c * c.transpose() + r1 * (c * u.transpose() + u * c.transpose()) + r2 * u * u.transpose());
                }
            }
        }
        sum.mass += m.mass;
        sum.first += m.first;
        sum.second += m.second;
        earlier.push_back({c, sphere.radius});
    }
    MassProperties p;
    p.mass = density * sum.mass;
    const Vec3 com = sum.first / sum.mass;
    p.centre = origin + com;
    const Eigen::Matrix3d spread = density * (sum.second - sum.mass * com * com.transpose());
    p.inertia = spread.trace() * Eigen::Matrix3d::Identity() - spread;
    p.inertia = 0.5 * (p.inertia + p.inertia.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(p.inertia);
    p.principal = eigen.eigenvalues();
    p.axes = eigen.eigenvectors();
    if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);
    return p;
}

}  // namespace rotbench
