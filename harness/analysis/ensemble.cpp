#include "harness/analysis/ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace rotbench {
namespace {

std::optional<double> seed_of(const RunSpec& spec) {
    std::optional<double> seed;
    for (const auto& [key, values] : spec.params)
        if (key == "seed" && values.size() == 1) seed = values[0];
    return seed;
}

ParamOverrides without_seed(const ParamOverrides& params) {
    ParamOverrides out;
    for (const auto& p : params)
        if (p.first != "seed") out.push_back(p);
    return out;
}


// Counts and flags: averaged, no interval.
bool is_count(const std::string& name) {
    const MetricInfo* m = find_metric(name);
    return m && (m->kind == MetricKind::timing || m->kind == MetricKind::count || m->kind == MetricKind::flag || m->kind == MetricKind::failure);
}

struct Summary {
    double mean = NAN, half_width = NAN;
};
// Mean and the half-width of the 95 % Student interval of the finite values.
Summary summarise(const std::vector<double>& values) {
    double n = 0, sum = 0;
    for (double v : values)
        if (std::isfinite(v)) n += 1, sum += v;
    if (n == 0) return {};
    const double mean = sum / n;
    if (n < 2) return {mean, NAN};
    double ss = 0;
    for (double v : values)
        if (std::isfinite(v)) ss += (v - mean) * (v - mean);
    return {mean, gsl_cdf_tdist_Pinv(0.975, n - 1) * std::sqrt(ss / (n - 1)) / std::sqrt(n)};
}

// The members' curves as one band: the abscissa, then for each other column its mean over the
// members, then its least and its largest value, row by row over the rows every member has at
// the same abscissa (the same dt samples the same instants). Only members that did not fail
// and recorded a curve count; with none, no band.
void collapse_curves(const std::vector<const RunResult*>& members, RunResult& c) {
    std::vector<const RunResult*> curves;
    for (const RunResult* m : members)
        if (m->failure.empty() && !m->series.empty() && !m->has_energy_series()) curves.push_back(m);
    if (curves.empty()) return;
    const RunResult& first = *curves.front();
    std::size_t rows = first.series.size();
    for (const RunResult* m : curves) {
        if (m->series_columns != first.series_columns) return;
        rows = std::min(rows, m->series.size());
        for (std::size_t k = 0; k < rows; ++k)
            if (m->series[k].at(0) != first.series[k].at(0)) rows = k;
    }
    const std::size_t ys = first.series_columns.size() - 1;
    c.series_columns = {first.series_columns.front()};
    for (const char* suffix : {"", "_min", "_max"})
        for (std::size_t j = 1; j <= ys; ++j) c.series_columns.push_back(first.series_columns[j] + suffix);
    for (std::size_t k = 0; k < rows; ++k) {
        std::vector<double> row(1 + 3 * ys, 0.0);
        row[0] = first.series[k][0];
        for (std::size_t j = 1; j <= ys; ++j) {
            double lo = INFINITY, hi = -INFINITY;
            for (const RunResult* m : curves) {
                const double v = m->series[k][j];
                row[j] += v / static_cast<double>(curves.size());
                lo = std::min(lo, v), hi = std::max(hi, v);
            }
            row[ys + j] = lo, row[2 * ys + j] = hi;
        }
        c.series.push_back(std::move(row));
    }
}

}  // namespace

RunSpec ensemble_of(RunSpec s) {
    s.params = without_seed(s.params);
    return s;
}

ParamOverrides ensemble_member(const ParamOverrides& overrides, double base_seed, int k) {
    ParamOverrides out = without_seed(overrides);
    out.push_back({"seed", {base_seed + k}});
    return out;
}

std::vector<RunResult> collapse_ensembles(const std::vector<RunResult>& runs) {
    std::map<RunSpec, std::vector<const RunResult*>> groups;
    for (const RunResult& r : runs)
        if (seed_of(r.spec)) groups[ensemble_of(r.spec)].push_back(&r);
    std::vector<RunResult> out;
    std::set<RunSpec> emitted;
    for (const RunResult& r : runs) {
        const auto found = seed_of(r.spec) ? groups.find(ensemble_of(r.spec)) : groups.end();
        if (found == groups.end() || found->second.size() < 2) {
            out.push_back(r);
            continue;
        }
        if (!emitted.insert(found->first).second) continue;  // collapsed at its first member
        const std::vector<const RunResult*>& members = found->second;
        RunResult c;
        c.spec = r.spec;
        c.spec.params = without_seed(r.spec.params);
        // The reference scheme's members by seed, for the paired differences.
        std::map<double, const RunResult*> reference;
        if (r.spec.scheme != ensemble_reference_scheme) {
            RunSpec key = found->first;
            key.scheme = ensemble_reference_scheme;
            if (const auto ref = groups.find(key); ref != groups.end())
                for (const RunResult* m : ref->second) reference[*seed_of(m->spec)] = m;
        }
        std::vector<std::string> names;  // in the first member's order
        for (const RunResult* m : members)
            for (const auto& [name, value] : m->metrics)
                if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        double failed = 0;
        for (const RunResult* m : members) failed += !m->failure.empty();
        for (const std::string& name : names) {
            std::vector<double> values, differences, reference_values;
            for (const RunResult* m : members) {
                const double v = m->failure.empty() ? m->value(name) : NAN;
                values.push_back(v);
                const auto ref = reference.find(*seed_of(m->spec));
                if (ref == reference.end() || !ref->second->failure.empty()) continue;
                const double rv = ref->second->value(name);
                if (std::isfinite(v) && std::isfinite(rv)) differences.push_back(v - rv), reference_values.push_back(rv);
            }
            const Summary s = summarise(values);
            c.metrics.emplace_back(name, s.mean);
            if (is_count(name)) continue;
            c.metrics.emplace_back(name + "_ci95", s.half_width);
            if (differences.size() >= 2) {
                const Summary d = summarise(differences), base = summarise(reference_values);
                c.metrics.emplace_back(name + "_diff", 100.0 * d.mean / base.mean);
                c.metrics.emplace_back(name + "_diff_ci95", 100.0 * d.half_width / std::abs(base.mean));
            }
        }
        c.metrics.emplace_back(metric::ensemble_size, static_cast<double>(members.size()));
        c.metrics.emplace_back(metric::ensemble_failed, failed);
        if (failed == static_cast<double>(members.size())) c.failure = members.front()->failure;
        for (const RunResult* m : members) c.timing_samples.insert(c.timing_samples.end(), m->timing_samples.begin(), m->timing_samples.end());
        collapse_curves(members, c);
        for (const RunResult* m : members)  // the pictures of the first member that has them
            if (m->failure.empty() && !m->snapshots.empty()) {
                c.snapshots = m->snapshots;
                c.walls = m->walls;
                break;
            }
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<bool> ensemble_members(const std::vector<RunResult>& runs) {
    std::map<RunSpec, int> sizes;
    for (const RunResult& r : runs)
        if (seed_of(r.spec)) ++sizes[ensemble_of(r.spec)];
    std::vector<bool> out;
    for (const RunResult& r : runs) out.push_back(seed_of(r.spec) && sizes[ensemble_of(r.spec)] >= 2);
    return out;
}

double member_seed(const RunSpec& spec) { return seed_of(spec).value_or(NAN); }

}  // namespace rotbench
