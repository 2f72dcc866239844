#include "reports/energy_series.hpp"

#include "harness/store/output_files.hpp"
#include "harness/store/series_csv.hpp"
#include "reports/gnuplot.hpp"
#include "reports/panels.hpp"
#include "reports/seed_figures.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace rotbench {
namespace {

// A run that blew up (its failure, the stability criterion's verdict) would set its panel's scale
// and flatten the others to a line: a panel is scaled to the runs that did not, and the key says
// when each other one blew up (or that it failed otherwise).
std::string y_range(const std::vector<const RunResult*>& panel_runs) {
    double lo = INFINITY, hi = -INFINITY;
    bool blown = false;
    for (const RunResult* r : panel_runs) {
        if (!r->failure.empty()) {
            blown = true;
            continue;
        }
        for (const auto& row : r->series)
            if (std::isfinite(row.at(1))) lo = std::min(lo, row.at(1)), hi = std::max(hi, row.at(1));
    }
    if (!blown || !(hi > lo)) return "set autoscale y\n";
    const double pad = 0.05 * (hi - lo);
    return fmt::format("set yrange [{}:{}]\n", format_number(lo - pad), format_number(hi + pad));
}

std::string plot_script(const std::string& scene, double dt, const std::vector<const RunResult*>& runs, const ResultSet& set) {
    std::vector<std::string> schemes;
    for (const RunResult* r : runs) schemes.push_back(r->spec.scheme);
    const auto panels = family_panels(set, schemes);
    const std::string setup = "set datafile separator ','\nset xlabel 't (s)'\nset ylabel '(E - E0) / |E0| (relative)'\nset grid\n";
    return panel_grid_script(gnuplot_output(fmt::format("energy_{}_dt{}.svg", scene, dt_tag(dt))),
                             fmt::format("Relative energy error, {}, dt = {:g} s", scene, dt), setup, panels, [&](std::size_t p) {
                                 std::vector<const RunResult*> panel_runs;
                                 for (const auto& scheme : panels[p].schemes)
                                     panel_runs.push_back(runs[std::find(schemes.begin(), schemes.end(), scheme) - schemes.begin()]);
                                 std::string line = y_range(panel_runs) + "plot ";
                                 for (std::size_t i = 0; i < panel_runs.size(); ++i) {
                                     const RunResult& r = *panel_runs[i];
                                     line += fmt::format("{}'../series/{}' using 1:2 with lines {} title '{}'", i ? ", \\\n     " : "",
                                                         series_file_name(r), scheme_style(set, r.spec.scheme, i), r.spec.scheme);
                                     const double failed_at = r.value(metric::fail_time);  // NaN for a run that threw
                                     if (!r.failure.empty())
                                         line += fmt::format(", keyentry with lines lt nodraw title '{}'",
                                                             std::isfinite(failed_at) ? fmt::format("(blew up, t = {:.3g} s)", failed_at)
                                                                                      : std::string("(failed)"));
                                 }
                                 return line + "\n";
                             });
}

const std::vector<std::string> seed_schemes = {"direct", "munjiza_rk4", "zvw", "zvw_corrected"};

double final_error(const RunResult& r) { return r.series.empty() ? NAN : std::abs(r.series.back().at(1)); }

// How the largest energy error of each scheme falls with dt, between the coarsest and
// the finest step of a scene: the slope of log error against log dt.
std::string energy_slopes(const std::map<std::pair<std::string, double>, std::vector<const RunResult*>>& groups) {
    std::map<std::string, std::map<std::string, std::vector<std::pair<double, double>>>> points;  // scene, scheme
    for (const auto& [key, runs] : groups)
        for (const RunResult* r : runs) points[key.first][r->spec.scheme].push_back({r->spec.dt, r->value(metric::energy_drift_max)});
    std::string md;
    for (const auto& [scene, by_scheme] : points) {
        std::string line;
        for (const auto& [scheme, p] : by_scheme) {
            const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
            if (p.size() < 2 || !(lo->second > 0.0) || !(hi->second > 0.0)) continue;
            const double slope = std::log(hi->second / lo->second) / std::log(hi->first / lo->first);
            line += fmt::format("{}{} {:.2f}", line.empty() ? "" : ", ", scheme, slope);
        }
        if (!line.empty())
            md += fmt::format("Slope of log(largest energy error) against log(dt) on `{}`, from dt = {:g} to {:g}: {}.\n\n", scene,
                              by_scheme.begin()->second.front().first, by_scheme.begin()->second.back().first, line);
    }
    return md;
}

}  // namespace

std::string energy_series_section(const ResultSet& set, const OutputDir& dir, const ParallelWork& parallel) {
    const std::vector<RunResult>& results = set.runs;
    // Plotted per scene: the coarsest and the finest step, and the steps of the seed's figures.
    std::map<std::string, std::pair<double, double>> range;  // scene -> (finest, coarsest)
    for (const auto& r : results)
        if (r.has_energy_series()) {
            auto [it, fresh] = range.try_emplace(r.spec.scene, r.spec.dt, r.spec.dt);
            it->second = {std::min(it->second.first, r.spec.dt), std::max(it->second.second, r.spec.dt)};
        }
    auto plotted = [&](const RunResult& r) {
        const auto& [finest, coarsest] = range.at(r.spec.scene);
        if (r.spec.dt == finest || r.spec.dt == coarsest) return true;
        return std::any_of(seed_energy_orderings().begin(), seed_energy_orderings().end(), [&](const auto& p) {
            return p.scene == r.spec.scene && std::abs(p.dt / r.spec.dt - 1.0) < 1e-12;
        });
    };
    std::map<std::pair<std::string, double>, std::vector<const RunResult*>> groups;
    std::map<std::pair<std::string, double>, std::vector<const RunResult*>> all_groups;  // for the slopes
    for (const auto& r : results)
        if (r.has_energy_series()) {
            all_groups[{r.spec.scene, r.spec.dt}].push_back(&r);
            if (plotted(r)) groups[{r.spec.scene, r.spec.dt}].push_back(&r);
        }
    if (groups.empty()) return "";

    std::string md = "## Energy against time\n\n"
                     "Relative energy error (E - E0)/|E0| of each scheme, for every scene whose true motion conserves "
                     "energy, at its coarsest and finest step; the seed's Figures 9-11 show the same quantity for "
                     "the bouncing fibre at dt = 1e-7 and 1e-5. Data: `series/`, plots and their gnuplot scripts: "
                     "`plots/`.\n\n";
    // The groups on every core (gnuplot draws one plot per process); their parts join in order.
    const std::vector group_list(groups.begin(), groups.end());
    std::vector<std::string> parts(group_list.size());
    parallel(group_list.size(), [&](std::size_t g) {
        const std::string& scene = group_list[g].first.first;
        const double dt = group_list[g].first.second;
        const std::vector<const RunResult*>& runs = group_list[g].second;
        std::string& md = parts[g];
        const std::string name = fmt::format("energy_{}_dt{}", scene, dt_tag(dt));
        const Drawn drawn = draw_with_gnuplot(dir, "plots/" + name + ".gp", plot_script(scene, dt, runs, set), "plots/" + name + ".svg");
        md += fmt::format("### `{}`, dt = {:g} s\n\n", scene, dt);
        md += drawn.ok ? fmt::format("![energy error, {} dt = {:g}](plots/{}.svg)\n\n", scene, dt, name)
                       : fmt::format("(plot not drawn: {}; script `plots/{}.gp`)\n\n", drawn.why, name);

        std::vector<const RunResult*> ranked = runs;
        std::stable_sort(ranked.begin(), ranked.end(), [](const RunResult* a, const RunResult* b) {
            return final_error(*a) < final_error(*b);
        });
        md += "| scheme | energy error at the end (abs.) | largest energy error (abs.) |\n|---|---:|---:|\n";
        for (const RunResult* r : ranked)
            md += fmt::format("| {} | {:.3e} | {:.3e} |\n", r->spec.scheme, final_error(*r), r->value(metric::energy_drift_max));
        std::string order;
        for (const RunResult* r : ranked) order += (order.empty() ? "" : " < ") + r->spec.scheme;
        md += fmt::format("\nOrdering by the final error, best first: {}.\n", order);

        for (const auto& published : seed_energy_orderings()) {
            if (published.scene != scene || std::abs(published.dt / dt - 1.0) > 1e-12) continue;
            // The computed ranking of the seed's schemes: it must equal the published one,
            // or, where the seed only names the best scheme, start with it.
            std::vector<std::string> computed;
            for (const RunResult* r : ranked)
                if (std::find(seed_schemes.begin(), seed_schemes.end(), r->spec.scheme) != seed_schemes.end())
                    computed.push_back(r->spec.scheme);
            const auto& claim = published.best_to_worst;
            const bool agrees = claim.size() == 1 ? (!computed.empty() && computed.front() == claim.front()) : computed == claim;
            md += fmt::format("The seed: {}. Here the ordering {} the seed's{}.\n", published.statement,
                              agrees ? "agrees with" : "differs from",
                              agrees ? "" : fmt::format(" (seed, best first: {}; here: {})",
                                                        fmt::join(published.best_to_worst, " < "),
                                                        fmt::join(computed, " < ")));
        }
        md += "\n";
    });
    for (const auto& part : parts) md += part;
    md += energy_slopes(all_groups);
    return md;
}

}  // namespace rotbench
