// A run's identity and its result: the key every layer above speaks (docs/outputs.md).
#pragma once

#include "harness/core/metrics.hpp"
#include "harness/scenes/params.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotbench {

// What a run measures (docs/outputs.md):
//   trajectory     the scheme steps the scene from t = 0 to t_end: errors, drifts, cost;
//   reversal       it steps forward to t_end and then back with -dt: how far from the
//                  initial state it returns (time reversibility);
//   stability      the largest dt at which it stays stable on a stability scene (dt unused);
//   horizon        it steps the scene over its duration T and over energy_horizon x T: how far
//                  its energy error grows (bounded energy);
//   amplification  on a stability scene linearised at rest: the dt where the eigenvalues of its
//                  step map reach the stability criterion, and whether it is unstable at every dt;
//   spectral       on such a scene: the spectral radius of its step map against dt (a series);
//   states         its states at up to RunOptions::series_samples + 1 instants (a series: the
//                  trajectory export);
//   cost           it and direct timed in turn on the same steps: the ratio of their costs.
enum class RunKind { trajectory, reversal, stability, horizon, amplification, spectral, states, cost };
inline constexpr double energy_horizon = 8.0;
const char* kind_name(RunKind kind);
RunKind kind_from_name(const std::string& name);  // InputError for an unknown one
// The stability study's kinds, which search or sweep dt themselves: their spec's dt is 0.
inline bool finds_its_own_dt(RunKind kind) {
    return kind == RunKind::stability || kind == RunKind::amplification || kind == RunKind::spectral;
}

struct RunSpec {
    std::string scene;
    std::string scheme;
    double dt = 0.0;
    double t_end = 0.0;     // 0: the scene's default
    ParamOverrides params;  // scene parameters other than t_end, as given by the user
    RunKind kind = RunKind::trajectory;
    bool timed = true;  // false: no timing repeats (the gate's accuracy runs)

    // A run's identity: two specs that compare equal make the same run.
    friend auto operator<=>(const RunSpec&, const RunSpec&) = default;
};

// What a run computes, its identity without `timed`: a timed and an untimed run give the same
// results (compare and merge match runs by it).
inline RunSpec computed_key(RunSpec spec) {
    spec.timed = true;
    return spec;
}

struct RunResult {
    RunSpec spec;
    std::vector<std::pair<std::string, double>> metrics;  // names are the CSV contract
    std::string failure;                                  // empty, or why the run stopped early
    bool interrupted = false;                             // SIGINT or SIGTERM stopped it: not a result
    // Energy against time, when asked for: columns t, energy_error ((E - E0)/|E0|), then
    // the scene's energy parts by name. Or a granular scene's curve (SceneProbe::curve), which
    // an ensemble's result holds as a band: each y column's mean, then y_min and y_max.
    std::vector<std::string> series_columns;
    std::vector<std::vector<double>> series;
    // A granular scene's pictures (SceneProbe::snapshots): rows t, x, y, z, radius.
    std::vector<std::vector<double>> snapshots;
    std::vector<std::vector<double>> walls;  // the walls at the same instants: rows t, x0, z0, x1, z1
    // The CPU time of each timing repeat, scaled to the whole run as cpu_seconds is: the
    // samples `rotbench compare` tests a cost change against.
    std::vector<double> timing_samples;

    bool has(std::string_view name) const;
    bool has_energy_series() const { return is_energy_series(series_columns); }
    // A client's program declined the run (docs/clients.md): skipped, not failed.
    bool declined() const { return value(metric::declined) == 1.0; }
    // An energy series' columns (t, energy_error, ...), not a granular curve's.
    static bool is_energy_series(const std::vector<std::string>& columns) { return columns.size() >= 2 && columns[1] == "energy_error"; }
    double value(std::string_view name) const;  // NaN when absent
};

// A run of more steps than this is timed on a sample of its own trajectory of this many steps
// (32 evenly spaced stretches, run.cpp); a shorter run is timed whole.
inline constexpr std::int64_t timing_sample_steps = 10000;

// Number of steps for a duration: t_end / dt rounded to the nearest integer when it is
// one to within 1e-9 relative, otherwise rounded up, so a run never stops short of t_end.
// Throws InputError when dt <= 0, t_end <= 0, either is not finite, or t_end < dt.
std::int64_t step_count(double t_end, double dt);

// Blow-up rule: a run is unstable when any state component is NaN or infinite, or when
// its energy E departs from E0 by more than 1e6 times the initial energy scale (max of
// |E0| and the initial kinetic energy): either way in a conservative scene, upwards in a
// damped one. Energy that a scene's physics feeds in (an applied torque) is never taken
// for a blow-up. The run stops at that step (fail_step, fail_time); its error metrics are NaN.
inline constexpr double blowup_energy_factor = 1e6;

// The relative angular-velocity error every tolerance is on: omega_err_max / omega_ref_max, the
// largest error over the run against the largest |w_ref| (NaN without a reference).
double relative_omega_error(const RunResult& r);

}  // namespace rotbench
