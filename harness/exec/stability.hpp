// Stability limits of a scheme on a scene: measured (bracketing and bisection) and from
// the eigenvalues of the scheme's own one-step map, linearised numerically.
//
// The blow-up criterion, shared by both so that they can be compared:
//   a run at dt is unstable when, within a horizon of `horizon` seconds, its energy grows
//   past `growth` times the initial energy, or the state stops being finite.
// For the linearised map this is rho(dt)^(2 N) >= growth with N = horizon / dt steps (the
// energy goes as the square of the amplitude). A scheme whose rho exceeds 1 at every dt
// (a weak instability, rho - 1 ~ dt^2) then has a limit that depends on the horizon; it is
// flagged by `unstable_at_every_dt`.
#pragma once

#include "harness/scenes/scene.hpp"
#include "harness/scenes/stability_probe.hpp"

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <string>

namespace rotbench {

struct StabilityCriterion {
    double horizon = 0;     // s
    double growth = 100.0;  // energy factor
};

// The criterion of every stability measurement (the study, the runs of kind stability,
// advice): energy growth by 1e6 within 1000 periods of the scene's fastest mode.
inline constexpr double stability_horizon_periods = 1000.0;
inline constexpr double stability_growth = 1e6;
// The relative width of the bracket a search stops at.
inline constexpr double stability_tolerance = 0.005;
inline StabilityCriterion stability_criterion(const StabilityProbe& probe) {
    return {stability_horizon_periods * probe.period(), stability_growth};
}

// The criterion on one state: energy `e` past `growth` times the initial `e0`, or not finite.
inline bool energy_blew_up(double e, double e0, const StabilityCriterion& c) { return !std::isfinite(e) || e > c.growth * e0; }

// The boundary of `unstable` (monotone in dt, assumed): bracketed from `dt_guess` by doubling
// or halving, then bisected until the bracket is narrower than `tolerance` (relative); the
// largest dt found stable. 0 when every dt down to dt_guess / 2^halvings is unstable; infinity
// when none up to dt_guess 2^30 is.
double stability_boundary(const std::function<bool(double)>& unstable, double dt_guess, double tolerance, int halvings = 30);

// One run of `steps` = horizon/dt steps from the scene's initial state.
bool unstable_at(const Scene& scene, const std::string& scheme, double dt, const StabilityCriterion& c);

// stability_boundary of runs of the scheme (unstable_at).
double empirical_limit(const Scene& scene, const std::string& scheme, double dt_guess, const StabilityCriterion& c,
                       double tolerance = stability_tolerance);

// The Jacobian of one step of `scheme` about the scene's equilibrium (its initial state at
// rest), by central differences. State per body: position, velocity, rotation vector
// relative to the initial orientation, angular velocity, force, torque (the force and
// torque a scheme reads at the start of a step are state too). Scheme memory is rebuilt
// from this state by the scheme's start(), as at the start of a run: true of every scheme
// whose memory is a function of the state at step boundaries.
struct StepJacobian {
    Eigen::MatrixXd scaled;  // D^-1 J D: J in units of the finite-difference steps
    Eigen::VectorXd scale;   // D
};
StepJacobian step_jacobian(const Scene& scene, const std::string& scheme, double dt);

// The spectral radius of the step map without its rigid-body motions. Bodies that only
// push on each other can translate and rotate together, and do so at any speed: twelve
// neutral directions (eigenvalue 1, defective), which finite differences split by a root
// of their error and which would read as growth. They span an invariant subspace R; the
// eigenvalues that matter are those of the map on the quotient, C^T J C with C an
// orthonormal complement of R. (Measured on sphere_pair with the scaled differences of
// step_jacobian: rho - 1 of a stable scheme is ~1.2e-8 without the projection, 1e-15 to
// 8e-9 with it.)
double spectral_radius(const Scene& scene, const StepJacobian& jacobian);

// The dt where rho(dt)^(2 horizon/dt) reaches `growth`, by the same bracketing and bisection.
double amplification_limit(const Scene& scene, const std::string& scheme, double dt_guess, const StabilityCriterion& c,
                           double tolerance = stability_tolerance);

// rho > 1 + 1e-6 at dt = dt_small: unstable however small the step (in the linearisation).
// 1e-6 is two orders above the finite-difference noise of rho (~1e-8).
bool unstable_at_every_dt(const Scene& scene, const std::string& scheme, double dt_small);

}  // namespace rotbench
