#include "harness/analysis/claims.hpp"

#include "harness/analysis/order_fit.hpp"
#include "harness/analysis/round_off.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

std::string figure(double v) { return fmt::format("{:.3g}", v); }

namespace {

// The first failed run, as a judgement's message; empty when none failed.
std::string failed_run(const RunRefs& runs) {
    for (const RunResult* r : runs)
        if (!r->failure.empty()) return fmt::format("the run at dt = {} failed: {}", figure(r->spec.dt), r->failure);
    return "";
}

std::vector<OrderPoint> points_of(const RunRefs& runs, std::string_view name = metric::omega_err_max) {
    std::vector<OrderPoint> points;
    for (const RunResult* r : runs) points.push_back({r->spec.dt, r->value(name)});
    return points;
}

std::string errors_text(const std::vector<OrderPoint>& points) {
    std::string errors;
    for (const auto& p : points) errors += (errors.empty() ? "" : ", ") + figure(p.error);
    return errors;
}

// The metrics of every run against their round-off bounds (round_off.hpp): the judgement's
// figure is the value with the largest ratio to its bound (NaN is the worst), `run` its run.
struct RoundOffJudgement {
    Judgement j;
    const RunResult* run = nullptr;
};
RoundOffJudgement within_round_off(const RunRefs& runs, std::initializer_list<const char*> metrics) {
    RoundOffJudgement out;
    if (const auto f = failed_run(runs); !f.empty()) {
        out.j.message = f;
        return out;
    }
    double worst = 0;
    for (const RunResult* r : runs)
        for (const char* m : metrics) {
            const double value = r->value(m), bound = round_off_bound(*r, m), ratio = value / bound;
            const bool worse = !out.run || std::isnan(ratio) || (!std::isnan(worst) && ratio > worst);
            if (worse) worst = ratio, out.j.measured = value, out.j.bound = bound, out.run = r;
        }
    out.j.passed = out.run && worst <= 1.0;
    if (!out.run) out.j.message = "no run to judge";
    return out;
}

Judgement bounded_energy(double early, double late, const std::string& where) {
    Judgement j;
    j.bound = energy_growth_bound;
    j.measured = early > 0.0 ? late / early : (late > 0.0 ? INFINITY : 1.0);
    j.passed = j.measured <= j.bound;
    j.message = fmt::format(
        "the largest energy error grew {:.3g}x {} ({} to {}); bound sqrt({:g}) = {:.2f} (a linear drift grows "
        "it {:g}x, a bounded error about 1x)",
        j.measured, where, figure(early), figure(late), energy_horizon, j.bound, energy_horizon);
    return j;
}

}  // namespace

bool judges_claims(const SceneInfo& scene, bool with_torque) {
    if (scene.reference == Scene::ReferenceKind::none) return false;
    return with_torque ? scene.torque_depends_on_orientation && scene.conserves_energy : scene.conserves_angular_momentum;
}

bool judges_energy(const SceneInfo& scene) { return scene.conserves_energy && (judges_claims(scene, false) || judges_claims(scene, true)); }

RunSpec horizon_run(const RunSpec& coarsest) {
    RunSpec spec = coarsest;
    spec.kind = RunKind::horizon;
    spec.timed = false;
    return spec;
}

// The 95 % interval, widened by how far the local orders over the fitted range stray from the
// order, must reach p: the t-interval only measures the scatter about a straight line, and the
// next term of the error expansion bends the line by about that spread.
Judgement judge_order(const RunRefs& ladder, int claimed) {
    Judgement j;
    j.bound = claimed;
    if (const auto f = failed_run(ladder); !f.empty()) {
        j.message = fmt::format("{}; claimed order {}", f, claimed);
        return j;
    }
    const auto points = points_of(ladder);
    const OrderFit fit = fit_order(points);
    if (!fit.sufficient) {
        j.message = fmt::format(
            "no order could be fitted (errors {} from dt {} to {}: fewer than 3 points in an asymptotic range); "
            "claimed order {}",
            errors_text(points), figure(points.front().dt), figure(points.back().dt), claimed);
        return j;
    }
    double spread = 0;
    for (const auto& l : fit.local_orders)
        if (l.dt_fine >= fit.dt_min && l.dt_coarse <= fit.dt_max) spread = std::max(spread, std::abs(l.order - fit.order));
    j.measured = fit.order, j.lo = fit.order_lo, j.hi = fit.order_hi;
    const bool close = std::abs(fit.order - claimed) <= order_tolerance;
    const bool reaches = fit.order_lo - spread <= claimed && claimed <= fit.order_hi + spread;
    j.passed = close && reaches;
    j.message = fmt::format("observed order {:.2f} [{:.2f}, {:.2f}] of {} over dt {} ... {} ({} points), claimed {}: {}", fit.order,
                            fit.order_lo, fit.order_hi, metric::omega_err_max, figure(fit.dt_max), figure(fit.dt_min), fit.points, claimed,
                            j.passed ? fmt::format("within {}, and the interval reaches it", order_tolerance)
                            : !close ? fmt::format("more than {} away", order_tolerance)
                                     : fmt::format("the interval, widened by the local orders' spread {:.2f}, does not reach it", spread));
    return j;
}

Judgement judge_sanity_order(const RunRefs& ladder) {
    Judgement j;
    j.bound = sanity_min_order;
    if (const auto f = failed_run(ladder); !f.empty()) {
        j.message = f;
        return j;
    }
    const auto points = points_of(ladder);
    const OrderFit fit = fit_order(points);
    if (fit.sufficient) {
        j.measured = fit.order, j.lo = fit.order_lo, j.hi = fit.order_hi;
        j.passed = fit.order >= sanity_min_order;
        j.message = fmt::format(
            "observed order {:.2f} [{:.2f}, {:.2f}] over dt {} ... {}, required at least {} (a consistent scheme "
            "converges)",
            fit.order, fit.order_lo, fit.order_hi, figure(fit.dt_max), figure(fit.dt_min), sanity_min_order);
        return j;
    }
    j.message = fmt::format("{} does not fall as a power of dt (errors {} from dt {} to {}), required an order of at least {}",
                            metric::omega_err_max, errors_text(points), figure(points.front().dt), figure(points.back().dt), sanity_min_order);
    return j;
}

Judgement judge_min_order(const RunRefs& ladder, const std::string& name, double min_order, double round_off) {
    Judgement j;
    j.bound = min_order;
    if (const auto f = failed_run(ladder); !f.empty()) {
        j.message = f;
        return j;
    }
    const auto points = points_of(ladder, name);
    const OrderFit fit = fit_order(points);
    double worst = 0;
    for (const auto& p : points) worst = std::max(worst, std::isnan(p.error) ? INFINITY : p.error);
    if (fit.sufficient) {
        j.measured = fit.order, j.lo = fit.order_lo, j.hi = fit.order_hi;
        j.passed = fit.order >= min_order;
        j.message = fmt::format("observed order {:.2f} [{:.2f}, {:.2f}] of {} over dt {} ... {} ({} points), required >= {}", fit.order,
                                fit.order_lo, fit.order_hi, name, figure(fit.dt_max), figure(fit.dt_min), fit.points, figure(min_order));
    } else if (worst <= round_off) {
        j.measured = INFINITY;
        j.passed = true;
        j.message = fmt::format("exact to round-off: every {} is at most {} (<= round_off {})", name, figure(worst), figure(round_off));
    } else {
        j.message = fmt::format("no order: {} does not fall as a power of dt (errors {} from dt {} to {}), required >= {}", name,
                                errors_text(points), figure(points.front().dt), figure(points.back().dt), figure(min_order));
    }
    return j;
}

Judgement judge_exact(const RunRefs& runs) {
    auto [j, run] = within_round_off(runs, {metric::omega_err_max, metric::orientation_err_max});
    if (run)
        j.message = fmt::format(
            "error {} at dt = {} against the round-off bound {} (N = {} steps x 10 eps, times |w_ref| for the "
            "angular velocity): {}",
            figure(j.measured), figure(run->spec.dt), figure(j.bound), run->value(metric::steps), j.passed ? "round-off only" : "more than round-off");
    return j;
}

Judgement judge_momentum(const RunRefs& runs) {
    auto [j, run] = within_round_off(runs, {metric::momentum_drift_max});
    if (run)
        j.message = fmt::format("momentum drift {} at dt = {}, bound (4 N + 16) eps = {} for N = {} steps: {}", figure(j.measured),
                                figure(run->spec.dt), figure(j.bound), run->value(metric::steps), j.passed ? "kept to round-off" : "not kept");
    return j;
}

const std::vector<std::string>& default_claim_scenes(bool with_torque) {
    static const std::vector<std::string> free = {"asymmetric_free", "tumbling_brick"}, torque = {"dipole_top"};
    return with_torque ? torque : free;
}

Judgement judge_same_map(const RunRefs& runs, const std::string& counterpart) {
    auto [j, run] = within_round_off(runs, {metric::counterpart_omega_diff_max, metric::counterpart_angle_diff_max});
    if (run && std::isnan(j.measured)) {
        j.passed = false;
        j.message = fmt::format("no difference from {} measured at dt = {} (the client file names no counterpart?)", counterpart, figure(run->spec.dt));
    } else if (run) {
        j.message = fmt::format("largest difference from {} {} at dt = {} against the round-off bound {} (N = {} steps x 10 eps, "
                                "times |w_ref| for the angular velocity): {}",
                                counterpart, figure(j.measured), figure(run->spec.dt), figure(j.bound), run->value(metric::steps),
                                j.passed ? "the same map" : "another map");
    }
    return j;
}

Judgement judge_sanity_momentum(const RunResult& run) {
    Judgement j;
    j.bound = sanity_max_momentum_drift;
    if (const auto f = failed_run({&run}); !f.empty()) {
        j.message = f;
        return j;
    }
    j.measured = run.value(metric::momentum_drift_max);
    j.passed = j.measured <= j.bound;
    j.message = fmt::format(
        "momentum drift {} at dt = {}, required at most {:g} % (a scheme that does not let w' precess loses far "
        "more)",
        figure(j.measured), figure(run.spec.dt), 100 * sanity_max_momentum_drift);
    return j;
}

Judgement judge_bounded_energy(const RunResult& run) {
    if (!run.failure.empty()) {
        Judgement j;
        j.bound = energy_growth_bound;
        j.message = fmt::format("the run at dt = {} failed: {}", figure(run.spec.dt), run.failure);
        return j;
    }
    return bounded_energy(
        run.value(metric::energy_drift_first), run.value(metric::energy_drift_horizon),
        fmt::format("from {} s to {} s at dt = {}", figure(run.spec.t_end), figure(energy_horizon * run.spec.t_end), figure(run.spec.dt)));
}

Judgement judge_reversal(const RunResult& run) {
    Judgement j;
    if (!run.failure.empty()) {
        j.message = "the reversal run failed: " + run.failure;
        return j;
    }
    const double n = run.value(metric::steps);
    j.bound = 2.0 * n * 4.0 * unit_round_off;
    j.measured = std::max(run.value(metric::reversal_angle), run.value(metric::reversal_omega));
    j.passed = j.measured <= j.bound;
    j.message = fmt::format(
        "after {} steps forward and {} back with -dt = {}, {} rad and {} (relative) from the start; bound 2 N x 4 "
        "eps = {}",
        n, n, figure(run.spec.dt), figure(run.value(metric::reversal_angle)), figure(run.value(metric::reversal_omega)), figure(j.bound));
    return j;
}

Judgement judge_stability_margin(const RunResult& search, double min_ratio) {
    Judgement j;
    j.bound = min_ratio;
    j.measured = search.value(metric::stability_ratio);
    j.passed = j.measured >= min_ratio;
    j.message = fmt::format("measured limit {} s = {} x Peng's prediction {} s, required >= {}", figure(search.value(metric::dt_empirical)),
                            figure(j.measured), figure(search.value(metric::dt_peng)), figure(min_ratio));
    return j;
}

Judgement judge_cost_ratio(const RunResult& cost, double max_ratio) {
    Judgement j;
    j.bound = max_ratio;
    j.measured = cost.value(metric::cost_ratio);
    j.lo = cost.value(metric::cost_ratio_lo), j.hi = cost.value(metric::cost_ratio_hi);
    // Failed only when the whole interval lies above the bound: one slow stretch of a loaded
    // machine moves a few pairs, not the median's interval.
    j.passed = !std::isnan(j.measured) && !(j.lo > max_ratio);
    j.message = std::isnan(j.measured)
                    ? "no timing (the run failed)"
                    : fmt::format("CPU time per step {} x direct's (95 % interval {}-{}, {} pairs timed in turn), required <= {}{}",
                                  figure(j.measured), figure(j.lo), figure(j.hi), cost.value(metric::timing_repeats), figure(max_ratio),
                                  j.passed ? "" : ": the whole interval is above");
    return j;
}

}  // namespace rotbench
