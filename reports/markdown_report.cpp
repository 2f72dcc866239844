#include "reports/markdown_report.hpp"

#include "build_info.hpp"
#include "references/odeint_reference.hpp"
#include "reports/energy_series.hpp"
#include "reports/seed_table1.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>

namespace rotbench {
namespace {

// Columns of the per-scene tables, in this order, when any run of the scene has them.
const std::vector<std::string> table_metrics = {
    "omega_rms_x",       "omega_rms_y",        "omega_rms_z",       "omega_err_max", "orientation_err_max",
    "energy_drift_max",  "momentum_drift_max", "quat_norm_err_max", "steps",         "force_evals",
    "ns_per_step",       "unstable"};

std::string cell(const std::string& metric, double v) {
    if (std::isnan(v)) return "—";
    if (metric == "steps" || metric == "force_evals" || metric == "unstable") return fmt::format("{:.0f}", v);
    if (metric == "ns_per_step") return fmt::format("{:.0f}", v);
    return fmt::format("{:.3e}", v);
}

std::vector<std::string> unique_in_order(const std::vector<RunResult>& results, std::string RunSpec::*field) {
    std::vector<std::string> out;
    for (const auto& r : results)
        if (std::find(out.begin(), out.end(), r.spec.*field) == out.end()) out.push_back(r.spec.*field);
    return out;
}

void scene_section(std::string& md, const std::string& scene_id, const std::vector<RunResult>& results) {
    const auto& entry = SceneRegistry::instance().at(scene_id, "scene");
    std::vector<const RunResult*> runs;
    for (const auto& r : results)
        if (r.spec.scene == scene_id) runs.push_back(&r);
    md += fmt::format("## Scene `{}`\n\n{}. Source: {}. Duration {} s.\n\n", scene_id, entry.summary, entry.source,
                      runs.front()->spec.t_end);
    const auto scene = make_scene(scene_id, runs.front()->spec.params);
    switch (scene->reference_kind()) {
        case Scene::ReferenceKind::closed_form: md += "Reference: closed form.\n\n"; break;
        case Scene::ReferenceKind::odeint:
            md += fmt::format("Reference: Boost.Odeint (Fehlberg 7(8), tolerance {:g}), sampled at every step.\n\n",
                              reference_tolerance);
            break;
        case Scene::ReferenceKind::none: md += "No step-by-step reference; the true motion conserves its energy.\n\n"; break;
    }
    if (!runs.front()->spec.params.empty()) {
        md += "Parameters set:";
        for (const auto& [key, values] : runs.front()->spec.params) md += fmt::format(" `{}` = {};", key, fmt::join(values, ", "));
        md += "\n\n";
    }
    if (!entry.notes.empty()) md += entry.notes + "\n\n";

    std::vector<std::string> columns;
    for (const auto& m : table_metrics)
        if (std::any_of(runs.begin(), runs.end(), [&](const RunResult* r) { return r->has(m); })) columns.push_back(m);
    md += "| scheme | dt (s) |";
    for (const auto& c : columns) md += " " + c + " |";
    md += "\n|---|---:|";
    for (std::size_t i = 0; i < columns.size(); ++i) md += "---:|";
    md += "\n";
    for (const RunResult* r : runs) {
        md += fmt::format("| {} | {:g} |", r->spec.scheme, r->spec.dt);
        for (const auto& c : columns) md += " " + cell(c, r->value(c)) + " |";
        md += "\n";
    }
    md += "\n";
    for (const RunResult* r : runs)
        if (!r->failure.empty())
            md += fmt::format("- **{} at dt = {:g} failed**: {}.\n", r->spec.scheme, r->spec.dt, r->failure);
    md += "\n";
}

void table1_section(std::string& md, const std::vector<RunResult>& results) {
    const auto rows = compare_table1(results);
    if (rows.empty()) return;
    md += "## Seed Table 1 reproduced\n\n"
          "Published (seed 000, Table 1, \"mean squared error\") and computed error of the body-frame angular "
          "velocity on `cylinder_free`. The published quantity is read as the root mean square over the "
          "steps t = dt, 2 dt, ..., 0.5 s (the initial, exact state excluded) of the difference from the exact "
          "solution: a mean of squares would fall as dt^4, not dt^2 as the table does. Including t = 0 would "
          "shift the dt = 1e-2 row by 1 % and leave the others unchanged. The seed's eq. 65b prints "
          "w'y = sin 50t; Euler's equations give cos 50t for this start. The seed's \"Quaternion int.\" is "
          "`zvw_corrected`; `zvw` gives the same numbers without torque, as the seed says.\n\n"
          "| dt (s) | scheme | | published | computed | difference | within 1 % |\n"
          "|---:|---|---|---:|---:|---:|---|\n";
    int agree_main = 0, total_main = 0;
    std::vector<const Table1Comparison*> noted;
    for (const auto& row : rows) {
        const bool main_range = row.entry.dt >= 1e-5;
        total_main += main_range;
        agree_main += main_range && row.agrees;
        md += fmt::format("| {:g} | {} ({}) | w'{} | {:.2e} | {:.4e} | {:+.2f} % | {} |\n", row.entry.dt,
                          row.entry.published_name, row.entry.scheme, row.entry.component, row.entry.published,
                          row.computed, 100.0 * row.relative_difference, row.agrees ? "yes" : "**no**");
        if (!row.agrees && !row.entry.note.empty()) noted.push_back(&row);
    }
    md += fmt::format("\n{} of {} entries with dt from 1e-2 to 1e-5 agree within 1 %.\n\n", agree_main, total_main);
    std::set<std::string> explained;
    for (const auto* row : noted) {
        const std::string key = row->entry.scheme + fmt::format("{:g}", row->entry.dt);
        if (!explained.insert(key).second) continue;
        md += fmt::format("- **{} at dt = {:g}**: {}\n", row->entry.published_name, row->entry.dt, row->entry.note);
    }
    md += "\n";
}

void schemes_section(std::string& md, const std::vector<RunResult>& results) {
    md += "## Schemes and the readings of the seed's equations\n\n";
    for (const auto& id : unique_in_order(results, &RunSpec::scheme)) {
        const auto& s = SchemeRegistry::instance().at(id, "scheme");
        md += fmt::format("- **`{}`**: {}. Source: {}.", id, s.summary, s.source);
        if (!s.notes.empty()) md += " Reading: " + s.notes;
        md += "\n";
    }
    md += "\n";
}

}  // namespace

std::string markdown_report(const std::vector<RunResult>& results, const std::string& command_line,
                            const std::filesystem::path& dir) {
    std::string md = "# rotbench report\n\n";
    md += fmt::format("rotbench {} (commit {}), {} {}, flags `{}`; generated {:%Y-%m-%d %H:%M} UTC.\n\n",
                      build_info::version, build_info::commit, build_info::compiler, build_info::build_type,
                      build_info::flags, fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())));
    md += fmt::format("Command: `{}`\n\n", command_line);
    const auto unstable = std::count_if(results.begin(), results.end(), [](const RunResult& r) { return r.value("unstable") != 0.0; });
    md += fmt::format("{} runs, {} unstable or failed. Errors are in rad/s (angular velocity) and rad (orientation); "
                      "drifts are relative; ns_per_step is the median per-thread CPU time of a run without the "
                      "metrics, divided by its steps.\n\n",
                      results.size(), unstable);
    for (const auto& scene : unique_in_order(results, &RunSpec::scene)) scene_section(md, scene, results);
    table1_section(md, results);
    md += energy_series_section(results, dir);
    schemes_section(md, results);
    md += "## Metrics\n\n"
          "- `omega_rms_x/y/z`: root mean square over all steps of the body-frame angular-velocity error "
          "(each solution in its own body frame), the seed's Table 1 quantity.\n"
          "- `omega_err_max`: max |w - w_ref| in the world frame. `orientation_err_max`: max rotation angle "
          "between q and q_ref.\n"
          "- `energy_drift_max`: max |E - E0|/|E0|; `energy_drift_rate`: slope (1/s) of the least-squares line "
          "through its running maximum, the secular drift. `momentum_drift_max`: max |L - L0|/|L0| (torque-free scenes). "
          "`quat_norm_err_max`: max ||q| - 1| (no scheme renormalises q).\n"
          "- `unstable`: 1 when the state became NaN/Inf, the energy error passed 1e6 times the initial energy, "
          "or the scheme threw; the run stops there and its error metrics are NaN.\n";
    return md;
}

}  // namespace rotbench
