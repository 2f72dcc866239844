#include "harness/core/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

const std::vector<MetricInfo>& metric_table() {
    using K = MetricKind;
    using R = RoundOff;
    // clang-format off
    static const std::vector<MetricInfo> table = {
        {.name = metric::omega_rms_x, .unit = "rad/s", .kind = K::error, .round_off = R::per_step_of_omega, .fit_rank = 3,
         .in_scene_table = true,
         .meaning = "root mean square over all steps of the body-frame angular-velocity error (each solution in its own body "
                    "frame), about body axis x: the seed's Table 1 quantity"},
        {.name = metric::omega_rms_y, .unit = "rad/s", .kind = K::error, .round_off = R::per_step_of_omega, .in_scene_table = true,
         .meaning = "the same about body axis y"},
        {.name = metric::omega_rms_z, .unit = "rad/s", .kind = K::error, .round_off = R::per_step_of_omega, .in_scene_table = true,
         .meaning = "the same about body axis z"},
        {.name = metric::omega_err_max, .unit = "rad/s", .kind = K::error, .round_off = R::per_step_of_omega, .fit_rank = 1,
         .in_scene_table = true, .label = "max |w - w_ref| (rad/s)", .meaning = "max |w - w_ref| over the steps, world frame"},
        {.name = metric::orientation_err_max, .unit = "rad", .kind = K::error, .round_off = R::per_step, .fit_rank = 2,
         .in_scene_table = true, .label = "max angle(q, q_ref) (rad)", .meaning = "max rotation angle between q and q_ref"},
        {.name = metric::energy_drift_max, .unit = "relative", .kind = K::drift, .round_off = R::per_step, .fit_rank = 4,
         .in_scene_table = true, .label = "max |E - E0| / |E0| (relative)",
         .meaning = "max |E - E0| / |E0| (scenes whose true motion conserves energy)"},
        {.name = metric::energy_drift_rate, .unit = "1/s", .kind = K::rate, .in_scene_table = true,
         .meaning = "slope of the least-squares line through the running maximum above: the secular drift"},
        {.name = metric::momentum_drift_max, .unit = "relative", .kind = K::drift, .round_off = R::momentum, .fit_rank = 5,
         .in_scene_table = true, .label = "max |L - L0| / |L0| (relative)",
         .meaning = "max |L - L0| / |L0|, world angular momentum about the origin (torque-free scenes)"},
        {.name = metric::quat_norm_err_max, .kind = K::drift, .in_scene_table = true,
         .meaning = "max ||q| - 1| (round-off only in the schemes that normalise q or keep it unit)"},
        {.name = metric::steps, .kind = K::count, .in_scene_table = true, .integer = true, .meaning = "steps made"},
        {.name = metric::force_evals, .kind = K::count, .in_scene_table = true, .integer = true,
         .meaning = "force and torque evaluations: one per step, plus one at t = 0"},
        {.name = metric::ns_per_step, .unit = "ns", .kind = K::timing, .in_scene_table = true, .integer = true,
         .meaning = "cpu_seconds / steps: the median per-thread CPU time of the run without its metrics and reference, over its "
                    "timing repeats"},
        {.name = metric::unstable, .unit = "0/1", .kind = K::flag, .in_scene_table = true, .integer = true,
         .meaning = "1 when the state became NaN or infinite, the energy of a conservative scene left its bound, or the scheme "
                    "threw; the run stops there and its error metrics are NaN"},
        {.name = metric::omega_ref_max, .unit = "rad/s", .kind = K::scale},
        {.name = metric::fail_step, .kind = K::failure},
        {.name = metric::fail_time, .unit = "s", .kind = K::failure},
        {.name = metric::cpu_seconds, .unit = "s", .kind = K::timing},
        {.name = metric::cpu_seconds_min, .unit = "s", .kind = K::timing},
        {.name = metric::cpu_seconds_max, .unit = "s", .kind = K::timing},
        {.name = metric::cpu_seconds_run, .unit = "s", .kind = K::timing},
        {.name = metric::cpu_seconds_per_simulated_second, .unit = "s/s", .kind = K::timing},
        {.name = metric::timing_repeats, .kind = K::timing},
        {.name = metric::client_cpu_seconds, .unit = "s", .kind = K::timing,
         .meaning = "a client's run: the CPU time of its program and the children it waited for, start-up included"},
        {.name = metric::client_wall_seconds, .unit = "s", .kind = K::timing, .meaning = "a client's run: its program's wall time"},
        {.name = metric::client_cpu_seconds_per_simulated_second, .unit = "s/s", .kind = K::timing,
         .meaning = "a granular client's run: client_cpu_seconds over the simulated time"},
        {.name = metric::declined, .unit = "0/1", .kind = K::flag, .integer = true,
         .meaning = "1 when a client's program declined the run (exit status 3): a scene or parameters it cannot represent; "
                    "skipped, not failed"},
        {.name = metric::timed_steps, .kind = K::count},
        {.name = metric::rotation_share, .kind = K::timing},
        {.name = metric::cost_ratio, .kind = K::timing,
         .meaning = "a cost run's median, over pairs timed in turn, of the scheme's CPU time over direct's on the same steps"},
        {.name = metric::cost_ratio_lo, .kind = K::timing, .meaning = "the lower end of cost_ratio's 95 % interval"},
        {.name = metric::cost_ratio_hi, .kind = K::timing, .meaning = "its upper end"},
        {.name = metric::energy_drift_first, .unit = "relative", .kind = K::horizon},
        {.name = metric::energy_drift_horizon, .unit = "relative", .kind = K::horizon},
        {.name = metric::reversal_angle, .unit = "rad", .kind = K::reversal},
        {.name = metric::reversal_omega, .unit = "relative", .kind = K::reversal},
        {.name = metric::dt_empirical, .unit = "s", .kind = K::stability},
        {.name = metric::dt_peng, .unit = "s", .kind = K::stability},
        {.name = metric::stability_ratio, .kind = K::stability},
        {.name = metric::dt_amplification, .unit = "s", .kind = K::stability},
        {.name = metric::unstable_at_every_dt, .kind = K::flag},
        {.name = metric::counterpart_omega_diff_max, .unit = "rad/s", .kind = K::error, .round_off = R::per_step_of_omega,
         .meaning = "a client's max |w - w_counterpart| over the steps: its largest difference from the built-in scheme it should equal"},
        {.name = metric::counterpart_angle_diff_max, .unit = "rad", .kind = K::error, .round_off = R::per_step,
         .meaning = "a client's max rotation angle between its q and its counterpart's over the steps"},
        {.name = metric::ensemble_size, .kind = K::ensemble},
        {.name = metric::ensemble_failed, .kind = K::ensemble},
    };
    // clang-format on
    return table;
}

const char* kind_name(MetricKind kind) {
    switch (kind) {
        case MetricKind::error:
            return "error";
        case MetricKind::drift:
            return "drift";
        case MetricKind::rate:
            return "rate";
        case MetricKind::scale:
            return "scale";
        case MetricKind::count:
            return "count";
        case MetricKind::flag:
            return "flag";
        case MetricKind::failure:
            return "failure";
        case MetricKind::timing:
            return "timing";
        case MetricKind::horizon:
            return "horizon";
        case MetricKind::reversal:
            return "reversal";
        case MetricKind::stability:
            return "stability";
        case MetricKind::ensemble:
            return "ensemble";
    }
    return "";
}

const MetricInfo* find_metric(std::string_view name) {
    const auto& t = metric_table();
    const auto it = std::find_if(t.begin(), t.end(), [&](const MetricInfo& m) { return m.name == name; });
    return it == t.end() ? nullptr : &*it;
}

bool is_timing_metric(std::string_view name) {
    const MetricInfo* m = find_metric(name);
    return m && m->kind == MetricKind::timing;
}

bool is_error_metric(std::string_view name) {
    const MetricInfo* m = find_metric(name);
    return m && (m->kind == MetricKind::error || m->kind == MetricKind::drift || m->kind == MetricKind::horizon ||
                 m->kind == MetricKind::reversal);
}

const std::vector<std::string>& fitted_metrics() {
    static const std::vector<std::string> fitted = [] {
        std::vector<const MetricInfo*> ranked;
        for (const auto& m : metric_table())
            if (m.fit_rank > 0) ranked.push_back(&m);
        std::sort(ranked.begin(), ranked.end(), [](const MetricInfo* a, const MetricInfo* b) { return a->fit_rank < b->fit_rank; });
        std::vector<std::string> names;
        for (const MetricInfo* m : ranked) names.emplace_back(m->name);
        return names;
    }();
    return fitted;
}

std::string metric_cell(std::string_view name, double value) {
    if (std::isnan(value)) return "—";
    const MetricInfo* m = find_metric(name);
    return m && m->integer ? fmt::format("{:.0f}", value) : fmt::format("{:.3e}", value);
}

}  // namespace rotbench
