#include "reports/verdicts.hpp"

#include "harness/analysis/claims.hpp"
#include "harness/analysis/median.hpp"
#include "harness/analysis/round_off.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

std::vector<std::string> schemes_of(const ResultSet& set) {
    std::vector<std::string> out;
    for (const auto& r : set.runs)
        if (std::find(out.begin(), out.end(), r.spec.scheme) == out.end()) out.push_back(r.spec.scheme);
    return out;
}

bool judged_scene(const SceneInfo& s, bool with_torque) { return with_torque ? judged_with_torque(s) : judged_without_torque(s); }

std::string range(double lo, double hi) {
    return std::abs(hi - lo) < 0.005 ? fmt::format("{:.2f}", lo) : fmt::format("{:.2f}–{:.2f}", lo, hi);
}

// omega_err_max over |w_ref| at the scheme's finest stable step on a scene: near 1 when the
// error has saturated, near round-off when it is round-off that does not converge.
double finest_relative_error(const ResultSet& set, const std::string& scene, const std::string& scheme) {
    const RunResult* finest = nullptr;
    for (const auto& r : set.runs)
        if (r.spec.scene == scene && r.spec.scheme == scheme && std::isfinite(r.value(metric::omega_err_max)) &&
            (!finest || r.spec.dt < finest->spec.dt))
            finest = &r;
    return finest ? finest->value(metric::omega_err_max) / finest->value(metric::omega_ref_max) : NAN;
}

// "claimed → observed" for the angular-velocity error's order over the judged scenes.
std::string order_cell(const ResultSet& set, const std::vector<OrderRow>& orders, const std::string& scheme, bool with_torque) {
    const SchemeInfo* info = set.scheme(scheme);
    std::string claimed = "—";
    if (info) {
        const int order = with_torque ? info->claims.with_torque.order : info->claims.without_torque.order;
        if (!with_torque && info->claims.exact_without_torque) claimed = "exact";
        else if (order > 0) claimed = std::to_string(order);
    }
    double lo = INFINITY, hi = -INFINITY, stuck_lo = INFINITY, stuck_hi = -INFINITY;
    std::map<OrderStatus, int> count;
    for (const auto& o : orders) {
        if (o.scheme != scheme || o.metric != metric::omega_err_max || !judged_scene(set.scene(o.scene), with_torque)) continue;
        ++count[o.status];
        if (o.status == OrderStatus::fit) lo = std::min(lo, o.fit.order), hi = std::max(hi, o.fit.order);
        if (o.status == OrderStatus::no_convergence) {
            const double e = finest_relative_error(set, o.scene, scheme);
            stuck_lo = std::min(stuck_lo, e), stuck_hi = std::max(stuck_hi, e);
        }
    }
    if (count.empty()) return "—";
    std::string observed;
    const auto add = [&](const std::string& part) { observed += (observed.empty() ? "" : "; ") + part; };
    if (count[OrderStatus::fit]) add(range(lo, hi));
    const int scenes = count[OrderStatus::fit] + count[OrderStatus::exact] + count[OrderStatus::insufficient] +
                       count[OrderStatus::no_convergence];
    if (int n = count[OrderStatus::exact]) add(n == scenes ? "exact" : fmt::format("{} exact", n));
    if (int n = count[OrderStatus::no_convergence]) {
        const std::string error = stuck_lo == stuck_hi ? fmt::format("{:.2g}", stuck_lo) : fmt::format("{:.2g}–{:.2g}", stuck_lo, stuck_hi);
        add(fmt::format("{}no convergence (relative error {} at the finest dt)", n == scenes ? "" : fmt::format("{} ", n), error));
    }
    if (int n = count[OrderStatus::insufficient]) add(n == scenes ? "insufficient" : fmt::format("{} insufficient", n));
    return claimed + " → " + observed;
}

std::vector<const RunResult*> torque_free_runs(const ResultSet& set, const std::string& scheme) {
    std::vector<const RunResult*> out;
    for (const auto& r : set.runs)
        if (r.spec.scheme == scheme && r.failure.empty() && judged_scene(set.scene(r.spec.scene), false)) out.push_back(&r);
    return out;
}

// "kept" when the claims module's momentum judge passes on every torque-free run, else the largest drift.
std::string momentum_cell(const ResultSet& set, const std::string& scheme) {
    RunRefs runs;
    double worst = 0;
    for (const RunResult* r : torque_free_runs(set, scheme))
        if (std::isfinite(r->value(metric::momentum_drift_max))) runs.push_back(r), worst = std::max(worst, r->value(metric::momentum_drift_max));
    if (runs.empty()) return "—";
    return judge_momentum(runs).passed ? "kept" : fmt::format("not kept (≤ {:.1e})", worst);
}

// Per scene whose energy the claims are judged on: "kept" when every run's energy error is
// round-off; else the claims module's bounded-energy judge on the scene's horizon run.
std::string energy_cell(const ResultSet& set, const std::string& scheme) {
    std::map<std::string, std::vector<const RunResult*>> by_scene;
    for (const auto& r : set.runs)
        if (r.spec.scheme == scheme && r.failure.empty() && judges_energy(set.scene(r.spec.scene)) &&
            std::isfinite(r.value(metric::energy_drift_max)))
            by_scene[r.spec.scene].push_back(&r);
    if (by_scene.empty()) return "—";
    bool kept = true, drifting = false, judged = false;
    double worst_growth = 0, worst_bounded = 0;
    std::string failed;  // scenes whose horizon run failed: not bounded, and no growth to show
    for (const auto& [scene, runs] : by_scene) {
        const bool scene_kept = std::all_of(runs.begin(), runs.end(), [](const RunResult* r) {
            return r->value(metric::energy_drift_max) <= round_off_bound(*r, metric::energy_drift_max);
        });
        if (scene_kept) continue;
        kept = false;
        for (const auto& h : set.horizons) {
            if (h.spec.scene != scene || h.spec.scheme != scheme) continue;
            judged = true;
            const Judgement j = judge_bounded_energy(h);
            if (!h.failure.empty()) failed += (failed.empty() ? "" : ", ") + scene;
            else if (j.passed) worst_bounded = std::max(worst_bounded, h.value(metric::energy_drift_horizon));
            else drifting = true, worst_growth = std::max(worst_growth, j.measured);
        }
    }
    if (kept) return "kept";
    if (!judged) return "—";
    const std::string failures = failed.empty() ? "" : fmt::format("; failed over {:g} T on {}", energy_horizon, failed);
    if (drifting) return fmt::format("drifting (grew {:.3g}x){}", worst_growth, failures);
    if (!failed.empty()) return "not judged" + failures;
    return fmt::format("bounded (≤ {:.1e})", worst_bounded);
}

std::string stability_cell(const std::vector<StabilityRow>& stability, const std::string& scheme) {
    double lo = INFINITY, hi = 0;
    std::string weak, failed;
    for (const auto& s : stability) {
        if (s.scheme != scheme || s.omega_max != 0) continue;
        if (!s.failure.empty()) {
            failed += fmt::format("{}{} ζ = {:g}", failed.empty() ? "" : ", ", s.scene, s.zeta);
            continue;
        }
        const double ratio = s.dt_empirical / s.dt_peng;
        lo = std::min(lo, ratio), hi = std::max(hi, ratio);
        if (stability_kind(s) == "weak") weak += fmt::format("{}{} ζ = {:g}", weak.empty() ? "" : ", ", s.scene, s.zeta);
    }
    const std::string not_measured = failed.empty() ? "" : " (failed: " + failed + ")";
    if (!(hi > 0)) return "—" + not_measured;
    const std::string r = hi - lo < 0.005 ? fmt::format("{:.2f}", lo) : fmt::format("{:.3g}–{:.3g}", lo, hi);
    return (weak.empty() ? r : r + " (weak: " + weak + ")") + not_measured;
}

}  // namespace

std::string cost_scene(const ResultSet& set) {
    if (set.scenes.count("asymmetric_free")) return "asymmetric_free";
    for (const auto& r : set.runs)
        if (set.scene(r.spec.scene).bodies == 1) return r.spec.scene;
    return set.runs.empty() ? "" : set.runs.front().spec.scene;
}

std::string verdict_section(const ResultSet& set, const std::vector<OrderRow>& orders, const std::vector<StabilityRow>& stability) {
    const std::string cost_on = cost_scene(set);
    std::string md = fmt::format(
        "## Verdicts\n\n"
        "One row per scheme. *Order*: claimed → observed order of the angular-velocity error, over the torque-free scenes "
        "with a reference (*free*) and those with an orientation-dependent torque (*torque*); a range spans the scenes, "
        "\"exact\" is round-off only, and the other statuses are those of `orders.csv`; after \"no convergence\", "
        "the relative error at the scheme's finest step (`{3}` over the largest |w_ref|): near 1 where the error "
        "has saturated, far below it where it is round-off that does not converge. *Momentum*: the world angular "
        "momentum on the torque-free scenes, \"kept\" to round-off ((4 N + 16) eps) or the largest relative drift. "
        "*Energy*: \"kept\" to round-off (10 eps per step) on every scene of either kind that conserves energy, else "
        "judged as the gate judges the bounded-energy claim, on each such scene's horizon run (its coarsest step, over the "
        "scene's duration T and {0:g} T): \"bounded\" (with the largest error over {0:g} T) when the largest energy error "
        "grows at most sqrt({0:g}) = {1:.2f} times from T to {0:g} T (a drift as t^a grows it {0:g}^a times), \"drifting\" "
        "(with the largest growth) when not, \"not judged\" where the horizon run itself failed. *Stability / Peng*: the measured stability "
        "limit over Peng et al.'s prediction on the contact pairs, every damping ratio (below 1: Peng's dt is unsafe). "
        "*ns / step*: **the cost figure of this report**, the median `ns_per_step` of the scheme's runs on `{2}` (one "
        "body; the per-thread CPU time of a run without its metrics over its steps); every CPU time in the report is "
        "this kind of figure, on its own scene.\n\n"
        "| scheme | order, free | order, torque | momentum | energy | stability / Peng | ns / step |\n"
        "|---|---|---|---|---|---|---:|\n",
        energy_horizon, energy_growth_bound, cost_on, metric::omega_err_max);
    for (const auto& scheme : schemes_of(set)) {
        const SchemeInfo* info = set.scheme(scheme);
        std::vector<double> ns;
        for (const auto& r : set.runs)
            if (r.spec.scheme == scheme && r.spec.scene == cost_on && std::isfinite(r.value(metric::ns_per_step))) ns.push_back(r.value(metric::ns_per_step));
        const double cost = median(ns);
        md += fmt::format("| `{}`{} | {} | {} | {} | {} | {} | {} |\n", scheme, info && !info->claims.sound ? " (control)" : "",
                          order_cell(set, orders, scheme, false), order_cell(set, orders, scheme, true), momentum_cell(set, scheme),
                          energy_cell(set, scheme), stability_cell(stability, scheme),
                          std::isfinite(cost) ? fmt::format("{:.0f}", cost) : "—");
    }
    if (stability.empty())
        md += "\nNo stability study in this directory: `rotbench stability --out DIR` writes one beside the runs, and "
              "`rotbench report DIR` then includes it.\n";
    return md + "\n";
}

}  // namespace rotbench
