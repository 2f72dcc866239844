#include "harness/gate/compare.hpp"
#include "harness/analysis/median.hpp"

#include "harness/analysis/mann_whitney.hpp"
#include "harness/analysis/order_fit.hpp"
#include "harness/analysis/orders.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <tuple>

namespace rotbench {
namespace {

// A relative change as a reader takes it: a percentage up to twice or half, a factor beyond.
std::string change_text(double change) {
    const double ratio = 1.0 + change;
    if (ratio >= 2.0) return fmt::format("{:.3g} times as large", ratio);
    if (ratio > 0.0 && ratio <= 0.5) return fmt::format("{:.3g} times smaller", 1.0 / ratio);
    return fmt::format("{:+.1f} %", 100 * change);
}

// Whether a run was timed does not change what it computes: a timed and an untimed run match.
RunSpec key_of(RunSpec s) {
    s.timed = true;
    return s;
}

std::string g(double v) { return fmt::format("{:.3g}", v); }

Verdict verdict(const std::string& id, const std::string& scene, const std::string& scheme, const std::string& where) {
    Verdict v;
    v.of.id = v.of.criterion = id;
    v.of.family = "baseline";
    v.of.scene = scene;
    v.of.scheme = scheme;
    v.of.location = where;
    return v;
}

}  // namespace

double MetricChange::change() const { return base == now ? 0.0 : (now - base) / std::abs(base); }

Comparison compare_runs(const std::vector<RunResult>& base, const std::vector<RunResult>& now, const CompareOptions& o,
                        const std::string& where) {
    Comparison c;
    std::map<RunSpec, const RunResult*> by_key;
    for (const auto& r : base) by_key[key_of(r.spec)] = &r;
    // Per scene and scheme, in the order of the new runs.
    std::vector<std::pair<std::string, std::string>> pairs;
    std::map<std::pair<std::string, std::string>, std::vector<std::pair<const RunResult*, const RunResult*>>> matched;
    std::map<RunSpec, bool> seen;
    for (const auto& r : now) {
        const auto it = by_key.find(key_of(r.spec));
        if (it == by_key.end()) {
            c.notes.push_back(fmt::format("{} {} {} dt={}: not in the baseline", r.spec.scene, r.spec.scheme, kind_name(r.spec.kind),
                                          g(r.spec.dt)));
            continue;
        }
        seen[it->first] = true;
        const auto pair = std::make_pair(r.spec.scene, r.spec.scheme);
        if (!matched.count(pair)) pairs.push_back(pair);
        matched[pair].push_back({it->second, &r});
        for (const auto& [metric, value] : r.metrics)
            if (it->second->has(metric) && !is_timing_metric(metric))
                c.changes.push_back({r.spec, metric, it->second->value(metric), value});
    }
    for (const auto& r : base)
        if (!seen.count(key_of(r.spec)))
            c.notes.push_back(fmt::format("{} {} {} dt={}: in the baseline only", r.spec.scene, r.spec.scheme, kind_name(r.spec.kind),
                                          g(r.spec.dt)));

    if (pairs.empty()) {  // comparing nothing proves nothing
        Verdict none = verdict("baseline_matched", "(any scene)", "(any scheme)", where);
        none.passed = false;
        none.message = fmt::format("no run of the new results is in the baseline ({} new, {} in the baseline): nothing was compared",
                                   now.size(), base.size());
        c.verdicts.push_back(none);
    }
    for (const auto& pair : pairs) {
        const auto& runs = matched[pair];
        const auto& [scene, scheme] = pair;
        // Accuracy: the worst relative increase of an error, above round-off.
        Verdict acc = verdict("baseline_accuracy", scene, scheme, where);
        acc.bound = o.error_tolerance;
        acc.measured = 0;
        std::string worst = "no error grew", improved;
        double best = 0;
        bool claimed_worst = false;  // the headline is the claims' metric's, when it regressed at all
        for (const auto& [b, n] : runs)
            for (const auto& info : metric_table()) {
                const std::string m(info.name);
                if (!is_error_metric(m) || !b->has(m) || !n->has(m)) continue;
                const double before = b->value(m), after = n->value(m);
                if (!std::isfinite(before) || !(after > order_floor)) continue;  // round-off, or compared as stability
                const double change = before > 0 ? (after - before) / before : INFINITY;
                if (before > order_floor && change < best) {  // an improvement, said as one
                    best = change;
                    improved = fmt::format("{} at dt = {} fell from {} to {} ({})", m, g(n->spec.dt), g(before), g(after), change_text(change));
                }
                // The claims' metric beyond the tolerance takes the headline from any other.
                const bool claimed = m == metric::omega_err_max && change > o.error_tolerance;
                const bool takes = claimed ? !claimed_worst || change > acc.measured : !claimed_worst && change > acc.measured;
                if (takes) {
                    claimed_worst = claimed_worst || claimed;
                    acc.measured = change;
                    // From round-off, a ratio says nothing: the error is said to have left it.
                    worst = before > order_floor
                                ? fmt::format("{} at dt = {} went from {} to {} ({})", m, g(n->spec.dt), g(before), g(after), change_text(change))
                                : fmt::format("{} at dt = {} went from round-off ({}) to {}", m, g(n->spec.dt), g(before), g(after));
                }
            }
        acc.passed = acc.measured <= o.error_tolerance;
        if (acc.measured == 0 && best < -o.error_tolerance) worst = "improved: " + improved;
        acc.message = fmt::format("baseline_accuracy on {}: {}; a regression is an error up by more than {:g} %", scene, worst,
                                  100 * o.error_tolerance);
        // Stability: a run that became unstable, or a stability limit that fell.
        Verdict stab = verdict("baseline_stability", scene, scheme, where);
        stab.passed = true;
        stab.message = fmt::format("baseline_stability on {}: no run became unstable or failed", scene);
        for (const auto& [b, n] : runs) {
            if (b->value(metric::unstable) == 0.0 && n->value(metric::unstable) == 1.0) {
                stab.passed = false;
                stab.message = fmt::format("baseline_stability on {}: the run at dt = {} is unstable now ({})", scene, g(n->spec.dt),
                                           n->failure);
                break;
            }
            // A failed run (or an ensemble every member of which failed) has no errors to compare:
            // it is a regression, never a pass by default. So is a member more that failed.
            const double members_before = b->value(metric::ensemble_failed), members_now = n->value(metric::ensemble_failed);
            if ((b->failure.empty() && !n->failure.empty()) || members_now > members_before) {
                stab.passed = false;
                stab.message = fmt::format("baseline_stability on {}: the run at dt = {} fails now{} ({})", scene, g(n->spec.dt),
                                           std::isfinite(members_now) ? fmt::format(", {:g} of its members against {:g}", members_now,
                                                                                    members_before)
                                                                      : "",
                                           n->failure.empty() ? "some members failed" : n->failure);
                break;
            }
            const double lb = b->value(metric::dt_empirical), ln = n->value(metric::dt_empirical);
            if (std::isfinite(lb) && ln < lb * (1.0 - o.error_tolerance)) {
                stab.passed = false;
                stab.measured = ln / lb - 1.0;
                stab.message = fmt::format("baseline_stability on {}: the stability limit fell from {} s to {} s", scene, g(lb), g(ln));
                break;
            }
        }
        // Orders: observed on the same ladders, the worst drop.
        std::vector<RunResult> ladder_base, ladder_now;
        for (const auto& [b, n] : runs)
            if (n->spec.kind == RunKind::trajectory) ladder_base.push_back(*b), ladder_now.push_back(*n);
        Verdict ord = verdict("baseline_order", scene, scheme, where);
        ord.bound = o.order_tolerance;
        ord.measured = 0;
        ord.passed = true;
        std::string order_text = "no observed order changed beyond its 95 % interval", rose;
        const auto fits_base = observed_orders(ladder_base), fits_now = observed_orders(ladder_now);
        // Two decimals, or four where two would print the two orders alike.
        const auto order_of = [](const OrderFit& f, const OrderFit& other) {
            const int d = fmt::format("{:.2f}", f.order) == fmt::format("{:.2f}", other.order) ? 4 : 2;
            return fmt::format("{:.{}f} [{:.{}f}, {:.{}f}]", f.order, d, f.order_lo, d, f.order_hi, d);
        };
        for (const auto& fb : fits_base)
            for (const auto& fn : fits_now) {
                if (fb.metric != fn.metric || fb.scene != fn.scene || !fb.fit.sufficient) continue;
                if (!fn.fit.sufficient) {
                    ord.passed = false;
                    order_text = fmt::format("the order of {} was {:.2f} and is not measurable now", fb.metric, fb.fit.order);
                    continue;
                }
                // A change is one when the two intervals do not overlap; within them it is the fit's noise.
                const double drop = fb.fit.order - fn.fit.order;
                if (fn.fit.order_hi < fb.fit.order_lo && drop > ord.measured) {
                    ord.measured = drop;
                    order_text = fmt::format("the order of {} fell from {} to {}", fb.metric, order_of(fb.fit, fn.fit), order_of(fn.fit, fb.fit));
                }
                if (fn.fit.order_lo > fb.fit.order_hi && rose.empty())
                    rose = fmt::format("improved: the order of {} rose from {} to {}", fb.metric, order_of(fb.fit, fn.fit), order_of(fn.fit, fb.fit));
            }
        if (ord.measured == 0 && !rose.empty()) order_text = rose;
        ord.passed = ord.passed && ord.measured <= o.order_tolerance;
        ord.message = fmt::format("baseline_order on {}: {}; a regression is an order down by more than {:g}", scene, order_text,
                                  o.order_tolerance);
        // Cost: the timing repeats per step, pooled over the runs, tested before they are compared.
        std::vector<double> cost_base, cost_now;
        for (const auto& [b, n] : runs) {
            for (double s : b->timing_samples) cost_base.push_back(s / b->value(metric::steps));
            for (double s : n->timing_samples) cost_now.push_back(s / n->value(metric::steps));
        }
        Verdict cost = verdict("baseline_cost", scene, scheme, where);
        cost.bound = o.cost_tolerance;
        const UTest test = mann_whitney(cost_base, cost_now);
        if (cost_base.empty() && cost_now.empty()) {
            cost.passed = true;
            cost.message = fmt::format("baseline_cost on {}: not timed", scene);
        } else if (!test.valid) {
            cost.passed = true;
            cost.message = fmt::format("baseline_cost on {}: not tested ({} and {} timing repeats; the test needs 5 of each)", scene,
                                       cost_base.size(), cost_now.size());
            c.notes.push_back(cost.message);
        } else {
            const double ratio = median(cost_now) / median(cost_base);
            cost.measured = ratio - 1.0;
            cost.passed = !(test.p < o.significance && ratio > 1.0 + o.cost_tolerance);
            const bool faster = test.p < o.significance && ratio < 1.0 - o.cost_tolerance;
            cost.message = fmt::format("baseline_cost on {}: {}median cost per step {:+.1f} % ({} repeats against {}), Mann-Whitney "
                                       "p = {:.3g}; a regression is more than {:g} % and p < {:g}",
                                       scene, faster ? "improved: " : "", 100 * (ratio - 1.0), cost_now.size(), cost_base.size(), test.p,
                                       100 * o.cost_tolerance, o.significance);
        }
        for (Verdict* v : {&acc, &ord, &stab, &cost}) {
            v->message = scheme + ": " + v->message;
            c.verdicts.push_back(*v);
        }
    }
    return c;
}

std::string compare_csv(const Comparison& c) {
    std::string out = "scene,scheme,kind,dt,metric,base,new,change\n";
    for (const auto& m : c.changes)
        out += csv_record({m.spec.scene, m.spec.scheme, kind_name(m.spec.kind), format_number(m.spec.dt), m.metric,
                           format_number(m.base), format_number(m.now), format_number(m.change())});
    return out;
}

}  // namespace rotbench
