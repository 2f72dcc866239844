// The kinds of run behind run_one (harness/engine/run.hpp), one function each.
#pragma once

#include "harness/engine/run.hpp"

namespace rotbench {

// From t = 0 to t_end: errors against the reference, drifts, cost (harness/engine/run.cpp).
RunResult run_trajectory(const RunSpec& spec, const RunOptions& options);

// Forward to t_end with dt, then back with -dt from where the forward steps ended, the scheme
// keeping its memory: a time-reversible scheme returns to the initial state to round-off.
// Metrics: reversal_angle (rad, largest over the bodies), reversal_omega (|w - w0| / |w0|),
// steps (each way), unstable.
RunResult run_reversal(const RunSpec& spec);

// Bounded energy: the largest energy error over the scene's duration T (energy_drift_first)
// and over energy_horizon x T (energy_drift_horizon), at dt; spec.t_end is T.
RunResult run_horizon(const RunSpec& spec);

// The largest stable dt of the scheme on a stability scene, by bracketing and bisection
// (harness/analysis/stability.hpp). Metrics: dt_empirical, dt_peng, stability_ratio.
RunResult run_stability_search(const RunSpec& spec);

}  // namespace rotbench
