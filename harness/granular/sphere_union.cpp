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

// The parts of the ray centre + r u, 0 <= r <= radius, that the spheres `earlier` do not hold,
// into `kept` (`cut` is scratch space: both are reused from ray to ray, so a ray allocates nothing).
void kept_intervals(const Vec3& centre, double radius, const Vec3& u, const std::vector<Sphere>& earlier,
                    std::vector<std::pair<double, double>>& cut, std::vector<std::pair<double, double>>& kept) {
    cut.clear();
    kept.clear();
    for (const Sphere& s : earlier) {
        const Vec3 d = centre - s.centre;
        const double b = u.dot(d), disc = b * b - (d.squaredNorm() - s.radius * s.radius);
        if (disc <= 0.0) continue;
        const double root = std::sqrt(disc);
        const double lo = std::max(0.0, -b - root), hi = std::min(radius, -b + root);
        if (lo < hi) cut.emplace_back(lo, hi);
    }
    std::sort(cut.begin(), cut.end());
    double from = 0.0;
    for (const auto& [lo, hi] : cut) {
        if (lo > from) kept.emplace_back(from, lo);
        from = std::max(from, hi);
    }
    if (from < radius) kept.emplace_back(from, radius);
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
    // Over the whole union: the integrals of 1, x and x x^T (x relative to `origin`).
    double volume = 0;
    Vec3 first = Vec3::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    std::vector<double> cos_phi(azimuths), sin_phi(azimuths);
    for (int k = 0; k < azimuths; ++k) cos_phi[k] = std::cos(azimuth_weight * k), sin_phi[k] = std::sin(azimuth_weight * k);
    std::vector<Sphere> earlier;
    std::vector<std::pair<double, double>> cut, kept;
    for (const Sphere& sphere : spheres) {
        const Vec3 c = sphere.centre - origin;
        std::vector<Sphere> overlapping;
        for (const Sphere& e : earlier)
            if ((e.centre - c).norm() < e.radius + sphere.radius) overlapping.push_back(e);
        // About the sphere's centre, x = c + r u: the integrals of r^2 (s0), r^3 u (s1) and
        // r^4 u u^T (s2, its six distinct entries) over the directions give all three moments.
        double s0 = 0;
        Vec3 s1 = Vec3::Zero();
        double s2[6] = {0, 0, 0, 0, 0, 0};  // xx, yy, zz, xy, xz, yz
        for (int a = 0; a < nodes; ++a) {
            double cos_theta = 0, weight = 0;
            gsl_integration_glfixed_point(-1.0, 1.0, static_cast<std::size_t>(a), &cos_theta, &weight, rule.get());
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
            const double w = weight * azimuth_weight;
            for (int k = 0; k < azimuths; ++k) {
                const Vec3 u(sin_theta * cos_phi[k], sin_theta * sin_phi[k], cos_theta);
                kept_intervals(c, sphere.radius, u, overlapping, cut, kept);
                double r0 = 0, r1 = 0, r2 = 0;  // integrals of r^2, r^3, r^4 dr over the kept parts
                for (const auto& [lo, hi] : kept) {
                    const double lo2 = lo * lo, hi2 = hi * hi;
                    r0 += (hi2 * hi - lo2 * lo) / 3.0;
                    r1 += (hi2 * hi2 - lo2 * lo2) / 4.0;
                    r2 += (hi2 * hi2 * hi - lo2 * lo2 * lo) / 5.0;
                }
                s0 += w * r0;
                s1 += (w * r1) * u;
                const double q = w * r2;
                s2[0] += q * u.x() * u.x(), s2[1] += q * u.y() * u.y(), s2[2] += q * u.z() * u.z();
                s2[3] += q * u.x() * u.y(), s2[4] += q * u.x() * u.z(), s2[5] += q * u.y() * u.z();
            }
        }
        Eigen::Matrix3d uu;
        uu << s2[0], s2[3], s2[4], s2[3], s2[1], s2[5], s2[4], s2[5], s2[2];
        volume += s0;
        first += s0 * c + s1;
        second += s0 * c * c.transpose() + c * s1.transpose() + s1 * c.transpose() + uu;
        earlier.push_back({c, sphere.radius});
    }
    MassProperties p;
    p.mass = density * volume;
    const Vec3 com = first / volume;
    p.centre = origin + com;
    const Eigen::Matrix3d spread = density * (second - volume * com * com.transpose());
    p.inertia = spread.trace() * Eigen::Matrix3d::Identity() - spread;
    p.inertia = 0.5 * (p.inertia + p.inertia.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(p.inertia);
    p.principal = eigen.eigenvalues();
    p.axes = eigen.eigenvectors();
    if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);
    return p;
}

}  // namespace rotbench
