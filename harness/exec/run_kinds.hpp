// The kinds of run behind run_one (harness/exec/run.hpp), one function each.
#pragma once

#include "harness/exec/run.hpp"

#include <functional>
#include <memory>
#include <string>

namespace rotbench {

// What makes the run's scheme: the registry's factory, or a client's replay of its program's
// trajectory (harness/exec/client_run.hpp).
using SchemeFactory = std::function<std::unique_ptr<RotationScheme>()>;
SchemeFactory registered_scheme(const std::string& id);

// From t = 0 to t_end: errors against the reference, drifts, cost (harness/exec/run.cpp).
RunResult run_trajectory(const RunSpec& spec, const RunOptions& options, const SchemeFactory& make);

// Forward to t_end with dt, then back with -dt from where the forward steps ended, the scheme
// keeping its memory: a time-reversible scheme returns to the initial state to round-off.
// Metrics: reversal_angle (rad, largest over the bodies), reversal_omega (|w - w0| / |w0|),
// steps (each way), unstable.
RunResult run_reversal(const RunSpec& spec);

// Bounded energy: the largest energy error over the scene's duration T (energy_drift_first)
// and over energy_horizon x T (energy_drift_horizon), at dt; spec.t_end is T.
RunResult run_horizon(const RunSpec& spec, const SchemeFactory& make);

// The cost of the scheme against direct's on the same scene and dt: the two timed in turn on
// one thread, cost_pairs times, over min(t_end / dt, timing_sample_steps) steps each. Metrics:
// cost_ratio (the median of the pairs' ratios of CPU time) and its 95 % interval cost_ratio_lo,
// cost_ratio_hi; ns_per_step (the scheme's median). timing_samples holds the ratios.
inline constexpr int cost_pairs = 15;
RunResult run_cost(const RunSpec& spec, const SchemeFactory& make);

// The largest stable dt of the scheme on a stability scene, by bracketing and bisection
// (harness/exec/stability.hpp). Metrics: dt_empirical, dt_peng, stability_ratio.
RunResult run_stability_search(const RunSpec& spec);

// The limit of the eigenvalues of the scheme's step map (harness/exec/stability.hpp) on a
// stability scene that can be linearised at rest. Metrics: dt_amplification, unstable_at_every_dt.
RunResult run_amplification(const RunSpec& spec);

// The spectral radius of the step map, undamped, at spectral_points dt from 1/30 to 3 times
// Peng's prediction: series columns dt, rho (rho infinite where the scheme threw).
inline constexpr int spectral_points = 41;
RunResult run_spectral(const RunSpec& spec);

// Body 0's state at every step, or every k-th so that at most options.series_samples + 1 rows
// are kept (harness/exec/export.hpp gives the columns). A run that blows up or throws ends at
// its last finite step, and `failure` says why it stopped.
RunResult run_states(const RunSpec& spec, const RunOptions& options);

}  // namespace rotbench
