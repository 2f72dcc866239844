#include "reports/granular_report.hpp"

#include "harness/analysis/ensemble.hpp"
#include "reports/granular_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

struct SceneMetrics {
    std::string scene;
    std::vector<std::string> metrics;  // in the order shown
};
const std::vector<SceneMetrics> granular_scenes = {
    {"silo_discharge", {"discharge_time", "mass_flow_rate", "repose_angle", "mass_left_end", "clogged"}},
    {"direct_shear",
     {"shear_stress_peak", "shear_stress_final", "normal_stress_mean", "inertial_number", "solid_fraction", "escaped_stones"}},
};

// Seed 000's published differences from its quaternion scheme (Tables 4 and 5), in %, by the
// rotbench id of the scheme that reproduces each of its schemes. Both tables print sizes only;
// Table 4's signs follow from its values, Table 5 gives none.
struct Published {
    std::string scene, metric, scheme, value;
};
const std::vector<Published> published = {
    {"silo_discharge", "discharge_time", "direct", "6.90 s, 2.22 %"},
    {"silo_discharge", "discharge_time", "munjiza_rk4", "6.70 s, 0.74 %"},
    {"silo_discharge", "discharge_time", "zvw_corrected", "6.75 s"},
    {"silo_discharge", "repose_angle", "direct", "35.8°, 4.78 %"},
    {"silo_discharge", "repose_angle", "munjiza_rk4", "37.3°, 0.80 %"},
    {"silo_discharge", "repose_angle", "zvw_corrected", "37.6°"},
    {"silo_discharge", metric::cpu_seconds_per_simulated_second, "direct", "17.77 h/s, 0.23 %"},
    {"silo_discharge", metric::cpu_seconds_per_simulated_second, "munjiza_rk4", "17.76 h/s, 0.19 %"},
    {"silo_discharge", metric::cpu_seconds_per_simulated_second, "zvw_corrected", "17.73 h/s"},
    {"direct_shear", "shear_stress_final", "direct", "23.37 / 22.94 / 15.94 % at 27 / 51 / 75 kPa (sizes; no sign given)"},
    {"direct_shear", "shear_stress_final", "munjiza_rk4", "0.59 / 0.47 / 0.26 % at 27 / 51 / 75 kPa (sizes; no sign given)"},
};

std::string published_for(const std::string& scene, const std::string& metric, const std::string& scheme) {
    for (const Published& p : published)
        if (p.scene == scene && p.metric == metric && p.scheme == scheme) return p.value;
    return "";
}

std::string value_cell(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : "—"; }

std::string with_interval(const RunResult& r, const std::string& metric) {
    const double mean = r.value(metric), half = r.value(metric + "_ci95");
    if (!std::isfinite(half)) return value_cell(mean);
    return value_cell(mean) + " ± " + value_cell(half);
}

std::string difference(const RunResult& r, const std::string& metric) {
    const double d = r.value(metric + "_diff"), half = r.value(metric + "_diff_ci95");
    if (!std::isfinite(d)) return r.spec.scheme == ensemble_reference_scheme ? "reference" : "—";
    const bool beyond = std::abs(d) > half;
    return fmt::format("{:+.2f} ± {:.2f} %{}", d, half, beyond ? " **beyond the scatter**" : " within the scatter");
}

}  // namespace

std::string granular_section(const ResultSet& set, const OutputDir& dir) {
    std::string md;
    for (const SceneMetrics& scene : granular_scenes) {
        std::vector<const RunResult*> runs;
        for (const RunResult& r : set.runs)
            if (r.spec.scene == scene.scene) runs.push_back(&r);
        if (runs.empty()) continue;
        if (md.empty())
            md = "## " + granular_heading + "\n\n" +
                 fmt::format(
                     "Chaotic flows: one run per scheme says nothing until it is set against the scatter between equally "
                     "valid runs. With `--ensemble K`, each scheme runs on K packings (seeds) and each metric is given as the "
                     "mean ± the half-width of its 95 % interval; the difference from `{}` (the seed's reference, its "
                     "quaternion scheme) is paired over the same seeds, in % of that scheme's mean, with its own 95 % "
                     "interval: **beyond the scatter** when the interval excludes 0. Seed Tables 4 and 5 give one run "
                     "per scheme, at full scale (4497 stones, dt = 1e-6 s); their differences are printed beside.\n\n",
                     ensemble_reference_scheme);
        std::map<double, std::vector<const RunResult*>> by_dt;
        for (const RunResult* r : runs) by_dt[r->spec.dt].push_back(r);
        for (const auto& [dt, group] : by_dt) {
            const double members = group.front()->has(metric::ensemble_size) ? group.front()->value(metric::ensemble_size) : 1.0;
            md += fmt::format("### `{}` at dt = {:g} s, ensemble of {:.0f}\n\n", scene.scene, dt, members);
            for (const std::string& metric : scene.metrics) {
                md += fmt::format("| {} | mean ± 95 % | difference from {} | seed 000 |\n|---|--:|--:|---|\n", metric,
                                  ensemble_reference_scheme);
                for (const RunResult* r : group)
                    md += fmt::format("| {} | {} | {} | {} |\n", r->spec.scheme, with_interval(*r, metric), difference(*r, metric),
                                      published_for(scene.scene, metric, r->spec.scheme));
                md += "\n";
            }
            md += "Cost of a whole DEM step (contact search and forces included), measured in the runs themselves; a client's is "
                  "its program's whole CPU time over the simulated time, start-up included (\"client\"):\n\n"
                  "| scheme | CPU s per simulated s | rotation's share of a step | seed 000 (Table 4) |\n|---|--:|--:|---|\n";
            for (const RunResult* r : group) {
                const std::string cost = r->has(metric::client_cpu_seconds_per_simulated_second)
                                             ? value_cell(r->value(metric::client_cpu_seconds_per_simulated_second)) + " (client)"
                                             : value_cell(r->value(metric::cpu_seconds_per_simulated_second));
                md += fmt::format("| {} | {} | {} | {} |\n", r->spec.scheme, cost,
                                  std::isfinite(r->value(metric::rotation_share)) ? fmt::format("{:.1f} %", 100.0 * r->value(metric::rotation_share)) : "—",
                                  published_for(scene.scene, metric::cpu_seconds_per_simulated_second, r->spec.scheme));
            }
            md += "\n";
            for (const RunResult* r : group)
                if (r->value(metric::ensemble_failed) > 0 || !r->failure.empty())
                    md += fmt::format("- {}: {:.0f} of {:.0f} runs failed{}.\n", r->spec.scheme,
                                      r->has(metric::ensemble_failed) ? r->value(metric::ensemble_failed) : 1.0, members,
                                      r->failure.empty() ? "" : ": " + r->failure);
            md += "\n" + granular_pictures(scene.scene, dt, group, set, dir);
        }
    }
    return md;
}

}  // namespace rotbench
