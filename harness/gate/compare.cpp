#include "harness/gate/compare.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace rotbench {
namespace {

std::string run_name(const RunSpec& s) { return fmt::format("{} {} {} dt={}", s.scene, s.scheme, kind_name(s.kind), figure(s.dt)); }

Verdict verdict(const std::string& id, const std::string& scene, const std::string& scheme, const std::string& where,
                const Judgement& j) {
    Verdict v;
    v.of.id = v.of.criterion = id;
    v.of.family = "baseline";
    v.of.scene = scene;
    v.of.scheme = scheme;
    v.of.location = where;
    v.passed = j.passed;
    v.measured = j.measured;
    v.bound = j.bound;
    v.message = fmt::format("{}: {} on {}: {}", scheme, id, scene, j.message);
    return v;
}

}  // namespace

double MetricChange::change() const { return base == now ? 0.0 : (now - base) / std::abs(base); }

Comparison compare_runs(const std::vector<RunResult>& base, const std::vector<RunResult>& now, const BaselineTolerances& t,
                        const std::string& where) {
    Comparison c;
    using Pair = std::pair<std::string, std::string>;  // scene, scheme
    std::map<RunSpec, const RunResult*> by_key;
    std::map<Pair, RunRefs> base_ladders, new_ladders;  // trajectory runs: all of BASE's, NEW's matched ones
    for (const auto& r : base) {
        by_key[computed_key(r.spec)] = &r;
        if (r.spec.kind == RunKind::trajectory) base_ladders[{r.spec.scene, r.spec.scheme}].push_back(&r);
    }
    std::vector<Pair> pairs;  // in the order of the new runs
    std::map<Pair, RunPairs> matched;
    std::map<RunSpec, bool> seen;
    for (const auto& r : now) {
        const auto it = by_key.find(computed_key(r.spec));
        if (it == by_key.end()) {
            c.notes.push_back(run_name(r.spec) + ": not in the baseline");
            continue;
        }
        seen[it->first] = true;
        const Pair pair{r.spec.scene, r.spec.scheme};
        if (!matched.count(pair)) pairs.push_back(pair);
        matched[pair].push_back({it->second, &r});
        if (r.spec.kind == RunKind::trajectory) new_ladders[pair].push_back(&r);
        for (const auto& [metric, value] : r.metrics)
            if (it->second->has(metric) && !is_timing_metric(metric)) c.changes.push_back({r.spec, metric, it->second->value(metric), value});
    }
    if (pairs.empty()) {  // comparing nothing proves nothing
        Judgement j;
        j.message = fmt::format("no run of the new results is in the baseline ({} new, {} in the baseline): nothing was compared",
                                now.size(), base.size());
        c.verdicts.push_back(verdict("baseline_matched", "(any scene)", "(any scheme)", where, j));
    }
    // A run of BASE that NEW lacks is a regression: what it showed is no longer shown.
    std::map<Pair, std::vector<std::string>> missing;
    for (const auto& r : base)
        if (!seen.count(computed_key(r.spec))) missing[{r.spec.scene, r.spec.scheme}].push_back(fmt::format("{} dt={}", kind_name(r.spec.kind), figure(r.spec.dt)));
    for (const auto& [pair, runs] : missing) {
        Judgement j;
        j.measured = static_cast<double>(runs.size());
        j.message = fmt::format("{} run{} of the baseline not in the new results ({}): what {} showed is no longer shown", runs.size(),
                                runs.size() == 1 ? "" : "s", fmt::join(runs, ", "), runs.size() == 1 ? "it" : "they");
        c.verdicts.push_back(verdict("baseline_matched", pair.first, pair.second, where, j));
    }
    for (const auto& pair : pairs) {
        const RunPairs& runs = matched[pair];
        const CostJudgement cost = judge_baseline_cost(runs, t);
        for (const auto& [id, j] : {std::pair<std::string, Judgement>{"baseline_accuracy", judge_baseline_accuracy(runs, t)},
                                    {"baseline_order", judge_baseline_order(base_ladders[pair], new_ladders[pair], t)},
                                    {"baseline_stability", judge_baseline_stability(runs, t)},
                                    {"baseline_cost", cost}})
            c.verdicts.push_back(verdict(id, pair.first, pair.second, where, j));
        if (!cost.tested) c.notes.push_back(c.verdicts.back().message);
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
