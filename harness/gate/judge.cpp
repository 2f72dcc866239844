// The verdicts of a gate: pure functions of the cases and the results of their runs. A claim
// is judged by the claims module (harness/analysis/claims.hpp), a [[check]] here. Every bound
// is stated in the message with where it comes from.
#include "harness/analysis/claims.hpp"
#include "harness/gate/gate.hpp"
#include "harness/store/plugin.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {
namespace {

using Runs = RunRefs;

// The judgement as the verdict's figures, its message after `name`.
void take(Verdict& v, const Judgement& j, const std::string& name) {
    v.passed = j.passed, v.measured = j.measured, v.lo = j.lo, v.hi = j.hi, v.bound = j.bound;
    v.message = name + ": " + j.message;
}

// A claim of the scheme on the scene, judged by the claims module.
Judgement judge_claim(const GateCase& c, const Runs& runs) {
    if (c.id == "order_without_torque" || c.id == "order_with_torque") return judge_order(runs, c.claimed_order);
    if (c.id == "exact_without_torque") return judge_exact(runs);
    if (c.id == "conserves_momentum") return judge_momentum(runs);
    if (c.id == "bounded_energy") return judge_bounded_energy(*runs.front());
    if (c.id == "time_reversible") return judge_reversal(*runs.front());
    if (c.id == "sanity_order") return judge_sanity_order(runs);
    if (c.id == "sanity_momentum") return judge_sanity_momentum(*runs.front());
    throw std::logic_error("no judge for the claim " + c.id);
}

// The [[check]] criteria.
void judge_check(Verdict& v, const GateCheck& c, const Runs& runs) {
    v.bound = c.bound;
    const std::string name = fmt::format("{} on {}", c.name, c.scene);
    if (c.criterion == "min_order") {
        take(v, judge_min_order(runs, c.metric, c.bound, c.round_off), name);
        return;
    }
    if (c.criterion == "same_map_as") {
        take(v, judge_same_map(runs, c.same_map_as), name);
        return;
    }
    const RunResult& r = *runs.front();
    if (!r.failure.empty()) {
        v.message = name + ": the run failed: " + r.failure;
        return;
    }
    if (c.criterion == "min_stability") {
        take(v, judge_stability_margin(r, c.bound), name);
    } else if (c.criterion == "max_cost_ratio") {
        take(v, judge_cost_ratio(r, c.bound), name);
        if (const LoadedPlugin* p = plugin_of(r.spec.scheme); p && !p->built_like_builtins()) {
            v.passed = false;  // whatever it measured: an unoptimised build says nothing of the scheme's cost
            v.message = name + ": not judged: " + build_warning(*p) + " (measured: " + judge_cost_ratio(r, c.bound).message + ")";
        }
    } else {
        v.measured = r.value(c.metric);
        if (std::isnan(v.measured)) {
            v.message = fmt::format("{}: scene '{}' has no {}", name, c.scene, c.metric);
            return;
        }
        v.passed = v.measured <= c.bound;
        v.message = fmt::format("{}: {} = {} at dt = {}, required <= {}", name, c.metric, figure(v.measured), figure(r.spec.dt), figure(c.bound));
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
    result.gate_file = file.path, result.gate_file_hash = file.hash;
    std::vector<std::string> judged;
    for (const GateCase& c : plan.cases) judged.push_back(c.scheme);
    result.schemes = describe_schemes(judged, {});
    for (const GateCase& c : plan.cases) {
        Verdict v;
        v.of = c;
        Runs used;
        for (std::size_t i : c.runs) {
            used.push_back(&runs.at(i));
            // A built-in's CPU time; a client's program's wall time (its cost is its own).
            const double cpu = runs[i].value(metric::cpu_seconds_run), wall = runs[i].value(metric::client_wall_seconds);
            if (std::isfinite(cpu)) v.seconds += cpu;
            else if (std::isfinite(wall)) v.seconds += wall;
        }
        // A client that declined a run of the case ("not mine", docs/clients.md): skipped with a warning, as an unlisted scene is.
        if (const auto d = std::find_if(used.begin(), used.end(), [](const RunResult* r) { return r->declined(); });
            d != used.end()) {
            const std::string w = fmt::format("client {} declined scene {} ({}): not judged there", c.scheme, c.scene, (*d)->failure);
            if (std::find(result.warnings.begin(), result.warnings.end(), w) == result.warnings.end()) result.warnings.push_back(w);
            continue;
        }
        if (c.family == "check") {
            judge_check(v, file.checks.at(c.check), used);
        } else {
            take(v, judge_claim(c, used), c.id + " on " + c.scene);
        }
        v.message = v.of.scheme + ": " + v.message;
        result.verdicts.push_back(std::move(v));
    }
    result.runs = std::move(runs);
    return result;
}

}  // namespace rotbench
