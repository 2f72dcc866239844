// `rotbench advise`: for a user's particle and contact, which schemes meet a tolerance at
// what dt, measured on the scene that stands for it (harness/scenes/particle_contact.cpp):
// the stability limit searched on that scene, a short ladder of runs against the Odeint
// reference for the observed order, and optionally a run at the recommended dt to verify it.
#pragma once

#include "harness/exec/executor.hpp"
#include "harness/scenes/params.hpp"

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

namespace rotbench {

struct Particle {
    Eigen::Vector3d inertia;  // kg m^2, principal moments
    double mass = 0;          // kg
    double stiffness = 0;     // N/m
    double zeta = 0;          // damping ratio
    double omega = 10;        // rad/s, typical spin rate
    double t_end = 0;         // s; 0: advice_default_periods periods of the fastest contact mode
};

inline constexpr double advice_safety = 0.9;   // a recommended dt is at most this times the measured limit
inline constexpr int advice_ladder_rungs = 8;  // 0.9 dt_limit, then halved 7 times
// Errors above this are not yet asymptotic (a phase error of order one saturates): the order
// is fitted on the rungs below it.
inline constexpr double advice_asymptotic_error = 0.1;
// Between rungs the dt is interpolated at this fraction of the tolerance: the rungs are a
// factor 2 apart and their local orders differ by up to ~0.3, which a log-log interpolation
// at the tolerance itself can miss by a few per cent.
inline constexpr double advice_error_margin = 0.8;
inline constexpr int advice_searches = 4;  // runs at an extrapolated dt, at most, when no rung meets the tolerance
inline constexpr double advice_default_periods = 20;  // t_end by default, in periods of the fastest contact mode
inline constexpr double advice_max_steps = 2e6;  // a dt needing more steps over t_end is not recommended (its
                                                 // reference would take ~0.4 GB, and its run seconds)

// The error the rotation scheme is not responsible for: the same scene at the same dt stepped by
// this scheme, whose rotation between the torque kicks is the exact free-body flow. When it is
// at least this fraction of a scheme's error, the contact and the translation, not the rotation
// scheme, make the error at that dt.
inline const std::string advice_exact_rotation = "exact_splitting";
inline constexpr double advice_contact_share = 0.9;

struct Rung {
    double dt = 0, error = 0;  // s; relative angular-velocity error (NaN: unstable or failed)
};

struct Recommendation {
    std::string scheme;
    double dt = 0, dt_stability = 0;  // s
    double stability_ratio = 0;       // dt_stability over Peng's prediction
    std::vector<Rung> ladder;         // every rung run, coarse to fine
    double order = std::numeric_limits<double>::quiet_NaN(), order_lo = order, order_hi = order;  // observed on the ladder
    // The error at dt of advice_exact_rotation, and its share of this scheme's predicted error.
    double exact_rotation_error = std::numeric_limits<double>::quiet_NaN(), contact_share = exact_rotation_error;
    // What sets dt: "stability" (the first rung already meets the tolerance), "contact" (the
    // exact rotation flow errs as much at dt), "rotation" (the rotation scheme's own error), or
    // "unknown" (the exact rotation flow failed at dt).
    std::string limited_by;
    double predicted_error = 0;       // relative angular-velocity error at dt, from the ladder
    std::string how;                  // "stability-bound" or "interpolated" between two measured rungs
    double ns_per_step = 0;           // median over the ladder's runs
    double cpu_seconds = 0;           // per simulated second at dt
    bool verified = false;
    double verified_error = std::numeric_limits<double>::quiet_NaN();
    bool verified_stable = false;
};

struct Advice {
    Particle particle;
    double tolerance = 0, t_end = 0, period = 0, dt_peng = 0;
    ParamOverrides params;                      // of particle_contact
    std::vector<Recommendation> recommendations;  // best (least CPU time per simulated second) first
    std::vector<std::pair<std::string, std::string>> not_recommended;  // scheme, why
    // One sentence on what limits dt across the recommendations, and what they are ranked on.
    std::string verdict;
};

// The scene's parameters for the particle (InputError, one line, for a particle that is not
// one: non-positive or non-finite values, moments that violate the triangle inequality, a
// t_end shorter than one period of the contact).
ParamOverrides particle_params(const Particle& p);

// Every scheme of `schemes` that is sound, in parallel over the executor's jobs; the same numbers
// whatever their number is (timings aside). Interrupted: the executor's signal() is set, and the
// advice is incomplete.
Advice advise(Executor& executor, const Particle& particle, double tolerance, const std::vector<std::string>& schemes, bool verify);

}  // namespace rotbench
