#include "harness/analysis/scheme_verdicts.hpp"

#include "harness/analysis/claims.hpp"
#include "harness/analysis/median.hpp"
#include "harness/analysis/round_off.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace rotbench {
namespace {

// omega_err_max over |w_ref| at the scheme's finest stable step on a scene: near 1 when the
// error has saturated, near round-off when it is round-off that does not converge.
double finest_relative_error(const ResultSet& set, const std::string& scene, const std::string& scheme) {
    const RunResult* finest = nullptr;
    for (const auto& r : set.runs)
        if (r.spec.scene == scene && r.spec.scheme == scheme && std::isfinite(r.value(metric::omega_err_max)) &&
            (!finest || r.spec.dt < finest->spec.dt))
            finest = &r;
    return finest ? relative_omega_error(*finest) : NAN;
}

OrderVerdict order_verdict(const ResultSet& set, const std::vector<OrderRow>& orders, const std::string& scheme, bool with_torque) {
    OrderVerdict v;
    if (const SchemeInfo* info = set.scheme(scheme)) {
        v.claimed_order = with_torque ? info->claims.with_torque.order : info->claims.without_torque.order;
        if (!with_torque && info->claims.exact_without_torque) v.claimed = "exact";
        else if (v.claimed_order > 0) v.claimed = std::to_string(v.claimed_order);
    }
    for (const auto& o : orders) {
        if (o.scheme != scheme || o.metric != metric::omega_err_max || !judges_claims(set.scene(o.scene), with_torque)) continue;
        switch (o.status) {
            case OrderStatus::fit:
                ++v.fitted;
                v.lo = std::isnan(v.lo) ? o.fit.order : std::min(v.lo, o.fit.order);
                v.hi = std::isnan(v.hi) ? o.fit.order : std::max(v.hi, o.fit.order);
                break;
            case OrderStatus::exact: ++v.exact; break;
            case OrderStatus::insufficient: ++v.insufficient; break;
            case OrderStatus::no_convergence: {
                ++v.no_convergence;
                const double e = finest_relative_error(set, o.scene, scheme);
                v.stuck_lo = std::isnan(v.stuck_lo) ? e : std::min(v.stuck_lo, e);
                v.stuck_hi = std::isnan(v.stuck_hi) ? e : std::max(v.stuck_hi, e);
                break;
            }
        }
    }
    return v;
}

// The claims module's momentum judge over every torque-free run.
void momentum_verdict(const ResultSet& set, SchemeVerdict& v) {
    RunRefs runs;
    for (const auto& r : set.runs)
        if (r.spec.scheme == v.scheme && r.failure.empty() && judges_claims(set.scene(r.spec.scene), false) &&
            std::isfinite(r.value(metric::momentum_drift_max)))
            runs.push_back(&r), v.momentum_worst = std::max(v.momentum_worst, r.value(metric::momentum_drift_max));
    v.momentum_runs = static_cast<int>(runs.size());
    v.momentum_kept = !runs.empty() && judge_momentum(runs).passed;
}

// Per scene whose energy the claims are judged on: kept when every run's energy error is
// round-off; else the claims module's bounded-energy judge on the scene's horizon run.
void energy_verdict(const ResultSet& set, SchemeVerdict& v) {
    std::map<std::string, std::vector<const RunResult*>> by_scene;
    for (const auto& r : set.runs)
        if (r.spec.scheme == v.scheme && r.failure.empty() && judges_energy(set.scene(r.spec.scene)) &&
            std::isfinite(r.value(metric::energy_drift_max)))
            by_scene[r.spec.scene].push_back(&r);
    if (by_scene.empty()) return;
    bool kept = true, drifting = false, judged = false;
    for (const auto& [scene, runs] : by_scene) {
        if (std::all_of(runs.begin(), runs.end(), [](const RunResult* r) {
                return r->value(metric::energy_drift_max) <= round_off_bound(*r, metric::energy_drift_max);
            }))
            continue;
        kept = false;
        for (const auto& h : set.horizons) {
            if (h.spec.scene != scene || h.spec.scheme != v.scheme) continue;
            judged = true;
            const Judgement j = judge_bounded_energy(h);
            if (!h.failure.empty()) v.energy_failed += (v.energy_failed.empty() ? "" : ", ") + scene;
            else if (j.passed) v.energy_bounded_max = std::max(v.energy_bounded_max, h.value(metric::energy_drift_horizon));
            else drifting = true, v.energy_growth = std::max(v.energy_growth, j.measured);
        }
    }
    v.energy = kept       ? EnergyVerdict::kept
               : !judged  ? EnergyVerdict::none
               : drifting ? EnergyVerdict::drifting
               : !v.energy_failed.empty() ? EnergyVerdict::not_judged
                                          : EnergyVerdict::bounded;
}

// Its claims on the runs of the sweep, by the claims module's judges on the scenes the claims
// module says judge them: the gate's verdicts, on whatever ladder the sweep ran.
void claims_verdict(const ResultSet& set, SchemeVerdict& v) {
    const SchemeInfo* info = set.scheme(v.scheme);
    if (!info || !info->claims.sound) return;
    const SchemeClaims& c = info->claims;
    v.claims_bounded_energy = c.bounded_energy;
    v.claims_anything = c.without_torque.order > 0 || c.with_torque.order > 0 || c.exact_without_torque || c.conserves_momentum ||
                        c.bounded_energy;
    std::map<std::string, RunRefs> ladders;  // scene -> its trajectory runs
    for (const auto& r : set.runs)
        if (r.spec.scheme == v.scheme && r.spec.kind == RunKind::trajectory && r.spec.params.empty())  // the scene itself, not a variant
            ladders[r.spec.scene].push_back(&r);
    const auto judge = [&](const Judgement& j, const std::string& claim, const std::string& scene) {
        ++v.claims_judged;
        if (!j.passed) v.claims_failed.push_back(claim + " on " + scene);
    };
    const auto claims_scene = [](const std::string& scene, bool with_torque) {
        const auto& list = default_claim_scenes(with_torque);
        return std::find(list.begin(), list.end(), scene) != list.end();
    };
    for (const auto& [scene, runs] : ladders) {
        const SceneInfo& info_of = set.scene(scene);
        if (claims_scene(scene, false) && judges_claims(info_of, false)) {
            if (c.without_torque.order > 0 && runs.size() >= 3) judge(judge_order(runs, c.without_torque.order), "order_without_torque", scene);
            if (c.exact_without_torque) judge(judge_exact(runs), "exact_without_torque", scene);
            if (c.conserves_momentum) judge(judge_momentum(runs), "conserves_momentum", scene);
        }
        if (claims_scene(scene, true) && judges_claims(info_of, true) && c.with_torque.order > 0 && runs.size() >= 3)
            judge(judge_order(runs, c.with_torque.order), "order_with_torque", scene);
    }
    if (c.bounded_energy)
        for (const auto& h : set.horizons)
            if (h.spec.scheme == v.scheme && h.spec.params.empty() && claims_scene(h.spec.scene, true) && judges_claims(set.scene(h.spec.scene), true))
                judge(judge_bounded_energy(h), "bounded_energy", h.spec.scene);
}

void stability_verdict(const std::vector<StabilityRow>& stability, SchemeVerdict& v) {
    for (const auto& s : stability) {
        if (s.scheme != v.scheme || s.omega_max != 0) continue;
        const std::string where = fmt::format("{} ζ = {:g}", s.scene, s.zeta);
        if (!s.failure.empty()) {
            v.stability_failed += (v.stability_failed.empty() ? "" : ", ") + where;
            continue;
        }
        const double ratio = s.dt_empirical / s.dt_peng;
        v.stability_lo = std::isnan(v.stability_lo) ? ratio : std::min(v.stability_lo, ratio);
        v.stability_hi = std::isnan(v.stability_hi) ? ratio : std::max(v.stability_hi, ratio);
        if (stability_kind(s) == "weak") v.stability_weak += (v.stability_weak.empty() ? "" : ", ") + where;
    }
}

}  // namespace

std::string cost_scene(const ResultSet& set) {
    if (set.scenes.count("asymmetric_free")) return "asymmetric_free";
    for (const auto& r : set.runs)
        if (set.scene(r.spec.scene).bodies == 1) return r.spec.scene;
    return set.runs.empty() ? "" : set.runs.front().spec.scene;
}

// A client's wall time per step on `scene`, start-up removed: the horizon run less the trajectory
// run at the same dt, over the steps the longer one adds. NaN without both, or for a built-in.
static double client_step_cost(const ResultSet& set, const std::string& scheme, const std::string& scene) {
    const RunResult *trajectory = nullptr, *horizon = nullptr;
    for (const auto& r : set.horizons)
        if (r.spec.scheme == scheme && r.spec.scene == scene && r.failure.empty() && r.has(metric::client_wall_seconds)) horizon = &r;
    if (!horizon) return NAN;
    for (const auto& r : set.runs)
        if (r.spec.scheme == scheme && r.spec.scene == scene && r.spec.kind == RunKind::trajectory && r.spec.dt == horizon->spec.dt &&
            r.failure.empty() && r.has(metric::client_wall_seconds))
            trajectory = &r;
    if (!trajectory) return NAN;
    // The horizon run records no step count: it made the steps of energy_horizon x T.
    const double added = static_cast<double>(step_count(energy_horizon * horizon->spec.t_end, horizon->spec.dt)) -
                         trajectory->value(metric::steps);
    const double seconds = horizon->value(metric::client_wall_seconds) - trajectory->value(metric::client_wall_seconds);
    return added > 0 ? 1e9 * seconds / added : NAN;
}

std::vector<SchemeVerdict> scheme_verdicts(const ResultSet& set, const std::vector<OrderRow>& orders,
                                           const std::vector<StabilityRow>& stability) {
    const std::string cost_on = cost_scene(set);
    std::vector<SchemeVerdict> out;
    for (const auto& r : set.runs) {
        if (std::any_of(out.begin(), out.end(), [&](const SchemeVerdict& v) { return v.scheme == r.spec.scheme; })) continue;
        SchemeVerdict v;
        v.scheme = r.spec.scheme;
        const SchemeInfo* info = set.scheme(v.scheme);
        v.control = info && !info->claims.sound;
        v.free = order_verdict(set, orders, v.scheme, false);
        v.torque = order_verdict(set, orders, v.scheme, true);
        momentum_verdict(set, v);
        claims_verdict(set, v);
        energy_verdict(set, v);
        stability_verdict(stability, v);
        std::vector<double> ns;
        for (const auto& run : set.runs)
            if (run.spec.scheme == v.scheme && run.spec.scene == cost_on && std::isfinite(run.value(metric::ns_per_step)))
                ns.push_back(run.value(metric::ns_per_step));
        v.ns_per_step = median(ns);
        v.client_wall_ns_per_step = client_step_cost(set, v.scheme, cost_on);
        out.push_back(std::move(v));
    }
    return out;
}

double CounterpartVerdict::relative(const RunResult& r) { return r.value(metric::counterpart_omega_diff_max) / r.value(metric::omega_ref_max); }

std::vector<CounterpartVerdict> counterpart_verdicts(const ResultSet& set) {
    // client -> scene -> its runs with a measured difference, by dt
    std::map<std::string, std::map<std::string, std::map<double, const RunResult*>>> found;
    for (const auto& r : set.runs) {
        const SchemeInfo* info = set.scheme(r.spec.scheme);
        if (info && !info->counterpart.empty() && r.has(metric::counterpart_omega_diff_max)) found[r.spec.scheme][r.spec.scene][r.spec.dt] = &r;
    }
    std::vector<CounterpartVerdict> out;
    for (const auto& [client, scenes] : found)
        for (const auto& [scene, by_dt] : scenes) {
            CounterpartVerdict v{client, set.scheme(client)->counterpart, scene, by_dt.rbegin()->second, by_dt.begin()->second};
            RunRefs runs;
            for (const auto& entry : by_dt) runs.push_back(entry.second);
            v.same_map = judge_same_map(runs, v.counterpart).passed;
            if (!v.same_map) {
                v.note = set.scheme(client)->counterpart_note;
                const double c = CounterpartVerdict::relative(*v.coarse), f = CounterpartVerdict::relative(*v.fine);
                if (by_dt.size() > 1 && c > 0 && f > 0) v.order = std::log(c / f) / std::log(v.coarse->spec.dt / v.fine->spec.dt);
            }
            out.push_back(std::move(v));
        }
    return out;
}

SchemeChoice recommend(const std::vector<SchemeVerdict>& verdicts, const std::vector<StabilityRow>& stability) {
    SchemeChoice rec;
    std::vector<const SchemeVerdict*> sorted;
    for (const auto& v : verdicts) sorted.push_back(&v);
    std::stable_sort(sorted.begin(), sorted.end(), [](const SchemeVerdict* a, const SchemeVerdict* b) {
        return (std::isnan(a->ns_per_step) ? INFINITY : a->ns_per_step) < (std::isnan(b->ns_per_step) ? INFINITY : b->ns_per_step);
    });
    for (const SchemeVerdict* v : sorted) {
        if (v->control) {
            rec.avoid.push_back({v->scheme, "a deliberately wrong control"});
            continue;
        }
        // Only what the claims module judged, as the gate judges it: a scheme recommended for its
        // second order claims it, and its claims hold on the runs there are.
        if (v->claims_judged == 0) {
            rec.unjudged.push_back(v->scheme);
            continue;
        }
        std::vector<std::string> why;
        if (v->torque.claimed_order < 2)
            why.push_back(v->torque.claimed_order > 0 ? fmt::format("order {} under an orientation-dependent torque", v->torque.claimed_order)
                                                      : "claims no order under an orientation-dependent torque");
        if (v->free.claimed != "exact" && v->free.claimed_order < 2)
            why.push_back(v->free.claimed_order > 0 ? fmt::format("order {} without torque", v->free.claimed_order)
                                                    : "claims no order without torque");
        if (v->momentum_runs && !v->momentum_kept)
            why.push_back(fmt::format("loses angular momentum without torque (up to {:.1e})", v->momentum_worst));
        if (!v->stability_weak.empty() && v->stability_lo < weak_stability_ratio)
            why.push_back(fmt::format("stable only to {:.2g} of Peng's step on {}", v->stability_lo, v->stability_weak));
        if (!v->claims_failed.empty()) why.push_back(fmt::format("fails its claims: {}", fmt::join(v->claims_failed, ", ")));
        if (!why.empty()) {
            std::string text;
            for (const auto& w : why) text += (text.empty() ? "" : "; ") + w;
            rec.avoid.push_back({v->scheme, text});
        } else if (v->energy == EnergyVerdict::kept || v->energy == EnergyVerdict::bounded) {
            rec.use.push_back(v->scheme);
        } else {
            rec.short_runs.push_back(v->scheme);
        }
    }
    std::map<std::pair<double, std::string>, double> best;  // (ζ, scene) -> the largest ratio of any sound scheme
    for (const auto& s : stability) {
        if (s.omega_max != 0 || !(s.zeta > 0) || !s.failure.empty()) continue;
        const auto v = std::find_if(verdicts.begin(), verdicts.end(), [&](const SchemeVerdict& x) { return x.scheme == s.scheme; });
        if (v != verdicts.end() && v->control) continue;
        double& b = best[{s.zeta, s.scene}];
        b = std::max(b, s.dt_empirical / s.dt_peng);
    }
    for (const auto& [key, ratio] : best) {  // per ζ, the scene where the best scheme falls shortest of Peng's step
        if (!(ratio < 1)) continue;
        if (!rec.peng_unsafe.empty() && rec.peng_unsafe.back().zeta == key.first) {
            if (ratio < rec.peng_unsafe.back().best_ratio) rec.peng_unsafe.back() = {key.first, key.second, ratio};
        } else {
            rec.peng_unsafe.push_back({key.first, key.second, ratio});
        }
    }
    return rec;
}

}  // namespace rotbench
