// The metric vocabulary (docs/outputs.md): every metric a run can record, its unit, what kind
// of figure it is, its round-off bound and how the report prints it. Names are the CSV
// contract; code names a metric through the constants below, never by a literal.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rotbench {

namespace metric {
#define ROTBENCH_METRIC(id) inline constexpr char id[] = #id;
ROTBENCH_METRIC(omega_rms_x)
ROTBENCH_METRIC(omega_rms_y)
ROTBENCH_METRIC(omega_rms_z)
ROTBENCH_METRIC(omega_err_max)
ROTBENCH_METRIC(orientation_err_max)
ROTBENCH_METRIC(omega_ref_max)
ROTBENCH_METRIC(energy_drift_max)
ROTBENCH_METRIC(energy_drift_rate)
ROTBENCH_METRIC(momentum_drift_max)
ROTBENCH_METRIC(quat_norm_err_max)
ROTBENCH_METRIC(steps)
ROTBENCH_METRIC(force_evals)
ROTBENCH_METRIC(unstable)
ROTBENCH_METRIC(fail_step)
ROTBENCH_METRIC(fail_time)
ROTBENCH_METRIC(cpu_seconds)
ROTBENCH_METRIC(cpu_seconds_min)
ROTBENCH_METRIC(cpu_seconds_max)
ROTBENCH_METRIC(cpu_seconds_run)
ROTBENCH_METRIC(cpu_seconds_per_simulated_second)
ROTBENCH_METRIC(timing_repeats)
ROTBENCH_METRIC(timed_steps)
ROTBENCH_METRIC(ns_per_step)
ROTBENCH_METRIC(rotation_share)
ROTBENCH_METRIC(cost_ratio)
ROTBENCH_METRIC(cost_ratio_lo)
ROTBENCH_METRIC(cost_ratio_hi)
ROTBENCH_METRIC(energy_drift_first)
ROTBENCH_METRIC(energy_drift_horizon)
ROTBENCH_METRIC(reversal_angle)
ROTBENCH_METRIC(reversal_omega)
ROTBENCH_METRIC(dt_empirical)
ROTBENCH_METRIC(dt_peng)
ROTBENCH_METRIC(stability_ratio)
ROTBENCH_METRIC(dt_amplification)
ROTBENCH_METRIC(unstable_at_every_dt)
ROTBENCH_METRIC(counterpart_omega_diff_max)
ROTBENCH_METRIC(counterpart_angle_diff_max)
ROTBENCH_METRIC(client_cpu_seconds)
ROTBENCH_METRIC(client_wall_seconds)
ROTBENCH_METRIC(client_cpu_seconds_per_simulated_second)
ROTBENCH_METRIC(declined)
ROTBENCH_METRIC(ensemble_size)
ROTBENCH_METRIC(ensemble_failed)
#undef ROTBENCH_METRIC
}  // namespace metric

// What a figure is, which decides how it is compared and aggregated.
enum class MetricKind {
    error,      // against the reference; larger is worse
    drift,      // of a conserved quantity or an invariant, relative; larger is worse
    rate,       // a drift per second
    scale,      // the size of the quantity the errors are measured against
    count,      // an integer tally of the run
    flag,       // 0 or 1
    failure,    // where an unstable run stopped
    timing,     // CPU time: the only figures two runs of one command may disagree on
    horizon,    // a horizon run's energy error over the scene's duration and over 8 times it; larger is worse
    reversal,   // how far a forward-then-back run returns from its start; larger is worse
    stability,  // a stability search's limits
    ensemble,   // an ensemble's size and losses
};

const char* kind_name(MetricKind kind);

// How much of a metric round-off alone can make, over a run of N steps (round_off.hpp).
enum class RoundOff {
    none,
    per_step_of_omega,  // 10 eps per step times |w_ref|
    per_step,           // 10 eps per step (1 rad, or 1 for a relative drift)
    momentum,           // (4 N + 16) eps: each step rounds L a few times, measuring it a few more
};

struct MetricInfo {
    std::string_view name, unit;
    MetricKind kind;
    RoundOff round_off = RoundOff::none;
    int fit_rank = 0;               // > 0: its order is fitted (orders.csv), in this order
    bool in_scene_table = false;    // a column of the report's per-scene tables
    bool integer = false;           // printed without decimals
    std::string_view label = {};    // a plot's axis, when it is plotted
    std::string_view meaning = {};  // one line for the report (docs/outputs.md says more)
};

// Every metric, in the order of the report's per-scene tables.
const std::vector<MetricInfo>& metric_table();
// The entry of `name`, or nullptr for a scene's own metric or an ensemble's derived one.
const MetricInfo* find_metric(std::string_view name);

bool is_timing_metric(std::string_view name);
// Errors and drifts: larger is worse, and a change below the round-off floor is no change.
bool is_error_metric(std::string_view name);
// The metrics whose order of convergence is fitted, in the order orders.csv lists them.
const std::vector<std::string>& fitted_metrics();
// How the report prints a value of `name`.
std::string metric_cell(std::string_view name, double value);

}  // namespace rotbench
