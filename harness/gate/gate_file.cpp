#include "harness/gate/gate_file.hpp"

#include "harness/analysis/claims.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/core/fnv1a.hpp"
#include "harness/core/metrics.hpp"
#include "harness/store/client.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/toml_input.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "schemes/scheme.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>

namespace rotbench {
namespace {

const std::vector<std::string> criteria = {"min_order",          "max_error",     "max_energy_drift",
                                           "max_momentum_drift", "min_stability", "max_cost_ratio", "same_map_as"};

std::string metric_of(const std::string& criterion, const std::string& metric) {
    if (criterion == "max_energy_drift") return metric::energy_drift_max;
    if (criterion == "max_momentum_drift") return metric::momentum_drift_max;
    if (criterion == "min_order" || criterion == "max_error") return metric.empty() ? metric::omega_err_max : metric;
    return "";
}

// The metrics a check may bound: errors against the reference and drifts.
const std::vector<std::string>& known_metrics() {
    static const std::vector<std::string> m = [] {
        std::vector<std::string> out;
        for (const auto& info : metric_table())
            if (info.kind == MetricKind::error || info.kind == MetricKind::drift) out.emplace_back(info.name);
        return out;
    }();
    return m;
}

// Every registered scheme that is not a control: what "*" means in a [[check]].
std::vector<std::string> sound_schemes() {
    std::vector<std::string> out;
    for (const auto& id : SchemeRegistry::instance().ids())
        if (SchemeRegistry::instance().at(id, "scheme").extra.sound) out.push_back(id);
    return out;
}

// gate --schemes: the selection, and the warnings for the schemes the file names outside it
// that are not loaded.
struct Selection {
    std::vector<std::string> only;
    std::vector<std::string>* warnings = nullptr;
    // Unknown, and outside a given selection: skipped (said once), not refused.
    bool skips(const std::string& id, const std::string& where) const {
        if (only.empty() || SchemeRegistry::instance().contains(id) || std::find(only.begin(), only.end(), id) != only.end()) return false;
        const std::string what = "scheme '" + id + "' is not loaded; outside --schemes, skipped";  // said once, where first named
        if (std::none_of(warnings->begin(), warnings->end(), [&](const std::string& w) { return w.ends_with(": " + what); }))
            warnings->push_back(where + ": " + what);
        return true;
    }
    // The schemes of a list, less those skipped; an unknown one in the selection (or without
    // one) refused, naming file, line and column, as ids() does.
    std::vector<std::string> schemes(const std::string& path, const std::string& key, const toml::node& node) const {
        std::vector<std::string> kept;
        const std::string where = fmt::format("{}:{}", path, node.source().begin.line);
        for (const auto& id : strings(path, key, node))
            if (!skips(id, where)) kept.push_back(id);
        for (const auto& id : kept)
            if (!SchemeRegistry::instance().contains(id)) return ids(path, key, node, SchemeRegistry::instance(), "scheme");  // throws
        return kept;
    }
};

// A check's schemes: the list, or every sound scheme ("*") less 'except'; for same_map_as, each a
// client measured against that counterpart.
std::vector<std::string> check_schemes(const std::string& path, const toml::table& t, const GateCheck& c, const toml::node& schemes_node,
                                       const toml::node* except_node, const Selection& selection) {
    const auto names = strings(path, "schemes", schemes_node);
    std::vector<std::string> schemes = names.size() == 1 && names[0] == "*" ? sound_schemes() : selection.schemes(path, "schemes", schemes_node);
    if (except_node) {  // "*" but these: a check that covers plug-ins yet leaves out a scheme held to another bound
        if (!(names.size() == 1 && names[0] == "*")) toml_error(path, *except_node, "'except' applies to schemes = [\"*\"] only");
        for (const auto& id : ids(path, "except", *except_node, SchemeRegistry::instance(), "scheme")) std::erase(schemes, id);
    }
    if (c.criterion == "same_map_as")
        for (const auto& id : schemes) {
            const LoadedClient* client = client_of(id);
            if (!client || client->counterpart != c.same_map_as)
                toml_error(path, t, "same_map_as = '" + c.same_map_as + "' judges clients whose counterpart it is; '" + id + "' is " +
                                        (client ? "a client with counterpart '" + client->counterpart + "'" : "not a client"));
        }
    return schemes;
}

// The steps a criterion needs: a ladder of at least 3 for min_order, none for min_stability (on a
// stability scene), exactly one for the others.
void check_steps(const std::string& path, const toml::table& t, const GateCheck& c) {
    const bool ladder = c.criterion == "min_order" || c.criterion == "same_map_as";
    if (c.criterion == "min_stability") {
        if (!c.dts.empty()) toml_error(path, t, "min_stability searches for the limit itself: remove 'dt'");
        const std::vector<std::string> valid = stability_scene_ids();
        if (std::find(valid.begin(), valid.end(), c.scene) == valid.end())
            toml_error(path, t, "min_stability needs a stability scene (" + join(valid, ", ") + "), not '" + c.scene + "'");
    } else if (!ladder && c.dts.size() != 1) {
        toml_error(path, t, "'" + c.criterion + "' needs exactly one 'dt'");
    }
    if (c.criterion == "min_order" && !c.dts.empty() && c.dts.size() < 3) toml_error(path, t, "min_order needs at least 3 time steps in 'dt'");
}

// A 'dt' list: finite steps greater than 0, none twice.
std::vector<double> steps(const std::string& path, const toml::node& v) {
    std::vector<double> dts = numbers(path, "dt", v);
    for (double dt : dts)
        if (!(dt > 0.0) || !std::isfinite(dt)) toml_error(path, v, "'dt' values must be finite numbers greater than 0");
    auto sorted = dts;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) toml_error(path, v, "'dt' has a duplicate value");
    return dts;
}

GateCheck read_check(const std::string& path, const toml::table& t, std::size_t index, const Selection& selection) {
    GateCheck c;
    c.location = fmt::format("{}:{}", path, t.source().begin.line);
    std::string metric;
    const toml::node* schemes_node = nullptr;
    const toml::node* except_node = nullptr;
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
        else if (key == "except") except_node = &v;
        else if (key == "metric") {
            metric = text(path, key, v);
            if (std::find(known_metrics().begin(), known_metrics().end(), metric) == known_metrics().end())
                toml_error(path, v, "unknown metric '" + metric + "'; valid metrics: " + join(known_metrics(), ", "));
        } else if (key == "dt") {
            c.dts = steps(path, v);
        } else if (key == "t_end") c.t_end = positive_number(path, key, v);
        else if (key == "round_off") c.round_off = positive_number(path, key, v);
        else if (key == "params") {
            if (!v.as_table()) toml_error(path, v, "'params' must be a table of scene parameters");
            if (c.scene.empty()) toml_error(path, v, "'params' needs a 'scene'");
            c.params = scene_overrides(path, c.scene, *v.as_table());
        } else if (key == "same_map_as") {
            if (!c.criterion.empty()) toml_error(path, v, "a check has one criterion; this one has '" + c.criterion + "' and '" + key + "'");
            c.criterion = key;
            c.same_map_as = text(path, key, v);
            if (!SchemeRegistry::instance().contains(c.same_map_as) || plugin_of(c.same_map_as))
                toml_error(path, v, "same_map_as = '" + c.same_map_as + "': neither a built-in scheme nor a loaded client");
        } else if (std::find(criteria.begin(), criteria.end(), key) != criteria.end()) {
            if (!c.criterion.empty()) toml_error(path, v, "a check has one criterion; this one has '" + c.criterion + "' and '" + key + "'");
            c.criterion = key;
            const auto b = numbers(path, key, v);
            if (b.size() != 1 || !std::isfinite(b[0])) toml_error(path, v, "'" + key + "' must be one finite number");
            c.bound = b[0];
        } else {
            toml_error(path, v, "unknown key '" + key + "' in [[check]]; valid keys: name, scene, schemes, except, metric, dt, t_end, "
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
    c.schemes = check_schemes(path, t, c, *schemes_node, except_node, selection);
    check_steps(path, t, c);
    if (c.name.empty()) c.name = c.criterion;
    make_scene(c.scene, c.params);  // parameters valid together (e.g. moments), named on error
    return c;
}

// The scenes of a [claims] list: registered, with a reference, and of the kind the list asks.
std::vector<std::string> claim_scenes(const std::string& path, const std::string& key, const toml::node& node, bool torque) {
    const auto list = ids(path, key, node, SceneRegistry::instance(), "scene");
    if (list.empty()) toml_error(path, node, "'" + key + "' is an empty list");
    for (const auto& id : list) {
        if (!judges_claims(scene_info(*make_scene(id)), torque))
            toml_error(path, node, "'" + id + "' is not a " +
                                       (torque ? std::string("scene with a reference and an orientation-dependent torque that conserves energy")
                                               : std::string("torque-free scene with a reference")));
    }
    return list;
}

// [claims.SCENE]: a ladder of at least 3 steps and scene parameters for the claims on SCENE.
ClaimScene read_claim_scene(const std::string& path, const std::string& scene, const toml::table& t) {
    ClaimScene c;
    for (auto&& [k, v] : t) {
        const std::string key(k.str());
        if (key == "dt") {
            c.dts = steps(path, v);
            if (c.dts.size() < 3) toml_error(path, v, "an order is fitted on at least 3 time steps in 'dt'");
            std::sort(c.dts.rbegin(), c.dts.rend());  // coarsest first, as a scene's ladder
        } else if (key == "params") {
            if (!v.as_table()) toml_error(path, v, "'params' must be a table of scene parameters");
            c.params = scene_overrides(path, scene, *v.as_table());
        } else {
            toml_error(path, v, "unknown key '" + key + "' in [claims." + scene + "]; valid keys: dt, params");
        }
    }
    return c;
}

ClaimsSection read_claims(const std::string& path, const toml::table& t, const Selection& selection) {
    ClaimsSection c;
    c.present = true;
    c.location = fmt::format("{}:{}", path, t.source().begin.line);
    bool has_schemes = false, has_free = false, has_torque = false;
    for (auto&& [k, v] : t) {
        const std::string key(k.str());
        if (key == "schemes") {
            const auto names = strings(path, key, v);
            c.schemes = names.size() == 1 && names[0] == "*" ? SchemeRegistry::instance().ids() : selection.schemes(path, key, v);
            has_schemes = true;
        } else if (key == "free") {
            c.free_scenes = claim_scenes(path, key, v, false);
            has_free = true;
        } else if (key == "torque") {
            c.torque_scenes = claim_scenes(path, key, v, true);
            has_torque = true;
        } else if (v.as_table() && SceneRegistry::instance().contains(key)) {
            c.scenes[key] = read_claim_scene(path, key, *v.as_table());
        } else {
            toml_error(path, v, "unknown key '" + key + "' in [claims]; valid keys: schemes, free, torque, and a table [claims.SCENE] "
                                "for a scene of those lists");
        }
    }
    if (!has_schemes || !has_free || !has_torque) throw InputError(c.location + ": [claims] needs 'schemes', 'free' and 'torque'");
    for (const auto& [scene, settings] : c.scenes) {
        const bool free = std::find(c.free_scenes.begin(), c.free_scenes.end(), scene) != c.free_scenes.end();
        if (!free && std::find(c.torque_scenes.begin(), c.torque_scenes.end(), scene) == c.torque_scenes.end()) throw InputError(c.location + ": [claims." + scene + "] is for a scene neither 'free' nor 'torque' lists");
        try {
            make_scene(scene, settings.params);  // parameters valid together, named on error
        } catch (const InputError& e) {
            throw InputError(c.location + ": [claims." + scene + "] params: " + e.what());
        }
    }
    if (c.free_scenes.size() < 2) throw InputError(c.location + ": [claims] 'free' needs at least two torque-free scenes");
    return c;
}

// std::nullopt for one whose scheme gate --schemes skips.
std::optional<ExpectedFailure> read_expected_failure(const std::string& path, const toml::table& t, const Selection& selection) {
    ExpectedFailure e;
    e.location = fmt::format("{}:{}", path, t.source().begin.line);
    for (auto&& [k, v] : t) {
        const std::string key(k.str());
        if (key == "check") e.check = text(path, key, v);
        else if (key == "reason") e.reason = text(path, key, v);
        else if (key == "scene" || key == "scheme") {
            const std::string id = text(path, key, v);
            if (key == "scheme" && selection.skips(id, fmt::format("{}:{}", path, v.source().begin.line))) return std::nullopt;
            try {
                if (key == "scene") SceneRegistry::instance().at(id, "scene");
                else SchemeRegistry::instance().at(id, "scheme");
            } catch (const InputError& error) {
                toml_error(path, v, error.what());
            }
            (key == "scene" ? e.scene : e.scheme) = id;
        } else {
            toml_error(path, v, "unknown key '" + key + "' in [[expected_failure]]; valid keys: check, scene, scheme, reason");
        }
    }
    if (e.check.empty() || e.scene.empty() || e.scheme.empty() || e.reason.empty())
        throw InputError(e.location + ": an [[expected_failure]] needs 'check', 'scene', 'scheme' and a 'reason'");
    return e;
}

GateFile gate_from_toml(const toml::table& root, const std::string& path, const std::vector<std::string>& only) {
    GateFile file;
    file.path = path;
    const Selection selection{only, &file.warnings};
    for (auto&& [name, node] : root) {
        const std::string key(name.str());
        if (key == "claims" && node.as_table()) {
            file.claims = read_claims(path, *node.as_table(), selection);
            continue;
        }
        const auto* array = node.as_array();
        if ((key != "check" && key != "expected_failure") || !array || !array->is_array_of_tables())
            toml_error(path, node, "unknown entry '" + key + "'; a gate file holds [claims], [[check]] and [[expected_failure]] tables");
        for (const auto& item : *array) {
            if (key == "check") file.checks.push_back(read_check(path, *item.as_table(), file.checks.size(), selection));
            else if (auto e = read_expected_failure(path, *item.as_table(), selection)) file.expected_failures.push_back(*e);
        }
    }
    if (file.checks.empty() && !file.claims.present) throw InputError(path + ": no [claims] and no [[check]] in the gate file");
    for (const auto& e : file.expected_failures) {
        const bool is_claim = std::find(claim_ids().begin(), claim_ids().end(), e.check) != claim_ids().end();
        const auto check = std::find_if(file.checks.begin(), file.checks.end(), [&](const GateCheck& c) { return c.name == e.check; });
        if (!is_claim && check == file.checks.end())
            throw InputError(e.location + ": expected failure of '" + e.check + "', which is neither a check of this file nor a claim (" +
                             join(claim_ids(), ", ") + ")");
        if (!is_claim && (check->scene != e.scene ||
                          std::find(check->schemes.begin(), check->schemes.end(), e.scheme) == check->schemes.end()))
            throw InputError(e.location + ": check '" + e.check + "' does not run " + e.scheme + " on " + e.scene);
    }
    return file;
}

}  // namespace

GateFile only_schemes(GateFile file, const std::vector<std::string>& schemes) {
    const auto chosen = [&](const std::string& id) { return std::find(schemes.begin(), schemes.end(), id) != schemes.end(); };
    const auto keep_chosen = [&](std::vector<std::string>& ids) { std::erase_if(ids, [&](const auto& id) { return !chosen(id); }); };
    keep_chosen(file.claims.schemes);
    for (auto& check : file.checks) keep_chosen(check.schemes);
    std::erase_if(file.checks, [](const GateCheck& c) { return c.schemes.empty(); });
    std::erase_if(file.expected_failures, [&](const ExpectedFailure& e) { return !chosen(e.scheme); });
    return file;
}

const std::vector<std::string>& claim_ids() {
    static const std::vector<std::string> ids = {"order_without_torque", "order_with_torque", "exact_without_torque",
                                                 "conserves_momentum",   "bounded_energy",    "time_reversible",
                                                 "sanity_order",         "sanity_momentum"};
    return ids;
}

GateFile load_gate(const std::string& path, const std::vector<std::string>& only) {
    const std::string text = read_input_file(path, "", 1u << 20);  // as parse_toml_file bounds it
    return parse_gate(text, path, only);
}

GateFile parse_gate(std::string_view text, const std::string& name, const std::vector<std::string>& only) {
    GateFile file = gate_from_toml(parse_toml_text(text, name), name, only);
    file.hash = Fnv1a().feed(text).hex();
    return file;
}

}  // namespace rotbench
