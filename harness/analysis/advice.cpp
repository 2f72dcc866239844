#include "harness/analysis/advice.hpp"

#include "harness/analysis/answer.hpp"

#include "harness/analysis/median.hpp"
#include "harness/analysis/order_fit.hpp"
#include "harness/exec/interrupt.hpp"
#include "harness/exec/reference.hpp"
#include "harness/scenes/stability_probe.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rotbench {
namespace {

const std::string scene_id = "particle_contact";


bool stable(const RunResult& r) { return r.failure.empty() && r.value(metric::unstable) == 0.0 && std::isfinite(relative_omega_error(r)); }

struct Outcome {
    bool recommended = false;
    Recommendation r;
    std::string why;
};

// The dt the ladder gives for the tolerance, with how and the error it predicts: dt0 when the first
// rung meets it, a measured rung after an unstable one, else interpolated between the first rung
// that meets it and the one before; NaN when none does.
double chosen_dt(const std::vector<RunResult>& ladder, double dt0, double tolerance, const std::string& extrapolated, Recommendation& r) {
    for (std::size_t k = 0; k < ladder.size(); ++k) {
        if (!stable(ladder[k]) || !(relative_omega_error(ladder[k]) <= tolerance)) continue;
        if (k == 0) {
            r.predicted_error = relative_omega_error(ladder[0]), r.how = "stability-bound";
            return dt0;
        }
        const RunResult &c = ladder[k - 1], &f = ladder[k];
        if (!stable(c)) {
            r.predicted_error = relative_omega_error(f), r.how = "measured";
            return f.spec.dt;
        }
        const double target = std::max(advice_error_margin * tolerance, relative_omega_error(f));
        r.predicted_error = target, r.how = "interpolated" + extrapolated;
        return interpolated_dt(c, f, target);
    }
    return NAN;
}

// A scheme's runs on halving steps, with the points its order is fitted to and the costs measured.
struct Ladder {
    std::function<RunResult(double)> run;  // a timed run at dt
    std::vector<RunResult> rungs;
    std::vector<OrderPoint> points;
    std::vector<double> ns;

    void add(double dt) {
        rungs.push_back(run(dt));
        const RunResult& r = rungs.back();
        if (stable(r) && relative_omega_error(r) < advice_asymptotic_error) points.push_back({r.spec.dt, relative_omega_error(r)});
        if (std::isfinite(r.value(metric::ns_per_step))) ns.push_back(r.value(metric::ns_per_step));
    }
    bool meets(double tolerance) const {
        return std::any_of(rungs.begin(), rungs.end(), [&](const RunResult& r) { return stable(r) && relative_omega_error(r) <= tolerance; });
    }
};

// Grows a stable ladder until a measured rung meets the tolerance; why it cannot, or "".
// `extrapolated` says so when a rung was placed by extrapolation.
std::string reach(Ladder& ladder, double tolerance, double t_end, std::string& extrapolated) {
    std::vector<RunResult>& rungs = ladder.rungs;
    // A scheme whose limit is far above the steps its accuracy needs (zvw_corrected on a stiff
    // contact) ends its ladder before its error is asymptotic: halve on, while the error still
    // falls, until the order can be fitted (a run costs no more than advice_max_steps).
    while (!ladder.meets(tolerance) && !fit_order(ladder.points).sufficient && stable(rungs.back()) &&
           relative_omega_error(rungs.back()) < relative_omega_error(rungs[rungs.size() - 2]) &&
           t_end / (rungs.back().spec.dt / 2) <= advice_max_steps)
        ladder.add(rungs.back().spec.dt / 2);
    // No rung meets the tolerance: extrapolate from the finest with the observed order, run
    // there, and again from that run, until a measured rung meets it; the dt is then always
    // interpolated between two measured rungs, never taken on trust from an extrapolation.
    for (int search = 0; search < advice_searches && !ladder.meets(tolerance); ++search) {
        const OrderFit fit = fit_order(ladder.points);
        const RunResult& finest = rungs.back();
        if (!stable(finest) || !fit.sufficient || fit.order < 0.5)
            return fmt::format("does not reach {:g} on the ladder down to {:.3g} s, and its error has no order to extrapolate with",
                               tolerance, finest.spec.dt);
        const double next = finest.spec.dt * std::pow(advice_error_margin * tolerance / relative_omega_error(finest), 1.0 / fit.order);
        if (t_end / next > advice_max_steps) return fmt::format("needs dt = {:.3g} s, {:.3g} steps over {:g} s", next, t_end / next, t_end);
        extrapolated = fmt::format(" (after extrapolating with order {:.2f})", fit.order);
        ladder.add(next);
    }
    return "";
}

// Why the particle's reference cannot be computed at dt over t_end, or "". It is the particle's,
// not a scheme's: one that fails at the first rung's step would fail every scheme's ladder, rung
// by rung, each up to its budget (minutes for an ill-scaled particle such as m = 1e-300 kg).
std::string reference_failure(const Scene& scene, double dt, double t_end) {
    try {
        make_reference(scene, dt, step_count(t_end, dt));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

// Each of the scheme's runs is a task of the executor: a plug-in's in its worker, so that one that
// crashes or hangs is not recommended, with the reason, and the other schemes are still advised.
Outcome advise_one(Executor& executor, const StabilityProbe& probe, const ParamOverrides& params, double t_end, double tolerance,
                   const std::string& scheme, bool verify) {
    Outcome o;
    o.r.scheme = scheme;
    const RunResult search = executor.run(RunSpec{scene_id, scheme, 0.0, t_end, params, RunKind::stability, false});
    if (!search.failure.empty()) return {false, o.r, "its stability search failed: " + search.failure};
    const double limit = search.value(metric::dt_empirical);
    o.r.dt_stability = limit;
    if (!(limit > 0)) return {false, o.r, "no stable dt found"};
    const double dt0 = advice_safety * (std::isfinite(limit) ? limit : probe.predicted_limit());

    const auto run_at = [&](double dt, bool timed, const std::string& by = "") {
        RunSpec spec{scene_id, by.empty() ? scheme : by, dt, t_end, params};
        spec.timed = timed;
        return executor.run(spec);
    };
    Ladder ladder{[&](double dt) { return run_at(dt, true); }, {}, {}, {}};
    for (int k = 0; k < advice_ladder_rungs && t_end / (dt0 / std::pow(2.0, k)) <= advice_max_steps; ++k) ladder.add(dt0 / std::pow(2.0, k));
    const std::vector<RunResult>& rungs = ladder.rungs;
    if (rungs.size() < 2)
        return {false, o.r, fmt::format("its ladder from {:.3g} s would need more than {:.3g} steps a run over {:g} s (the budget of a run)",
                                        dt0, advice_max_steps, t_end)};
    // A blow-up is the scheme's instability (it records its fail_step); anything else crashed, hung or threw.
    if (!rungs.front().failure.empty() && !rungs.front().has(metric::fail_step))
        return {false, o.r, "its run failed: " + rungs.front().failure};
    if (!stable(rungs.front()))  // the search's horizon is the criterion's; a run may still fail
        return {false, o.r, fmt::format("unstable at {:.3g} s below its measured limit {:.3g} s", dt0, limit)};
    std::string extrapolated;
    if (const std::string why = reach(ladder, tolerance, t_end, extrapolated); !why.empty()) return {false, o.r, why};
    const double dt = chosen_dt(rungs, dt0, tolerance, extrapolated, o.r);
    if (std::isnan(dt)) return {false, o.r, fmt::format("does not reach {:g} down to {:.3g} s", tolerance, rungs.back().spec.dt)};
    if (t_end / dt > advice_max_steps) return {false, o.r, fmt::format("needs dt = {:.3g} s, {:.3g} steps over {:g} s", dt, t_end / dt, t_end)};
    o.r.dt = dt;
    o.r.stability_ratio = limit / probe.predicted_limit();
    for (const auto& r : rungs) o.r.ladder.push_back({r.spec.dt, stable(r) ? relative_omega_error(r) : NAN});
    if (const OrderFit fit = fit_order(ladder.points); fit.sufficient) o.r.order = fit.order, o.r.order_lo = fit.order_lo, o.r.order_hi = fit.order_hi;
    // The part of the error that is not the rotation scheme's: the exact rotation flow at the same dt.
    if (const RunResult exact = run_at(dt, false, advice_exact_rotation); stable(exact)) {
        o.r.exact_rotation_error = relative_omega_error(exact);
        o.r.contact_share = o.r.exact_rotation_error / o.r.predicted_error;
    }
    o.r.limited_by = o.r.how == "stability-bound"                ? "stability"
                     : std::isnan(o.r.contact_share)                ? "unknown"  // the exact rotation flow failed at dt
                     : o.r.contact_share >= advice_contact_share ? "contact"
                                                                     : "rotation";
    o.r.ns_per_step = median(ladder.ns);
    o.r.cpu_seconds = o.r.ns_per_step * 1e-9 / dt;
    if (verify) {
        const RunResult v = run_at(dt, false);
        o.r.verified = true;
        o.r.verified_stable = stable(v);
        o.r.verified_error = o.r.verified_stable ? relative_omega_error(v) : NAN;
    }
    o.recommended = true;
    return o;
}

// What limits dt across the recommendations, one sentence per cause, and so what the ranking rests on.
std::string advice_verdict(const Advice& a) {
    const auto& rs = a.recommendations;
    if (rs.empty()) return fmt::format("No scheme meets {:g} within the budget of a run.", a.tolerance);
    std::string out;
    for (const std::string cause : {"contact", "rotation", "stability", "unknown"}) {
        std::vector<std::string> ids;
        double lo = INFINITY, hi = 0;
        for (const auto& r : rs)
            if (r.limited_by == cause) ids.push_back(r.scheme), lo = std::min(lo, r.dt), hi = std::max(hi, r.dt);
        if (ids.empty()) continue;
        const std::string who = ids.size() == rs.size() ? "every scheme" : fmt::format("{} ({} of {})", fmt::join(ids, ", "), ids.size(), rs.size());
        const std::string dts = fmt::format("{:.2g} to {:.2g} s, {:.2g} to {:.2g} times Peng's step", lo, hi, lo / a.dt_peng, hi / a.dt_peng);
        if (cause == "contact")
            out += fmt::format("The contact, not the rotation scheme, limits dt for {}: stepped with the exact rotation flow ({}) the "
                               "error at the same dt is at least {:.0f} % of theirs, so they need the same dt ({}) and differ only in "
                               "cost, which ranks them, and in stability margin. ",
                               who, advice_exact_rotation, 100 * advice_contact_share, dts);
        else if (cause == "rotation")
            out += fmt::format("For {} the rotation scheme's own error adds to the contact's and sets dt ({}): there the scheme's "
                               "order and error constant matter, weighed against its cost per step. ", who, dts);
        else if (cause == "stability")
            out += fmt::format("For {} stability sets dt: {:g} is met at 0.9 of the scheme's own stability limit ({}). ", who,
                               a.tolerance, dts);
        else
            out += fmt::format("For {} what limits dt is not known: {} did not run stably at that dt ({}). ", who,
                               advice_exact_rotation, dts);
    }
    out.pop_back();  // the space after the last sentence: every recommendation has one of the causes
    return out;
}

}  // namespace

ParamOverrides particle_params(const Particle& p) {
    ParamOverrides params = {{"inertia", {p.inertia.x(), p.inertia.y(), p.inertia.z()}},
                             {"mass", {p.mass}},
                             {"stiffness", {p.stiffness}},
                             {"zeta", {p.zeta}},
                             {"omega", {p.omega}}};
    std::unique_ptr<Scene> scene;
    try {
        scene = make_scene(scene_id, params);  // every value checked
    } catch (const InputError& e) {  // named as the option of the same name: "particle_contact.zeta" is --zeta
        std::string message = e.what();
        for (std::size_t at = 0; (at = message.find(scene_id + ".", at)) != std::string::npos;) message.replace(at, scene_id.size() + 1, "--");
        throw InputError(message);
    }
    const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
    const double period = probe.period();
    if (p.t_end > 0 && p.t_end < period)
        throw InputError(fmt::format("--t-end: {:g} s is shorter than one period of the contact ({:.3g} s)", p.t_end, period));
    // The budget of a run, checked before any work: the ladder starts near Peng's step, and a
    // run of advice_max_steps steps resolves at most that many radians of spin.
    const double t_end = p.t_end > 0 ? p.t_end : advice_default_periods * period, dt = advice_safety * probe.predicted_limit();
    if (t_end / dt > advice_max_steps)
        throw InputError(fmt::format("--t-end: {:g} s is {:.3g} steps of {:.3g} s (0.9 of Peng's step); a run of advise takes at most "
                                     "{:.3g}: give at most {:.3g} s", t_end, t_end / dt, dt, advice_max_steps, advice_max_steps * dt));
    const std::string over = p.t_end > 0 ? fmt::format("{:.3g} s", t_end)
                                         : fmt::format("{:.3g} s ({:g} periods of the contact, the default --t-end)", t_end,
                                                       advice_default_periods);
    if (p.omega * t_end > advice_max_steps)
        throw InputError(fmt::format("--omega {:g} rad/s turns the particle {:.3g} rad in {}, more than a run of at most {:.3g} "
                                     "steps resolves; give a slower spin or a shorter --t-end", p.omega, p.omega * t_end, over,
                                     advice_max_steps));
    return params;
}

Advice advise(Executor& executor, const Particle& particle, double tolerance, const std::vector<std::string>& schemes, bool verify) {
    Advice a{particle, tolerance, particle.t_end, 0, 0, particle_params(particle), {}, {}};
    const auto probe_scene = make_scene(scene_id, a.params);
    const auto& probe = dynamic_cast<const StabilityProbe&>(*probe_scene);
    a.period = probe.period();
    a.dt_peng = probe.predicted_limit();
    if (a.t_end == 0) a.t_end = advice_default_periods * a.period;

    std::vector<std::string> sound;
    for (const auto& s : schemes) {
        if (SchemeRegistry::instance().at(s, "scheme").extra.sound) sound.push_back(s);
        else a.not_recommended.push_back({s, "a control (sound = false): never recommended"});
    }
    if (const std::string why = reference_failure(*probe_scene, advice_safety * a.dt_peng, a.t_end); !why.empty()) {
        if (interrupt_signal()) return a;  // the verb says it was interrupted
        a.verdict = "No scheme can be judged: this particle's reference could not be computed (" + why + ").";
        for (const auto& s : sound) a.not_recommended.push_back({s, "not run: the particle's reference could not be computed"});
        return a;
    }
    std::vector<Outcome> outcomes(sound.size());
    executor.for_each(sound.size(), [&](std::size_t i) { outcomes[i] = advise_one(executor, probe, a.params, a.t_end, tolerance, sound[i], verify); });
    for (const auto& o : outcomes) {
        if (o.recommended) a.recommendations.push_back(o.r);
        else a.not_recommended.push_back({o.r.scheme, o.why});
    }
    std::stable_sort(a.recommendations.begin(), a.recommendations.end(),
                     [](const Recommendation& x, const Recommendation& y) { return x.cpu_seconds < y.cpu_seconds; });
    a.verdict = advice_verdict(a);
    return a;
}

}  // namespace rotbench
