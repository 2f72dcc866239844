#include "harness/exec/stability.hpp"

#include "harness/exec/interrupt.hpp"
#include "harness/exec/run.hpp"
#include "schemes/quaternion.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace rotbench {
namespace {

constexpr int block = 18;  // x v theta w F T

Vec3 log_map(const Quat& q) {  // rotation vector of a unit quaternion, angle in [0, pi]
    const Quat u = q.w() < 0 ? Quat(-q.coeffs()) : q;
    const double s = u.vec().norm();
    if (s < 1e-300) return Vec3::Zero();
    return (2.0 * std::atan2(s, u.w()) / s) * u.vec();
}

}  // namespace

double stability_boundary(const std::function<bool(double)>& unstable, double dt_guess, double tolerance, int halvings) {
    double lo = dt_guess, hi = dt_guess;
    if (unstable(dt_guess)) {
        do {
            if (halvings-- == 0) return 0.0;
            hi = lo;
            lo *= 0.5;
        } while (unstable(lo));
    } else {
        int doublings = 30;
        do {
            if (doublings-- == 0) return std::numeric_limits<double>::infinity();  // no limit up to 2^30 dt_guess
            lo = hi;
            hi *= 2.0;
        } while (!unstable(hi));
    }
    while ((hi - lo) > tolerance * lo) {
        const double mid = 0.5 * (lo + hi);
        (unstable(mid) ? hi : lo) = mid;
    }
    return lo;
}

bool unstable_at(const Scene& scene, const std::string& scheme_id, double dt, const StabilityCriterion& c) {
    auto scheme = SchemeRegistry::instance().at(scheme_id, "scheme").make();
    Bodies b = scene.initial_state();
    const double e0 = scene.energy(b);
    const auto steps = static_cast<std::int64_t>(std::ceil(c.horizon / dt));
    std::int64_t evals = 0;
    bool blew_up = false;
    try {
        simulate(scene, *scheme, b, dt, steps, evals, [&](std::int64_t, double, const Bodies& s) {
            blew_up = energy_blew_up(scene.energy(s), e0, c);
            return !blew_up && !interrupt_signal();  // a signal ends the search (the caller drops it)
        });
    } catch (...) {
        return true;  // a scheme that throws (anything) has failed at this dt
    }
    return blew_up;
}

double empirical_limit(const Scene& scene, const std::string& scheme, double dt_guess, const StabilityCriterion& c,
                       double tolerance) {
    return stability_boundary([&](double dt) { return unstable_at(scene, scheme, dt, c); }, dt_guess, tolerance);
}

namespace {

// The state of the step map: per body x, v, theta (rotation vector from `reference`), w, F, T.
struct StepMap {
    const Scene& scene;
    std::string scheme_id;
    double dt;
    Bodies rest;
    std::vector<Quat> reference;

    StepMap(const Scene& s, std::string id, double step) : scene(s), scheme_id(std::move(id)), dt(step), rest(s.initial_state()) {
        for (std::size_t i = 0; i < rest.size(); ++i) {
            rest.velocity.set(i, Vec3::Zero());
            rest.omega.set(i, Vec3::Zero());
            reference.push_back(rest.orientation[i]);
        }
        scene.evaluate_forces(rest, 0.0);
    }
    Eigen::VectorXd state(const Bodies& b) const {
        Eigen::VectorXd s(block * b.size());
        for (std::size_t i = 0; i < b.size(); ++i) {
            s.segment<3>(block * i + 0) = b.position[i];
            s.segment<3>(block * i + 3) = b.velocity[i];
            s.segment<3>(block * i + 6) = log_map(b.orientation[i].normalized() * reference[i].conjugate());
            s.segment<3>(block * i + 9) = b.omega[i];
            s.segment<3>(block * i + 12) = b.force[i];
            s.segment<3>(block * i + 15) = b.torque[i];
        }
        return s;
    }
    Bodies bodies(const Eigen::VectorXd& s) const {
        Bodies b = rest;
        for (std::size_t i = 0; i < b.size(); ++i) {
            b.position.set(i, s.segment<3>(block * i + 0));
            b.velocity.set(i, s.segment<3>(block * i + 3));
            b.orientation.set(i, rotation_from_vector(s.segment<3>(block * i + 6)) * reference[i]);
            b.omega.set(i, s.segment<3>(block * i + 9));
            b.force.set(i, s.segment<3>(block * i + 12));
            b.torque.set(i, s.segment<3>(block * i + 15));
        }
        return b;
    }
    Eigen::VectorXd operator()(const Eigen::VectorXd& s) const {
        Bodies b = bodies(s);
        auto scheme = SchemeRegistry::instance().at(scheme_id, "scheme").make();
        scheme->start(b);
        dem_step(scene, *scheme, b, dt, dt);
        return state(b);
    }
};

}  // namespace


StepJacobian step_jacobian(const Scene& scene, const std::string& scheme_id, double dt) {
    const StepMap map(scene, scheme_id, dt);
    const Eigen::VectorXd s0 = map.state(map.rest);
    // Each component is nudged by what moves the system by 1e-7 of its size in one step:
    // x by 1e-7 L, v by 1e-7 L/dt, theta by 1e-7, w by 1e-7/dt, F by 1e-7 m L/dt^2, T by
    // 1e-7 I/dt^2. Far above round-off (a force nudge of 1e-7 N would move a body by 1e-18 m,
    // below the round-off of its position, and fill the Jacobian with noise), and small
    // enough for the rotations, the only nonlinearity (curvature scale 1 rad).
    const Bodies& r = map.rest;
    Vec3 centre = Vec3::Zero();
    for (std::size_t i = 0; i < r.size(); ++i) centre += r.position[i] / static_cast<double>(r.size());
    double length = 0;
    for (std::size_t i = 0; i < r.size(); ++i) length = std::max(length, (r.position[i] - centre).norm());
    if (length == 0) length = 1.0;
    Eigen::VectorXd h(s0.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        const double scales[6] = {length, length / dt, 1.0, 1.0 / dt, r.mass[i] * length / (dt * dt),
                                  r.inertia[i].maxCoeff() / (dt * dt)};
        for (int g = 0; g < 6; ++g) h.segment<3>(block * i + 3 * g).setConstant(1e-7 * scales[g]);
    }
    // Returned in units of the nudges, D^-1 J D with D = diag(h): the same eigenvalues, and
    // entries of similar size (raw, they span 30 orders of magnitude and the eigensolver
    // loses the small eigenvalues).
    StepJacobian out{Eigen::MatrixXd(s0.size(), s0.size()), h};
    for (Eigen::Index k = 0; k < s0.size(); ++k) {
        Eigen::VectorXd plus = s0, minus = s0;
        plus[k] += h[k];
        minus[k] -= h[k];
        out.scaled.col(k) = ((map(plus) - map(minus)) / 2.0).cwiseQuotient(h);
    }
    return out;
}

double spectral_radius(const Scene& scene, const StepJacobian& j) {
    const Eigen::MatrixXd& jacobian = j.scaled;
    if (!jacobian.allFinite()) return std::numeric_limits<double>::infinity();  // the step map itself blew up
    const Bodies rest = scene.initial_state();
    const std::size_t n = rest.size();
    const Eigen::Index dim = jacobian.rows();
    Vec3 centre = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i) centre += rest.position[i] / static_cast<double>(n);
    Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(dim, 12);
    for (int k = 0; k < 3; ++k) {
        const Vec3 e = Vec3::Unit(k);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 arm = rest.position[i] - centre;
            rigid.block<3, 1>(block * i + 0, k) = e;                  // translation
            rigid.block<3, 1>(block * i + 3, 3 + k) = e;              // its rate
            rigid.block<3, 1>(block * i + 6, 6 + k) = e;              // rotation of the whole
            rigid.block<3, 1>(block * i + 0, 6 + k) = e.cross(arm);
            rigid.block<3, 1>(block * i + 9, 9 + k) = e;              // its rate
            rigid.block<3, 1>(block * i + 3, 9 + k) = e.cross(arm);
        }
    }
    rigid = j.scale.cwiseInverse().asDiagonal() * rigid;  // in the units of the scaled Jacobian
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(rigid);
    const Eigen::MatrixXd q = qr.householderQ();
    const Eigen::MatrixXd complement = q.rightCols(dim - 12);
    const Eigen::MatrixXd quotient = complement.transpose() * jacobian * complement;
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(quotient, /*computeEigenvectors=*/false);
    return solver.eigenvalues().cwiseAbs().maxCoeff();
}

double amplification_limit(const Scene& scene, const std::string& scheme, double dt_guess, const StabilityCriterion& c,
                           double tolerance) {
    return stability_boundary(
        [&](double dt) {
            double rho = 0;
            try {
                rho = spectral_radius(scene, step_jacobian(scene, scheme, dt));
            } catch (...) {
                return true;  // as in unstable_at: a scheme that throws has failed at this dt
            }
            return !std::isfinite(rho) || 2.0 * (c.horizon / dt) * std::log(rho) >= std::log(c.growth);
        },
        dt_guess, tolerance);
}

bool unstable_at_every_dt(const Scene& scene, const std::string& scheme, double dt_small) {
    try {
        return spectral_radius(scene, step_jacobian(scene, scheme, dt_small)) > 1.0 + 1e-6;
    } catch (...) {
        return true;
    }
}

}  // namespace rotbench
