// The judges against a baseline (claims.hpp): accuracy, stability, order and cost of new runs
// against the same runs of BASE.
#include "harness/analysis/claims.hpp"

#include "harness/analysis/mann_whitney.hpp"
#include "harness/analysis/median.hpp"
#include "harness/analysis/order_fit.hpp"
#include "harness/analysis/orders.hpp"

#include <cmath>
#include <fmt/format.h>

namespace rotbench {
namespace {

// A relative change as a reader takes it: a percentage up to twice or half, a factor beyond.
std::string change_text(double change) {
    const double ratio = 1.0 + change;
    if (ratio >= 2.0) return fmt::format("{:.3g} times as large", ratio);
    if (ratio > 0.0 && ratio <= 0.5) return fmt::format("{:.3g} times smaller", 1.0 / ratio);
    return fmt::format("{:+.1f} %", 100 * change);
}

std::vector<RunResult> copies(const RunRefs& runs) {
    std::vector<RunResult> out;
    for (const RunResult* r : runs) out.push_back(*r);
    return out;
}

}  // namespace

Judgement judge_baseline_accuracy(const RunPairs& runs, const BaselineTolerances& t) {
    Judgement j;
    j.bound = t.error;
    j.measured = 0;
    std::string worst = "no error grew", improved;
    double best = 0;
    bool claimed_worst = false;  // the headline is the claims' metric's, when it regressed at all
    for (const auto& [b, n] : runs)
        for (const auto& info : metric_table()) {
            const std::string m(info.name);
            if (!is_error_metric(m) || !b->has(m) || !n->has(m)) continue;
            const double before = b->value(m), after = n->value(m);
            if (!std::isfinite(before) || !(after > order_floor)) continue;  // round-off, or judged as stability
            const double change = before > 0 ? (after - before) / before : INFINITY;
            if (before > order_floor && change < best) {  // an improvement, said as one
                best = change;
                improved = fmt::format("{} at dt = {} fell from {} to {} ({})", m, figure(n->spec.dt), figure(before), figure(after), change_text(change));
            }
            // The claims' metric beyond the tolerance takes the headline from any other.
            const bool claimed = m == metric::omega_err_max && change > t.error;
            const bool takes = claimed ? !claimed_worst || change > j.measured : !claimed_worst && change > j.measured;
            if (!takes) continue;
            claimed_worst = claimed_worst || claimed;
            j.measured = change;
            // From round-off, a ratio says nothing: the error is said to have left it.
            worst = before > order_floor
                        ? fmt::format("{} at dt = {} went from {} to {} ({})", m, figure(n->spec.dt), figure(before), figure(after), change_text(change))
                        : fmt::format("{} at dt = {} went from round-off ({}) to {}", m, figure(n->spec.dt), figure(before), figure(after));
        }
    j.passed = j.measured <= t.error;
    if (j.measured == 0 && best < -t.error) worst = "improved: " + improved;
    j.message = fmt::format("{}; a regression is an error up by more than {:g} %", worst, 100 * t.error);
    return j;
}

Judgement judge_baseline_stability(const RunPairs& runs, const BaselineTolerances& t) {
    Judgement j;
    j.passed = true;
    j.message = "no run became unstable or failed";
    for (const auto& [b, n] : runs) {
        if (b->value(metric::unstable) == 0.0 && n->value(metric::unstable) == 1.0) {
            j.passed = false;
            j.message = fmt::format("the run at dt = {} is unstable now ({})", figure(n->spec.dt), n->failure);
            return j;
        }
        // A failed run (or an ensemble every member of which failed) has no errors to compare:
        // it is a regression, never a pass by default. So is a member more that failed.
        const double members_before = b->value(metric::ensemble_failed), members_now = n->value(metric::ensemble_failed);
        if ((b->failure.empty() && !n->failure.empty()) || members_now > members_before) {
            j.passed = false;
            j.message = fmt::format("the run at dt = {} fails now{} ({})", figure(n->spec.dt),
                                    std::isfinite(members_now) ? fmt::format(", {:g} of its members against {:g}", members_now, members_before)
                                                               : "",
                                    n->failure.empty() ? "some members failed" : n->failure);
            return j;
        }
        const double lb = b->value(metric::dt_empirical), ln = n->value(metric::dt_empirical);
        if (std::isfinite(lb) && ln < lb * (1.0 - t.error)) {
            j.passed = false;
            j.measured = ln / lb - 1.0;
            j.message = fmt::format("the stability limit fell from {} s to {} s", figure(lb), figure(ln));
            return j;
        }
    }
    return j;
}

Judgement judge_baseline_order(const RunRefs& base_ladder, const RunRefs& new_ladder, const BaselineTolerances& t) {
    Judgement j;
    j.bound = t.order;
    j.measured = 0;
    j.passed = true;
    std::string text = "no observed order changed beyond its 95 % interval", rose;
    const auto fits_base = observed_orders(copies(base_ladder)), fits_now = observed_orders(copies(new_ladder));
    // Two decimals, or four where two would print the two orders alike.
    const auto order_of = [](const OrderFit& f, const OrderFit& other) {
        const int d = fmt::format("{:.2f}", f.order) == fmt::format("{:.2f}", other.order) ? 4 : 2;
        return fmt::format("{:.{}f} [{:.{}f}, {:.{}f}]", f.order, d, f.order_lo, d, f.order_hi, d);
    };
    for (const auto& fb : fits_base) {
        if (!fb.fit.sufficient) continue;
        const auto fn = std::find_if(fits_now.begin(), fits_now.end(), [&](const OrderRow& o) { return o.metric == fb.metric; });
        if (fn == fits_now.end() || !fn->fit.sufficient) {  // too few runs now, or too few usable ones
            j.passed = false;
            text = fmt::format("the order of {} was {:.2f} and is not measurable now", fb.metric, fb.fit.order);
            continue;
        }
        // A change is one when the two intervals do not overlap; within them it is the fit's noise.
        const double drop = fb.fit.order - fn->fit.order;
        if (fn->fit.order_hi < fb.fit.order_lo && drop > j.measured) {
            j.measured = drop;
            text = fmt::format("the order of {} fell from {} to {}", fb.metric, order_of(fb.fit, fn->fit), order_of(fn->fit, fb.fit));
        }
        if (fn->fit.order_lo > fb.fit.order_hi && rose.empty())
            rose = fmt::format("improved: the order of {} rose from {} to {}", fb.metric, order_of(fb.fit, fn->fit), order_of(fn->fit, fb.fit));
    }
    if (j.measured == 0 && !rose.empty()) text = rose;
    j.passed = j.passed && j.measured <= t.order;
    j.message = fmt::format("{}; a regression is an order down by more than {:g}", text, t.order);
    return j;
}

CostJudgement judge_baseline_cost(const RunPairs& runs, const BaselineTolerances& t) {
    std::vector<double> base, now;
    for (const auto& [b, n] : runs) {
        for (double s : b->timing_samples) base.push_back(s / b->value(metric::steps));
        for (double s : n->timing_samples) now.push_back(s / n->value(metric::steps));
    }
    CostJudgement j;
    j.bound = t.cost;
    j.passed = true;
    const UTest test = mann_whitney(base, now);
    if (base.empty() && now.empty()) {
        j.message = "not timed";
    } else if (!test.valid) {
        j.tested = false;
        j.message = fmt::format("not tested ({} and {} timing repeats; the test needs 5 of each)", base.size(), now.size());
    } else {
        const double ratio = median(now) / median(base);
        j.measured = ratio - 1.0;
        j.passed = !(test.p < t.significance && ratio > 1.0 + t.cost);
        const bool faster = test.p < t.significance && ratio < 1.0 - t.cost;
        j.message = fmt::format("{}median cost per step {:+.1f} % ({} repeats against {}), Mann-Whitney p = {:.3g}; a regression is "
                                "more than {:g} % and p < {:g}",
                                faster ? "improved: " : "", 100 * (ratio - 1.0), now.size(), base.size(), test.p, 100 * t.cost,
                                t.significance);
    }
    return j;
}

}  // namespace rotbench
