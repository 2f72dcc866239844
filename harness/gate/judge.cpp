// The verdicts of a gate: pure functions of the cases and the results of their runs. Every
// bound is stated in the message with where it comes from.
#include "harness/analysis/order_fit.hpp"
#include "harness/analysis/round_off.hpp"
#include "harness/gate/gate.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
// How far an observed order may lie from the claimed one (docs/gate.md).
constexpr double order_tolerance = 0.2;

std::string g(double v) { return fmt::format("{:.3g}", v); }

using Runs = std::vector<const RunResult*>;

// The first failed run, as a verdict's message; empty when none failed.
std::string failed_run(const Runs& runs) {
    for (const RunResult* r : runs)
        if (!r->failure.empty()) return fmt::format("the run at dt = {} failed: {}", g(r->spec.dt), r->failure);
    return "";
}

std::vector<OrderPoint> points_of(const Runs& runs, std::string_view metric) {
    std::vector<OrderPoint> points;
    for (const RunResult* r : runs) points.push_back({r->spec.dt, r->value(metric)});
    return points;
}

std::string errors_text(const std::vector<OrderPoint>& points) {
    std::string errors;
    for (const auto& p : points) errors += (errors.empty() ? "" : ", ") + g(p.error);
    return errors;
}

// A claimed order p holds when the observed order lies within 0.2 of p and its 95 % interval,
// widened by how far the local orders over the fitted range stray from it, reaches p. The
// t-interval only measures the scatter about a straight line; the next term of the error
// expansion bends the line, and the spread of the local orders is the size of that bend.
void judge_claimed_order(Verdict& v, const Runs& runs) {
    const int p = v.of.claimed_order;
    v.bound = p;
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}; claimed order {}", v.of.id, v.of.scene, f, p);
        return;
    }
    const auto points = points_of(runs, metric::omega_err_max);
    const OrderFit fit = fit_order(points);
    if (!fit.sufficient) {
        v.message = fmt::format("{} on {}: no order could be fitted (errors {} from dt {} to {}: fewer than 3 points in an "
                                "asymptotic range); claimed order {}",
                                v.of.id, v.of.scene, errors_text(points), g(points.front().dt), g(points.back().dt), p);
        return;
    }
    double spread = 0;
    for (const auto& l : fit.local_orders)
        if (l.dt_fine >= fit.dt_min && l.dt_coarse <= fit.dt_max) spread = std::max(spread, std::abs(l.order - fit.order));
    v.measured = fit.order, v.lo = fit.order_lo, v.hi = fit.order_hi;
    const bool close = std::abs(fit.order - p) <= order_tolerance;
    const bool reaches = fit.order_lo - spread <= p && p <= fit.order_hi + spread;
    v.passed = close && reaches;
    v.message = fmt::format("{} on {}: observed order {:.2f} [{:.2f}, {:.2f}] of omega_err_max over dt {} ... {} ({} points), "
                            "claimed {}: {}",
                            v.of.id, v.of.scene, fit.order, fit.order_lo, fit.order_hi, g(fit.dt_max), g(fit.dt_min), fit.points, p,
                            v.passed ? "within 0.2, and the interval reaches it"
                                     : !close ? fmt::format("more than {} away", order_tolerance)
                                              : fmt::format("the interval, widened by the local orders' spread {:.2f}, does not reach it", spread));
}

// At least first order, or exact to round-off: what any scheme that claims nothing must show.
void judge_sanity_order(Verdict& v, const Runs& runs) {
    v.bound = 0.8;
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}", v.of.id, v.of.scene, f);
        return;
    }
    const auto points = points_of(runs, metric::omega_err_max);
    const OrderFit fit = fit_order(points);
    if (fit.sufficient) {
        v.measured = fit.order, v.lo = fit.order_lo, v.hi = fit.order_hi;
        v.passed = fit.order >= 0.8;
        v.message = fmt::format("{} on {}: observed order {:.2f} [{:.2f}, {:.2f}] over dt {} ... {}, required at least 0.8 (a "
                                "consistent scheme converges)",
                                v.of.id, v.of.scene, fit.order, fit.order_lo, fit.order_hi, g(fit.dt_max), g(fit.dt_min));
        return;
    }
    v.message = fmt::format("{} on {}: omega_err_max does not fall as a power of dt (errors {} from dt {} to {}), required an "
                            "order of at least 0.8",
                            v.of.id, v.of.scene, errors_text(points), g(points.front().dt), g(points.back().dt));
}

// The ratio of a measured value to its bound, largest over the runs: the verdict's figure.
struct Worst {
    double ratio = 0, value = 0, bound = 0;
    const RunResult* run = nullptr;
    void add(const RunResult* r, double value_, double bound_) {
        const double q = value_ / bound_;
        if (!run || !(q <= ratio)) ratio = q, value = value_, bound = bound_, run = r;  // NaN is the worst
    }
};

// Round-off only: every error within its round-off bound (harness/analysis/round_off.hpp).
void judge_exact(Verdict& v, const Runs& runs) {
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}", v.of.id, v.of.scene, f);
        return;
    }
    Worst w;
    for (const RunResult* r : runs) {
        w.add(r, r->value(metric::omega_err_max), round_off_bound(*r, metric::omega_err_max));
        w.add(r, r->value(metric::orientation_err_max), round_off_bound(*r, metric::orientation_err_max));
    }
    v.measured = w.value, v.bound = w.bound, v.passed = w.ratio <= 1.0;
    v.message = fmt::format("{} on {}: error {} at dt = {} against the round-off bound {} (N = {} steps x 10 eps, times |w_ref| "
                            "for the angular velocity): {}",
                            v.of.id, v.of.scene, g(w.value), g(w.run->spec.dt), g(w.bound), w.run->value(metric::steps),
                            v.passed ? "round-off only" : "more than round-off");
}

// Angular momentum to round-off (harness/analysis/round_off.hpp).
void judge_momentum(Verdict& v, const Runs& runs) {
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}", v.of.id, v.of.scene, f);
        return;
    }
    Worst w;
    for (const RunResult* r : runs) w.add(r, r->value(metric::momentum_drift_max), round_off_bound(*r, metric::momentum_drift_max));
    v.measured = w.value, v.bound = w.bound, v.passed = w.ratio <= 1.0;
    v.message = fmt::format("{} on {}: momentum drift {} at dt = {}, bound (4 N + 16) eps = {} for N = {} steps: {}", v.of.id,
                            v.of.scene, g(w.value), g(w.run->spec.dt), g(w.bound), w.run->value(metric::steps),
                            v.passed ? "kept to round-off" : "not kept");
}

void judge_sanity_momentum(Verdict& v, const Runs& runs) {
    v.bound = 0.05;
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}", v.of.id, v.of.scene, f);
        return;
    }
    v.measured = runs.front()->value(metric::momentum_drift_max);
    v.passed = v.measured <= v.bound;
    v.message = fmt::format("{} on {}: momentum drift {} at dt = {}, required at most 5 % (a scheme that does not let w' "
                            "precess loses far more)",
                            v.of.id, v.of.scene, g(v.measured), g(runs.front()->spec.dt));
}

// No secular drift: the largest energy error over a run eight times as long. A drift that
// grows as t^a multiplies it by 8^a; a bounded error about 1x. sqrt(8) splits the two.
void judge_bounded_energy(Verdict& v, const Runs& runs) {
    v.bound = std::sqrt(8.0);
    if (const auto f = failed_run(runs); !f.empty()) {
        v.message = fmt::format("{} on {}: {}", v.of.id, v.of.scene, f);
        return;
    }
    const double short_run = runs[0]->value(metric::energy_drift_max), long_run = runs[1]->value(metric::energy_drift_max);
    v.measured = short_run > 0.0 ? long_run / short_run : (long_run > 0.0 ? INFINITY : 1.0);
    v.passed = v.measured <= v.bound;
    v.message = fmt::format("{} on {}: the largest energy error grew {:.3g}x from {} s to {} s at dt = {} ({} to {}); bound "
                            "sqrt(8) = 2.83 (a linear drift grows it 8x, a bounded error about 1x)",
                            v.of.id, v.of.scene, v.measured, g(runs[0]->spec.t_end), g(runs[1]->spec.t_end), g(runs[0]->spec.dt),
                            g(short_run), g(long_run));
}

// Back to the start to round-off: 2 N steps, each rounding every component a few times.
void judge_reversal(Verdict& v, const Runs& runs) {
    const RunResult& r = *runs.front();
    if (!r.failure.empty()) {
        v.message = fmt::format("{} on {}: the reversal run failed: {}", v.of.id, v.of.scene, r.failure);
        return;
    }
    const double n = r.value(metric::steps);
    v.bound = 2.0 * n * 4.0 * eps;
    v.measured = std::max(r.value(metric::reversal_angle), r.value(metric::reversal_omega));
    v.passed = v.measured <= v.bound;
    v.message = fmt::format("{} on {}: after {} steps forward and {} back with -dt = {}, {} rad and {} (relative) from the start; "
                            "bound 2 N x 4 eps = {}",
                            v.of.id, v.of.scene, n, n, g(r.spec.dt), g(r.value(metric::reversal_angle)), g(r.value(metric::reversal_omega)),
                            g(v.bound));
}

// The [[check]] criteria.
void judge_check(Verdict& v, const GateCheck& c, const Runs& runs) {
    v.bound = c.bound;
    const std::string name = fmt::format("{} on {}", c.name, c.scene);
    if (c.criterion == "min_order") {
        if (const auto f = failed_run(runs); !f.empty()) {
            v.message = name + ": " + f;
            return;
        }
        const auto points = points_of(runs, c.metric);
        const OrderFit fit = fit_order(points);
        double worst = 0;
        for (const auto& p : points) worst = std::max(worst, std::isnan(p.error) ? INFINITY : p.error);
        if (fit.sufficient) {
            v.measured = fit.order, v.lo = fit.order_lo, v.hi = fit.order_hi;
            v.passed = fit.order >= c.bound;
            v.message = fmt::format("{}: observed order {:.2f} [{:.2f}, {:.2f}] of {} over dt {} ... {} ({} points), required >= {}",
                                    name, fit.order, fit.order_lo, fit.order_hi, c.metric, g(fit.dt_max), g(fit.dt_min), fit.points,
                                    g(c.bound));
        } else if (worst <= c.round_off) {
            v.measured = INFINITY;
            v.passed = true;
            v.message = fmt::format("{}: exact to round-off: every {} is at most {} (<= round_off {})", name, c.metric, g(worst),
                                    g(c.round_off));
        } else {
            v.message = fmt::format("{}: no order: {} does not fall as a power of dt (errors {} from dt {} to {}), required >= {}",
                                    name, c.metric, errors_text(points), g(points.front().dt), g(points.back().dt), g(c.bound));
        }
        return;
    }
    const RunResult& r = *runs.front();
    if (!r.failure.empty()) {
        v.message = name + ": the run failed: " + r.failure;
        return;
    }
    if (c.criterion == "min_stability") {
        v.measured = r.value(metric::stability_ratio);
        v.passed = v.measured >= c.bound;
        v.message = fmt::format("{}: measured limit {} s = {} x Peng's prediction {} s, required >= {}", name, g(r.value(metric::dt_empirical)),
                                g(v.measured), g(r.value(metric::dt_peng)), g(c.bound));
    } else if (c.criterion == "max_cost_ratio") {
        const RunResult& direct = *runs[1];
        v.measured = r.value(metric::ns_per_step) / direct.value(metric::ns_per_step);
        v.passed = v.measured <= c.bound;
        v.message = std::isnan(v.measured) ? name + ": no timing (a run failed)"
                                           : fmt::format("{}: {} ns per step against {} for direct: ratio {}, required <= {}", name,
                                                         g(r.value(metric::ns_per_step)), g(direct.value(metric::ns_per_step)), g(v.measured), g(c.bound));
    } else {
        v.measured = r.value(c.metric);
        if (std::isnan(v.measured)) {
            v.message = fmt::format("{}: scene '{}' has no {}", name, c.scene, c.metric);
            return;
        }
        v.passed = v.measured <= c.bound;
        v.message = fmt::format("{}: {} = {} at dt = {}, required <= {}", name, c.metric, g(v.measured), g(r.spec.dt), g(c.bound));
    }
}

}  // namespace

std::string Verdict::outcome() const {
    if (of.expected_to_fail) return passed ? "unexpected pass" : "expected failure";
    return passed ? "pass" : "fail";
}

bool GateResult::passed() const {
    return std::all_of(verdicts.begin(), verdicts.end(), [](const Verdict& v) { return v.ok(); });
}

std::size_t GateResult::count(const std::string& outcome) const {
    return static_cast<std::size_t>(
        std::count_if(verdicts.begin(), verdicts.end(), [&](const Verdict& v) { return v.outcome() == outcome; }));
}

GateResult judge_gate(const GateFile& file, const GatePlan& plan, std::vector<RunResult> runs) {
    GateResult result;
    result.warnings = plan.warnings;
    for (const GateCase& c : plan.cases) {
        Verdict v;
        v.of = c;
        Runs used;
        for (std::size_t i : c.runs) {
            used.push_back(&runs.at(i));
            const double s = runs[i].value(metric::cpu_seconds_run);
            if (std::isfinite(s)) v.seconds += s;
        }
        if (c.family == "check") judge_check(v, file.checks.at(c.check), used);
        else if (c.id == "order_without_torque" || c.id == "order_with_torque") judge_claimed_order(v, used);
        else if (c.id == "exact_without_torque") judge_exact(v, used);
        else if (c.id == "conserves_momentum") judge_momentum(v, used);
        else if (c.id == "bounded_energy") judge_bounded_energy(v, used);
        else if (c.id == "time_reversible") judge_reversal(v, used);
        else if (c.id == "sanity_order") judge_sanity_order(v, used);
        else if (c.id == "sanity_momentum") judge_sanity_momentum(v, used);
        v.message = v.of.scheme + ": " + v.message;
        result.verdicts.push_back(std::move(v));
    }
    result.runs = std::move(runs);
    return result;
}

}  // namespace rotbench
