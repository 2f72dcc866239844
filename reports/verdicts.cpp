#include "reports/verdicts.hpp"

#include "harness/analysis/claims.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rotbench {
namespace {

std::string range(double lo, double hi) {
    return std::abs(hi - lo) < 0.005 ? fmt::format("{:.2f}", lo) : fmt::format("{:.2f}–{:.2f}", lo, hi);
}

// "claimed → observed" for the angular-velocity error's order over the judged scenes.
std::string order_cell(const OrderVerdict& v) {
    const int scenes = v.scenes();
    if (scenes == 0) return "—";
    std::string observed;
    const auto add = [&](const std::string& part) { observed += (observed.empty() ? "" : "; ") + part; };
    if (v.fitted) add(range(v.lo, v.hi));
    if (v.exact) add(v.exact == scenes ? "exact" : fmt::format("{} exact", v.exact));
    if (v.no_convergence) {
        const std::string error = v.stuck_lo == v.stuck_hi ? fmt::format("{:.2g}", v.stuck_lo) : fmt::format("{:.2g}–{:.2g}", v.stuck_lo, v.stuck_hi);
        add(fmt::format("{}no convergence (relative error {} at the finest dt)", v.no_convergence == scenes ? "" : fmt::format("{} ", v.no_convergence), error));
    }
    if (v.insufficient) add(v.insufficient == scenes ? "insufficient" : fmt::format("{} insufficient", v.insufficient));
    return v.claimed + " → " + observed;
}

std::string momentum_cell(const SchemeVerdict& v) {
    if (v.momentum_runs == 0) return "—";
    return v.momentum_kept ? "kept" : fmt::format("not kept (≤ {:.1e})", v.momentum_worst);
}

std::string energy_cell(const SchemeVerdict& v) {
    const std::string failures = v.energy_failed.empty() ? "" : fmt::format("; failed over {:g} T on {}", energy_horizon, v.energy_failed);
    switch (v.energy) {
        case EnergyVerdict::none: return "—";
        case EnergyVerdict::kept: return "kept";
        case EnergyVerdict::drifting:
            return fmt::format("drifting (grew {:.3g}x){}{}", v.energy_growth, v.claims_bounded_energy ? "" : ", not claimed", failures);
        case EnergyVerdict::not_judged: return "not judged" + failures;
        case EnergyVerdict::bounded: return fmt::format("bounded (≤ {:.1e})", v.energy_bounded_max);
    }
    return "—";
}

std::string claims_cell(const SchemeVerdict& v) {
    if (v.control) return "control";
    if (!v.claims_anything) return "nothing claimed";
    if (v.claims_judged == 0) return "not judged here";
    if (v.claims_failed.empty()) return "yes";
    return "**no**: " + fmt::format("{}", fmt::join(v.claims_failed, "; "));
}

std::string stability_cell(const SchemeVerdict& v) {
    const std::string not_measured = v.stability_failed.empty() ? "" : " (failed: " + v.stability_failed + ")";
    if (!(v.stability_hi > 0)) return "—" + not_measured;
    const std::string r = v.stability_hi - v.stability_lo < 0.005 ? fmt::format("{:.2f}", v.stability_lo)
                                                                  : fmt::format("{:.3g}–{:.3g}", v.stability_lo, v.stability_hi);
    return (v.stability_weak.empty() ? r : r + " (weak: " + v.stability_weak + ")") + not_measured;
}

// The scheme's CPU time per step, NaN when it was not timed (a client) or has no verdict.
double ns_per_step_of(const std::string& id, const std::vector<SchemeVerdict>& verdicts) {
    const auto v = std::find_if(verdicts.begin(), verdicts.end(), [&](const SchemeVerdict& x) { return x.scheme == id; });
    return v == verdicts.end() ? NAN : v->ns_per_step;
}

std::string code_list(const std::vector<std::string>& ids, const std::vector<SchemeVerdict>& verdicts) {
    std::string out;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const double ns = ns_per_step_of(ids[i], verdicts);
        out += (i == 0 ? "" : i + 1 == ids.size() ? " and " : ", ") + fmt::format("`{}`", ids[i]);
        out += std::isfinite(ns) ? fmt::format(" ({:.0f} ns/step)", ns) : " (not timed)";
    }
    return out;
}

}  // namespace

std::string verdict_section(const ResultSet& set, const std::vector<SchemeVerdict>& verdicts, bool has_stability) {
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
        "this kind of figure, on its own scene. A client's figure is its program's wall time per step, \"(client, wall)\": the "
        "horizon run (8 T) less the trajectory run (T) at the coarsest dt, over the steps added, so its start-up drops out; it "
        "is not a CPU time, and the rankings leave it out. *Meets its claims*: every claim the scheme registers, judged by the "
        "gate's judges on this sweep's runs of the default gate's claim scenes (`asymmetric_free` and `tumbling_brick` without "
        "torque, `dipole_top` with it) and their horizon runs; \"no\" names the claims that fail, \"not judged here\" where "
        "none of those scenes ran, \"nothing claimed\" where it claims nothing.\n\n"
        "| scheme | order, free | order, torque | momentum; energy | stability / Peng | ns / step | meets its claims |\n"
        "|---|---|---|---|---|---:|---|\n",
        energy_horizon, energy_growth_bound, cost_on, metric::omega_err_max);
    for (const auto& v : verdicts)
        md += fmt::format("| `{}`{} | {} | {} | {}; {} | {} | {} | {} |\n", v.scheme, v.control ? " (control)" : "", order_cell(v.free),
                          order_cell(v.torque), momentum_cell(v), energy_cell(v), stability_cell(v),
                          std::isfinite(v.ns_per_step)             ? fmt::format("{:.0f}", v.ns_per_step)
                          : std::isfinite(v.client_wall_ns_per_step) ? fmt::format("{:.3g} (client, wall)", v.client_wall_ns_per_step)
                                                                     : "—",
                          claims_cell(v));
    for (const auto& r : set.declined)  // a client's "not mine": skipped, said, in no table
        md += fmt::format("\n- Skipped: client `{}` on `{}` at dt = {:g} ({} run), {}", r.spec.scheme, r.spec.scene, r.spec.dt,
                          kind_name(r.spec.kind), r.failure);
    if (!set.declined.empty()) md += "\n";
    if (!has_stability)
        md += "\nNo stability study in this directory: `rotbench stability --out DIR` writes one beside the runs, and "
              "`rotbench report DIR` then includes it.\n";
    return md + "\n";
}

std::string recommendation_section(const SchemeChoice& rec, const std::vector<SchemeVerdict>& verdicts) {
    std::string md = "## Recommendation\n\n";
    if (!rec.use.empty())
        md += fmt::format("- **Use** {}: second order with and without torque as claimed, every claim met as the gate judges it, "
                          "the angular momentum kept and the energy bounded (or kept) over {:g} times a scene's duration; cheapest "
                          "first (the verdicts below say why).\n",
                          code_list(rec.use, verdicts), energy_horizon);
    if (!rec.short_runs.empty()) {
        const bool all_timed = std::all_of(rec.short_runs.begin(), rec.short_runs.end(),
                                           [&](const std::string& id) { return std::isfinite(ns_per_step_of(id, verdicts)); });
        md += fmt::format("- **For short runs** {}: second order as claimed, every claim met and the momentum kept, but their energy "
                          "drifts secularly; {}"
                          "accurate until the drift matters.\n",
                          code_list(rec.short_runs, verdicts), all_timed ? "cheap, and " : "");
    }
    if (!rec.avoid.empty()) {
        md += "- **Avoid**";
        for (std::size_t i = 0; i < rec.avoid.size(); ++i)
            md += fmt::format("{} `{}` ({})", i ? ";" : "", rec.avoid[i].first, rec.avoid[i].second);
        md += ".\n";
    }
    if (!rec.unjudged.empty())
        md += fmt::format("- **Not judged here** {}: none of the scenes that judge a claim ran ({} without torque, {} with one).\n",
                          code_list(rec.unjudged, verdicts), fmt::join(default_claim_scenes(false), ", "),
                          fmt::join(default_claim_scenes(true), ", "));
    if (!rec.peng_unsafe.empty()) {
        md += "- **Peng's step is unsafe once contacts are damped**, for every scheme:";
        for (std::size_t i = 0; i < rec.peng_unsafe.size(); ++i) {
            const auto& u = rec.peng_unsafe[i];
            md += fmt::format("{} at ζ = {:g} the best limit is {:.2f} of it ({})", i ? ";" : "", u.zeta, u.best_ratio, u.scene);
        }
        md += ". Take a damped contact's dt from the measured limits (section Stability limits), not from eq. 46 alone.\n";
    }
    md += "- **For your own particle and contact**, `rotbench advise --inertia I1,I2,I3 --mass M --stiffness K --zeta Z --omega W "
          "--tolerance TOL` measures which scheme meets TOL at what dt, and says whether the contact or the rotation scheme "
          "limits it.\n\n";
    return md;
}

}  // namespace rotbench
