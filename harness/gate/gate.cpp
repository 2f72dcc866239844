#include "harness/gate/gate.hpp"

#include "harness/analysis/order_fit.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/analysis/stability.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/engine/sweep.hpp"
#include "harness/io/toml_input.hpp"
#include "harness/io/output_files.hpp"
#include "schemes/scheme.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

const std::vector<std::string> criteria = {"min_order",          "max_error",     "max_energy_drift",
                                           "max_momentum_drift", "min_stability", "max_cost_ratio"};

std::string metric_of(const std::string& criterion, const std::string& metric) {
    if (criterion == "max_energy_drift") return "energy_drift_max";
    if (criterion == "max_momentum_drift") return "momentum_drift_max";
    if (criterion == "min_order" || criterion == "max_error") return metric.empty() ? "omega_err_max" : metric;
    return "";
}

const std::vector<std::string>& known_metrics() {
    static const std::vector<std::string> m = {"omega_rms_x",      "omega_rms_y",       "omega_rms_z",
                                               "omega_err_max",    "orientation_err_max", "energy_drift_max",
                                               "momentum_drift_max", "quat_norm_err_max"};
    return m;
}

GateCheck read_check(const std::string& path, const toml::table& t, std::size_t index) {
    GateCheck c;
    c.location = fmt::format("{}:{}", path, t.source().begin.line);
    std::string metric;
    const toml::node* schemes_node = nullptr;
    if (const toml::node* scene = t.get("scene")) {  // first: 'params' are checked against it
        c.scene = text(path, "scene", *scene);
        try {
            SceneRegistry::instance().at(c.scene, "scene");
        } catch (const InputError& e) {
            toml_error(path, *scene, e.what());
        }
    }
    for (auto&& [k, v] : t) {
        const std::string key(k.str());
        if (key == "name") c.name = text(path, key, v);
        else if (key == "why") c.why = text(path, key, v);
        else if (key == "scene") continue;
        else if (key == "schemes") schemes_node = &v;
        else if (key == "metric") {
            metric = text(path, key, v);
            if (std::find(known_metrics().begin(), known_metrics().end(), metric) == known_metrics().end())
                toml_error(path, v, "unknown metric '" + metric + "'; valid metrics: " + join(known_metrics(), ", "));
        } else if (key == "dt") {
            c.dts = numbers(path, key, v);
            for (double dt : c.dts)
                if (!(dt > 0.0) || !std::isfinite(dt)) toml_error(path, v, "'dt' values must be finite numbers greater than 0");
            auto sorted = c.dts;
            std::sort(sorted.begin(), sorted.end());
            if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) toml_error(path, v, "'dt' has a duplicate value");
        } else if (key == "t_end") c.t_end = positive_number(path, key, v);
        else if (key == "round_off") c.round_off = positive_number(path, key, v);
        else if (key == "params") {
            if (!v.as_table()) toml_error(path, v, "'params' must be a table of scene parameters");
            if (c.scene.empty()) toml_error(path, v, "'params' needs a 'scene'");
            c.params = scene_overrides(path, c.scene, *v.as_table());
        } else if (std::find(criteria.begin(), criteria.end(), key) != criteria.end()) {
            if (!c.criterion.empty()) toml_error(path, v, "a check has one criterion; this one has '" + c.criterion + "' and '" + key + "'");
            c.criterion = key;
            const auto b = numbers(path, key, v);
            if (b.size() != 1 || !std::isfinite(b[0])) toml_error(path, v, "'" + key + "' must be one finite number");
            c.bound = b[0];
        } else {
            toml_error(path, v, "unknown key '" + key + "' in [[check]]; valid keys: name, scene, schemes, metric, dt, t_end, "
                          "round_off, params, why, " + join(criteria, ", "));
        }
    }
    const auto missing = [&](const std::string& what) {
        throw InputError(c.location + ": check " + std::to_string(index + 1) + " has no " + what);
    };
    if (c.scene.empty()) missing("'scene'");
    if (!schemes_node) missing("'schemes'");
    if (c.criterion.empty()) missing("criterion (one of " + join(criteria, ", ") + ")");
    if (!metric.empty() && c.criterion != "min_order" && c.criterion != "max_error")
        toml_error(path, t, "'metric' applies to min_order and max_error only");
    c.metric = metric_of(c.criterion, metric);
    const auto names = strings(path, "schemes", *schemes_node);
    if (names.size() == 1 && names[0] == "*") c.schemes = SchemeRegistry::instance().ids();
    else c.schemes = ids(path, "schemes", *schemes_node, SchemeRegistry::instance(), "scheme");
    const bool ladder = c.criterion == "min_order";
    if (c.criterion == "min_stability") {
        if (!c.dts.empty()) toml_error(path, t, "min_stability searches for the limit itself: remove 'dt'");
        if (!dynamic_cast<const StabilityProbe*>(make_scene(c.scene).get()))
            toml_error(path, t, "min_stability needs a stability scene (ellipsoid_pair, fast_spin, sphere_pair), not '" + c.scene + "'");
    } else if (!ladder && c.dts.size() != 1) {
        toml_error(path, t, "'" + c.criterion + "' needs exactly one 'dt'");
    }
    if (ladder && !c.dts.empty() && c.dts.size() < 3) toml_error(path, t, "min_order needs at least 3 time steps in 'dt'");
    if (c.name.empty()) c.name = c.criterion;
    make_scene(c.scene, c.params);  // parameters valid together (e.g. moments), named on error
    return c;
}

struct RunKey {
    std::string scene, scheme;
    double dt, t_end;
    ParamOverrides params;
    auto tie() const { return std::tie(scene, scheme, dt, t_end, params); }
    bool operator<(const RunKey& o) const { return tie() < o.tie(); }
};

std::vector<double> ladder_of(const GateCheck& c) {
    return c.dts.empty() ? make_scene(c.scene, c.params)->default_dts() : c.dts;
}

std::string number(double v) { return fmt::format("{:.3g}", v); }

GateOutcome judge_order(const GateCheck& c, const std::vector<const RunResult*>& runs) {
    GateOutcome o;
    std::vector<OrderPoint> points;
    double worst = 0;
    for (const RunResult* r : runs) {
        if (!r->failure.empty()) {
            o.measured = NAN;
            o.detail = fmt::format("the run at dt = {} failed: {}", number(r->spec.dt), r->failure);
            return o;
        }
        const double e = r->value(c.metric);
        points.push_back({r->spec.dt, e});
        worst = std::max(worst, std::isnan(e) ? INFINITY : e);
    }
    const OrderFit fit = fit_order(points);
    if (fit.sufficient) {
        o.measured = fit.order;
        o.passed = fit.order >= c.bound;
        o.detail = fmt::format("observed order {:.2f} [{:.2f}, {:.2f}] over dt {} ... {} ({} points), required >= {}",
                               fit.order, fit.order_lo, fit.order_hi, number(fit.dt_max), number(fit.dt_min), fit.points,
                               number(c.bound));
        return o;
    }
    if (worst <= c.round_off) {
        o.measured = INFINITY;
        o.passed = true;
        o.detail = fmt::format("exact to round-off: every {} is at most {} (<= round_off {})", c.metric, number(worst),
                               number(c.round_off));
        return o;
    }
    o.measured = NAN;
    std::string errors;
    for (const auto& p : points) errors += (errors.empty() ? "" : ", ") + number(p.error);
    o.detail = fmt::format("no order: {} does not fall as a power of dt (errors {} from dt {} to {}), required >= {}",
                           c.metric, errors, number(points.front().dt), number(points.back().dt), number(c.bound));
    return o;
}

GateOutcome judge_max(const GateCheck& c, const RunResult& r) {
    GateOutcome o;
    o.measured = r.value(c.metric);
    if (!r.failure.empty()) {
        o.detail = "the run failed: " + r.failure;
        return o;
    }
    if (std::isnan(o.measured)) {
        o.detail = fmt::format("scene '{}' has no {}", c.scene, c.metric);
        return o;
    }
    o.passed = o.measured <= c.bound;
    o.detail = fmt::format("{} = {} at dt = {}, required <= {}", c.metric, number(o.measured), number(r.spec.dt), number(c.bound));
    return o;
}

std::vector<GateCheck> gate_from_toml(const toml::table& root, const std::string& path) {
    std::vector<GateCheck> checks;
    for (auto&& [name, node] : root) {
        const std::string key(name.str());
        const auto* array = node.as_array();
        if (key != "check" || !array || !array->is_array_of_tables())
            toml_error(path, node, "unknown entry '" + key + "'; a gate file holds [[check]] tables only");
        for (const auto& item : *array) checks.push_back(read_check(path, *item.as_table(), checks.size()));
    }
    if (checks.empty()) throw InputError(path + ": no [[check]] in the gate file");
    return checks;
}

}  // namespace

std::vector<GateCheck> load_gate(const std::string& path) { return gate_from_toml(parse_toml_file(path), path); }

std::vector<GateCheck> parse_gate(std::string_view text, const std::string& name) {
    return gate_from_toml(parse_toml_text(text, name), name);
}

GateResult run_gate(const std::vector<GateCheck>& checks, int jobs) {
    // Every distinct accuracy run once.
    std::map<RunKey, std::size_t> index;
    std::vector<RunSpec> plan;
    auto need = [&](const RunKey& k) {
        if (index.emplace(k, plan.size()).second) plan.push_back({k.scene, k.scheme, k.dt, k.t_end, k.params});
    };
    for (const auto& c : checks) {
        if (c.criterion == "min_stability" || c.criterion == "max_cost_ratio") continue;
        for (const auto& s : c.schemes)
            for (double dt : ladder_of(c)) need({c.scene, s, dt, c.t_end, c.params});
    }
    GateResult result;
    result.runs = run_sweep(plan, {.measure_time = false}, {}, jobs);
    const auto run_of = [&](const GateCheck& c, const std::string& s, double dt) -> const RunResult& {
        return result.runs[index.at({c.scene, s, dt, c.t_end, c.params})];
    };

    // Timing runs one at a time, so that they do not compete for the cores.
    std::map<RunKey, double> ns_per_step;
    const auto timed = [&](const GateCheck& c, const std::string& s) {
        const RunKey k{c.scene, s, c.dts[0], c.t_end, c.params};
        auto it = ns_per_step.find(k);
        if (it != ns_per_step.end()) return it->second;
        const RunResult r = run_one({c.scene, s, c.dts[0], c.t_end, c.params});
        const double ns = r.failure.empty() ? r.value("ns_per_step") : NAN;
        return ns_per_step[k] = ns;
    };

    for (std::size_t i = 0; i < checks.size(); ++i) {
        const GateCheck& c = checks[i];
        for (const auto& s : c.schemes) {
            GateOutcome o;
            if (c.criterion == "min_order") {
                std::vector<const RunResult*> runs;
                for (double dt : ladder_of(c)) runs.push_back(&run_of(c, s, dt));
                o = judge_order(c, runs);
            } else if (c.criterion == "min_stability") {
                const auto scene = make_scene(c.scene, c.params);
                const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
                const StabilityCriterion criterion{stability_horizon_periods * probe.period(), stability_growth};
                const double limit = empirical_limit(*scene, s, probe.predicted_limit(), criterion);
                o.measured = limit / probe.predicted_limit();
                o.passed = o.measured >= c.bound;
                o.detail = fmt::format("measured limit {} s = {} x Peng's prediction {} s, required >= {}", number(limit),
                                       number(o.measured), number(probe.predicted_limit()), number(c.bound));
            } else if (c.criterion == "max_cost_ratio") {
                const double ns = timed(c, s), base = timed(c, "direct");
                o.measured = ns / base;
                o.passed = o.measured <= c.bound;
                o.detail = std::isnan(o.measured)
                               ? "no timing: the run failed"
                               : fmt::format("{} ns per step against {} for direct: ratio {}, required <= {}", number(ns),
                                             number(base), number(o.measured), number(c.bound));
            } else {
                o = judge_max(c, run_of(c, s, c.dts[0]));
            }
            o.check = i;
            o.scheme = s;
            result.outcomes.push_back(std::move(o));
        }
    }
    return result;
}

}  // namespace rotbench
