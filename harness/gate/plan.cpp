// The plan of a gate: every case (a claim or check of one scheme on one scene) and the runs it
// reads, each distinct run once.
#include "harness/gate/gate.hpp"

#include "harness/scenes/scene.hpp"
#include "harness/store/client.hpp"
#include "harness/store/plugin.hpp"
#include "schemes/scheme.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <tuple>

namespace rotbench {
namespace {

// file:line with the file relative to the working directory when it lies below it: CI annotations
// name files relative to the checkout, where CI runs.
std::string workspace_relative(const std::string& location) {
    const auto colon = location.rfind(':');
    const std::filesystem::path file = location.substr(0, colon);
    const std::filesystem::path relative = file.lexically_relative(std::filesystem::current_path());
    if (file.is_relative() || relative.empty() || *relative.begin() == "..") return location;
    return relative.string() + location.substr(colon);
}

class Planner {
public:
    Planner(const GateFile& file, bool quick) : file_(file), quick_(quick) {}

    std::size_t run(RunSpec spec) {
        // The scene's duration written out, as its run records it: a slice's runs must make the
        // plan whose fingerprint they carry (harness/store/shard.hpp).
        if (spec.t_end == 0.0) {
            const auto [duration, fresh] = t_ends_.try_emplace({spec.scene, spec.params}, 0.0);
            if (fresh) duration->second = make_scene(spec.scene, spec.params)->t_end();
            spec.t_end = duration->second;
        }
        const auto [it, fresh] = index_.try_emplace(spec, plan_.runs.size());
        if (fresh) plan_.runs.push_back(std::move(spec));
        return it->second;
    }

    std::vector<std::size_t> ladder(const std::string& scene, const std::string& scheme, const std::vector<double>& dts,
                                    double t_end = 0.0, const ParamOverrides& params = {}) {
        std::vector<std::size_t> runs;
        for (double dt : dts) runs.push_back(run({scene, scheme, dt, t_end, params, RunKind::trajectory, false}));
        return runs;
    }

    void add(GateCase c) {
        const SchemeClaims& claims = SchemeRegistry::instance().at(c.scheme, "scheme").extra;
        if (!claims.sound) {
            c.expected_to_fail = true;
            c.expected_reason = c.scheme + " is a control (sound = false): a scheme known to be wrong";
        }
        for (const auto& e : file_.expected_failures)
            if (e.check == c.id && e.scene == c.scene && e.scheme == c.scheme) {
                c.expected_to_fail = true;
                c.expected_reason = e.reason + " (" + e.location + ")";
            }
        plan_.cases.push_back(std::move(c));
    }

    void claims() {
        const ClaimsSection& section = file_.claims;
        if (!section.present) return;
        for (const auto& scheme : section.schemes) {
            const SchemeClaims& c = SchemeRegistry::instance().at(scheme, "scheme").extra;
            // A plug-in's claim points at its registration, in the candidate's source; a built-in's at the gate file.
            const std::string location = plugin_of(scheme) && !c.declared_at.empty() ? workspace_relative(c.declared_at) : section.location;
            const auto claim = [&](const std::string& id, const std::string& scene, std::vector<std::size_t> runs, int order = 0) {
                add({id, "claim", id, scene, scheme, std::move(runs), std::numeric_limits<std::size_t>::max(), order, location});
            };
            if (c.claims_nothing()) {
                if (c.sound)
                    plan_.warnings.push_back(scheme + " registers no claims (SchemeClaims): it is held to the generic sanity "
                                                      "checks only (order at least 0.8, angular momentum within 5 %)");
                for (const auto& scene : section.free_scenes) {
                    if (skipped(scheme, scene)) continue;
                    const auto runs = claim_ladder(scene, scheme);
                    add({"sanity_order", "sanity", "sanity_order", scene, scheme, runs, std::numeric_limits<std::size_t>::max(), 0,
                         section.location});
                    add({"sanity_momentum", "sanity", "sanity_momentum", scene, scheme, {runs.back()},
                         std::numeric_limits<std::size_t>::max(), 0, section.location});
                }
                for (const auto& scene : section.torque_scenes)
                    if (!skipped(scheme, scene))
                        add({"sanity_order", "sanity", "sanity_order", scene, scheme, claim_ladder(scene, scheme),
                         std::numeric_limits<std::size_t>::max(), 0, section.location});
                continue;
            }
            for (const auto& scene : section.free_scenes) {
                if (skipped(scheme, scene)) continue;
                const auto runs = claim_ladder(scene, scheme);
                if (c.without_torque.order > 0) claim("order_without_torque", scene, runs, c.without_torque.order);
                if (c.exact_without_torque) claim("exact_without_torque", scene, runs);
                if (c.conserves_momentum) claim("conserves_momentum", scene, runs);
                if (c.time_reversible) claim("time_reversible", scene, {reversal(scene, scheme)});
            }
            for (const auto& scene : section.torque_scenes) {
                if (skipped(scheme, scene)) continue;
                if (c.with_torque.order > 0) claim("order_with_torque", scene, claim_ladder(scene, scheme), c.with_torque.order);
                if (c.bounded_energy)  // the coarsest step of the ladder
                    claim("bounded_energy", scene, {run({scene, scheme, coarsest(scene), 0.0, claim_scene(scene).params, RunKind::horizon, false})});
                if (c.time_reversible) claim("time_reversible", scene, {reversal(scene, scheme)});
            }
        }
    }

    void checks() {
        for (std::size_t i = 0; i < file_.checks.size(); ++i) {
            const GateCheck& c = file_.checks[i];
            for (const auto& scheme : c.schemes) {
                if (skipped(scheme, c.scene)) continue;
                if (c.criterion == "max_cost_ratio" && client_of(scheme)) {
                    plan_.warnings.push_back(c.name + ": client " + scheme + "'s cost is its program's, not measured: not judged");
                    continue;
                }
                std::vector<std::size_t> runs;
                if (c.criterion == "min_order" || c.criterion == "same_map_as") {
                    runs = ladder(c.scene, scheme, c.dts.empty() ? dts(c.scene, c.params) : c.dts, c.t_end, c.params);
                } else if (c.criterion == "min_stability") {
                    runs = {run({c.scene, scheme, 0.0, c.t_end, c.params, RunKind::stability, false})};
                } else if (c.criterion == "max_cost_ratio") {
                    runs = {run({c.scene, scheme, c.dts[0], c.t_end, c.params, RunKind::cost, true})};
                } else {
                    runs = {run({c.scene, scheme, c.dts[0], c.t_end, c.params, RunKind::trajectory, false})};
                }
                add({c.name, "check", c.criterion, c.scene, scheme, runs, i, 0, c.location});
            }
        }
    }

    GatePlan take() {
        for (const auto& e : file_.expected_failures) {
            const bool used = std::any_of(plan_.cases.begin(), plan_.cases.end(), [&](const GateCase& c) {
                return c.id == e.check && c.scene == e.scene && c.scheme == e.scheme;
            });
            if (!used)
                throw InputError(e.location + ": the expected failure of '" + e.check + "' for " + e.scheme + " on " + e.scene +
                                 " matches no check the gate makes");
        }
        return std::move(plan_);
    }

private:
    // A client that does not take the scene: said in a warning, and nothing planned.
    bool skipped(const std::string& scheme, const std::string& scene) {
        const std::string why = why_not_taken(scheme, scene);
        if (!why.empty() && std::find(plan_.warnings.begin(), plan_.warnings.end(), why + ": not judged there") == plan_.warnings.end())
            plan_.warnings.push_back(why + ": not judged there");
        return !why.empty();
    }
    // A ladder the file leaves to the scene: its default one, or with --quick its finest
    // quick_rungs, where every sound scheme's error is already asymptotic (the coarse rungs are
    // the ones an order fit would set aside).
    std::vector<double> dts(const std::string& scene, const ParamOverrides& params = {}) {
        std::vector<double> ladder = make_scene(scene, params)->default_dts();
        if (quick_ && ladder.size() > quick_rungs) ladder.erase(ladder.begin(), ladder.end() - quick_rungs);
        return ladder;
    }
    // What [claims.SCENE] sets for the claims on a scene (nothing: the scene's ladder and defaults).
    const ClaimScene& claim_scene(const std::string& scene) const {
        static const ClaimScene none;
        const auto found = file_.claims.scenes.find(scene);
        return found == file_.claims.scenes.end() ? none : found->second;
    }
    std::vector<std::size_t> claim_ladder(const std::string& scene, const std::string& scheme) {
        const ClaimScene& settings = claim_scene(scene);
        return ladder(scene, scheme, settings.dts.empty() ? dts(scene, settings.params) : settings.dts, 0.0, settings.params);
    }
    // The bounded-energy and reversal runs' step, with or without --quick: the hardest, the coarsest.
    double coarsest(const std::string& scene) {
        const ClaimScene& settings = claim_scene(scene);
        return settings.dts.empty() ? make_scene(scene, settings.params)->default_dts().front() : settings.dts.front();
    }
    std::size_t reversal(const std::string& scene, const std::string& scheme) {
        return run({scene, scheme, coarsest(scene), 0.0, claim_scene(scene).params, RunKind::reversal, false});
    }

    const GateFile& file_;
    bool quick_;  // gate --quick
    GatePlan plan_;
    std::map<RunSpec, std::size_t> index_;
    std::map<std::pair<std::string, ParamOverrides>, double> t_ends_;  // each scene's default duration
};

}  // namespace

GatePlan plan_gate(const GateFile& file, bool quick) {
    Planner planner(file, quick);
    planner.claims();
    planner.checks();
    GatePlan plan = planner.take();
    plan.warnings.insert(plan.warnings.begin(), file.warnings.begin(), file.warnings.end());
    for (const auto& p : loaded_plugins())
        if (const std::string w = build_warning(p); !w.empty()) plan.warnings.push_back(w);
    return plan;
}

}  // namespace rotbench
