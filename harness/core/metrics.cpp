#include "harness/core/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

const std::vector<MetricInfo>& metric_table() {
    using K = MetricKind;
    using R = RoundOff;
    static const std::vector<MetricInfo> table = {
        {metric::omega_rms_x,
         "rad/s",
         K::error,
         R::per_step_of_omega,
         3,
         true,
         false,
         {},
         "root mean square over all steps of the body-frame angular-velocity error (each solution in its own body frame), about body axis x: the seed's Table 1 quantity"},
        {metric::omega_rms_y, "rad/s", K::error, R::per_step_of_omega, 0, true, false, {}, "the same about body axis y"},
        {metric::omega_rms_z, "rad/s", K::error, R::per_step_of_omega, 0, true, false, {}, "the same about body axis z"},
        {metric::omega_err_max, "rad/s", K::error, R::per_step_of_omega, 1, true, false, "max |w - w_ref| (rad/s)",
         "max |w - w_ref| over the steps, world frame"},
        {metric::orientation_err_max, "rad", K::error, R::per_step, 2, true, false, "max angle(q, q_ref) (rad)",
         "max rotation angle between q and q_ref"},
        {metric::energy_drift_max, "relative", K::drift, R::per_step, 4, true, false, "max |E - E0| / |E0| (relative)",
         "max |E - E0| / |E0| (scenes whose true motion conserves energy)"},
        {metric::energy_drift_rate,
         "1/s",
         K::rate,
         R::none,
         0,
         true,
         false,
         {},
         "slope of the least-squares line through the running maximum above: the secular drift"},
        {metric::momentum_drift_max, "relative", K::drift, R::momentum, 5, true, false, "max |L - L0| / |L0| (relative)",
         "max |L - L0| / |L0|, world angular momentum about the origin (torque-free scenes)"},
        {metric::quat_norm_err_max,
         "",
         K::drift,
         R::none,
         0,
         true,
         false,
         {},
         "max ||q| - 1| (round-off only in the schemes that normalise q or keep it unit)"},
        {metric::steps, "", K::count, R::none, 0, true, true, {}, "steps made"},
        {metric::force_evals, "", K::count, R::none, 0, true, true, {}, "force and torque evaluations: one per step, plus one at t = 0"},
        {metric::ns_per_step,
         "ns",
         K::timing,
         R::none,
         0,
         true,
         true,
         {},
         "cpu_seconds / steps: the median per-thread CPU time of the run without its metrics and reference, over its timing repeats"},
        {metric::unstable,
         "0/1",
         K::flag,
         R::none,
         0,
         true,
         true,
         {},
         "1 when the state became NaN or infinite, the energy of a conservative scene left its bound, or the scheme threw; the run stops there and its error metrics are NaN"},
        {metric::omega_ref_max, "rad/s", K::scale},
        {metric::fail_step, "", K::failure},
        {metric::fail_time, "s", K::failure},
        {metric::cpu_seconds, "s", K::timing},
        {metric::cpu_seconds_min, "s", K::timing},
        {metric::cpu_seconds_max, "s", K::timing},
        {metric::cpu_seconds_run, "s", K::timing},
        {metric::cpu_seconds_per_simulated_second, "s/s", K::timing},
        {metric::timing_repeats, "", K::timing},
        {metric::timed_steps, "", K::count},
        {metric::rotation_share, "", K::timing},
        {metric::energy_drift_first, "relative", K::horizon},
        {metric::energy_drift_horizon, "relative", K::horizon},
        {metric::reversal_angle, "rad", K::reversal},
        {metric::reversal_omega, "relative", K::reversal},
        {metric::dt_empirical, "s", K::stability},
        {metric::dt_peng, "s", K::stability},
        {metric::stability_ratio, "", K::stability},
        {metric::ensemble_size, "", K::ensemble},
        {metric::ensemble_failed, "", K::ensemble},
    };
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
