#include "harness/analysis/answer.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

const RunResult* coarsest(const std::vector<const RunResult*>& sorted) { return sorted.front(); }

// A run's CPU time scaled to a run of the same duration at `dt`; NaN for a run with no CPU time
// (a client's: its program's cost is its own).
double seconds_at(const RunResult& r, double dt) { return r.value(metric::ns_per_step) * 1e-9 * (r.value(metric::steps) * r.spec.dt) / dt; }

}  // namespace


double interpolated_dt(const RunResult& coarse, const RunResult& fine, double error) {
    const double lc = std::log(relative_omega_error(coarse)), lf = std::log(relative_omega_error(fine));
    const double w = (std::log(error) - lf) / (lc - lf);  // 0 at the fine run, 1 at the coarse
    return std::exp(std::log(fine.spec.dt) + w * (std::log(coarse.spec.dt) - std::log(fine.spec.dt)));
}

LargestDt largest_dt(const std::vector<const RunResult*>& runs, const OrderRow& order, double tolerance) {
    LargestDt a{order.scene, order.scheme, tolerance, "never", NAN, NAN, NAN, ""};
    std::vector<const RunResult*> ok;  // the dt is judged by the errors alone, timed or not
    for (const RunResult* r : runs)
        if (r->failure.empty() && std::isfinite(relative_omega_error(*r))) ok.push_back(r);
    if (ok.empty()) return a;
    std::sort(ok.begin(), ok.end(), [](const RunResult* x, const RunResult* y) { return x->spec.dt > y->spec.dt; });
    const auto set = [&](const char* how, const RunResult& r, double dt) {
        a.how = how, a.dt = dt, a.cpu_seconds = seconds_at(r, dt);
        return a;
    };
    if (order.status == OrderStatus::exact) return set("exact", *coarsest(ok), coarsest(ok)->spec.dt);
    for (std::size_t i = 0; i < ok.size(); ++i) {
        if (!(relative_omega_error(*ok[i]) <= tolerance)) continue;
        if (i == 0) return set("at most", *ok[0], ok[0]->spec.dt);
        return set("interpolated", *ok[i], interpolated_dt(*ok[i - 1], *ok[i], tolerance));
    }
    if (order.status != OrderStatus::fit || order.fit.order <= 0.1) return a;
    const RunResult& finest = *ok.back();
    return set("extrapolated", finest, finest.spec.dt * std::pow(tolerance / relative_omega_error(finest), 1.0 / order.fit.order));
}

std::vector<LargestDt> largest_dts(const ResultSet& set, const std::vector<OrderRow>& orders, const std::vector<double>& tolerances,
                                   const std::vector<StabilityRow>& stability) {
    std::vector<LargestDt> out;
    for (const double tolerance : tolerances)
        for (const auto& o : orders) {
            if (o.metric != metric::omega_err_max) continue;
            std::vector<const RunResult*> runs;
            double omega_ref = 0;
            for (const auto& r : set.runs)
                if (r.spec.scene == o.scene && r.spec.scheme == o.scheme && r.spec.kind == RunKind::trajectory) {
                    runs.push_back(&r);
                    if (r.has(metric::omega_ref_max)) omega_ref = std::max(omega_ref, r.value(metric::omega_ref_max));
                }
            if (omega_ref <= 0) continue;
            LargestDt a = largest_dt(runs, o, tolerance);
            const SceneInfo& scene = set.scene(o.scene);
            for (const auto& s : stability)  // the scene's own limit, at its damping ratio
                if (s.failure.empty() && scene.stability_scene && s.scene == o.scene && s.scheme == o.scheme && s.omega_max == 0 && s.zeta == scene.zeta)
                    a.dt_limit = s.dt_empirical, a.limit_from = fmt::format("stability study, zeta = {:g}", s.zeta);
            if (a.limit_from.empty()) {  // a spin limit: the least dt x w_max measured on fast_spin, over this scene's |w|
                double least = NAN;
                for (const auto& s : stability)
                    if (s.failure.empty() && s.scheme == o.scheme && s.omega_max > 0 && !(s.dt_empirical * s.omega_max >= least))
                        least = s.dt_empirical * s.omega_max;
                if (!std::isnan(least))
                    a.dt_limit = least / omega_ref, a.limit_from = fmt::format("fast_spin: dt w_max = {:.3g}, over |w| = {:.3g} rad/s", least, omega_ref);
            }
            out.push_back(a);
        }
    return out;
}

std::string answer_csv(const std::vector<LargestDt>& answers) {
    std::string csv = "tolerance,scene,scheme,how,dt,cpu_seconds,dt_limit,limit_from\n";
    for (const auto& a : answers)
        csv += csv_record({format_number(a.tolerance), a.scene, a.scheme, a.how, format_number(a.dt), format_number(a.cpu_seconds),
                           format_number(a.dt_limit), a.limit_from});
    return csv;
}

}  // namespace rotbench
