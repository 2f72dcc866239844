#include "reports/markdown_report.hpp"

#include "schemes/plugin_abi.hpp"

#include "reports/clients_report.hpp"

#include "reports/cost_table.hpp"
#include "reports/granular_speed.hpp"
#include "reports/granular_report.hpp"
#include "reports/provenance.hpp"

#include "references/odeint_reference.hpp"
#include "reports/convergence_plots.hpp"
#include "reports/energy_series.hpp"
#include "harness/analysis/claims.hpp"
#include "harness/analysis/expected_orders.hpp"
#include "harness/analysis/orders.hpp"
#include "reports/answer.hpp"
#include "reports/panels.hpp"
#include "reports/stability_report.hpp"
#include "reports/verdicts.hpp"
#include "harness/analysis/seed_table1.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <set>

namespace rotbench {
namespace {

// Columns of the per-scene tables, in the metric table's order, when any run of the scene has them.
std::vector<std::string> table_metrics() {
    std::vector<std::string> out;
    for (const auto& m : metric_table())
        if (m.in_scene_table) out.emplace_back(m.name);
    return out;
}

std::vector<std::string> unique_in_order(const std::vector<RunResult>& results, std::string RunSpec::*field) {
    std::vector<std::string> out;
    for (const auto& r : results)
        if (std::find(out.begin(), out.end(), r.spec.*field) == out.end()) out.push_back(r.spec.*field);
    return out;
}

// The metrics of `candidates` that any of `runs` has, in the order given.
std::vector<std::string> present(const std::vector<std::string>& candidates, const std::vector<const RunResult*>& runs) {
    std::vector<std::string> out;
    for (const auto& m : candidates)
        if (std::any_of(runs.begin(), runs.end(), [&](const RunResult* r) { return r->has(m); })) out.push_back(m);
    return out;
}

// A Markdown table head: a text column, one more right-aligned column per `numeric`.
std::string table_head(const std::string& first, const std::vector<std::string>& numeric) {
    std::string head = "| " + first + " |", rule = "|---|";
    for (const auto& c : numeric) {
        head += " " + c + " |";
        rule += "---:|";
    }
    return head + "\n" + rule + "\n";
}

const OrderRow* find_order(const std::vector<OrderRow>& orders, const std::string& scene, const std::string& scheme,
                           const std::string& metric) {
    for (const auto& o : orders)
        if (o.scene == scene && o.scheme == scheme && o.metric == metric) return &o;
    return nullptr;
}

std::string order_cell(const OrderRow* o) {
    if (!o) return "—";
    if (o->status != OrderStatus::fit) return status_name(o->status);
    return fmt::format("{:.2f} [{:.2f}, {:.2f}]", o->fit.order, o->fit.order_lo, o->fit.order_hi);
}

void scene_section(std::string& md, const SceneInfo& entry, const ResultSet& set, const std::vector<OrderRow>& orders,
                   const OutputDir& dir, const std::vector<std::string>& best, const std::vector<ExpectedOrder>& claimed) {
    const std::vector<RunResult>& results = set.runs;
    const std::string& scene_id = entry.id;
    std::vector<const RunResult*> runs;
    for (const auto& r : results)
        if (r.spec.scene == scene_id) runs.push_back(&r);
    md += fmt::format("## Scene `{}`\n\n{}. Source: {}. Duration {} s.\n\n", scene_id, entry.summary, entry.source,
                      runs.front()->spec.t_end);
    switch (entry.reference) {
        case Scene::ReferenceKind::closed_form: md += "Reference: closed form.\n\n"; break;
        case Scene::ReferenceKind::odeint:
            md += fmt::format("Reference: Boost.Odeint (Fehlberg 7(8), tolerance {:g}), sampled at every step.\n\n",
                              reference_tolerance);
            break;
        case Scene::ReferenceKind::none:
            md += entry.conserves_energy ? "No step-by-step reference; the true motion conserves its energy.\n\n"
                                         : "No reference: the motion is dissipative and chaotic (see the section on granular scenes).\n\n";
            break;
    }
    if (!runs.front()->spec.params.empty()) {
        md += "Parameters set:";
        for (const auto& [key, values] : runs.front()->spec.params) md += fmt::format(" `{}` = {};", key, fmt::join(values, ", "));
        md += "\n\n";
    }
    if (!entry.notes.empty()) md += entry.notes + "\n\n";
    md += convergence_plots(scene_id, runs, set, dir, best);

    // Observed orders of each fitted metric, with the expected one on the scenes that judge a
    // claim (claims.hpp); a torque fixed in the body (torqued_cylinder) is left without one.
    const bool torque = judges_claims(entry, true);
    const bool expectation = torque || judges_claims(entry, false);
    const auto metrics = present(fitted_metrics(), runs);
    std::vector<std::string> order_columns = {"expected"};
    for (const auto& m : metrics) order_columns.push_back("order of " + m);
    md += table_head("scheme", order_columns);
    for (const auto& scheme : unique_in_order(results, &RunSpec::scheme)) {
        if (std::none_of(runs.begin(), runs.end(), [&](const RunResult* r) { return r->spec.scheme == scheme; })) continue;
        std::string expected = "—";
        if (expectation)
            for (const auto& e : claimed)
                if (e.scheme == scheme && e.with_torque == torque) expected = std::to_string(e.order);
        md += fmt::format("| {} | {} |", scheme, expected);
        for (const auto& m : metrics) md += " " + order_cell(find_order(orders, scene_id, scheme, m)) + " |";
        md += "\n";
    }
    md += "\n";

    // Every run, in tables of at most 7 columns: scheme, dt and 5 metrics each.
    const auto columns = present(table_metrics(), runs);
    md += "<details><summary>Every run</summary>\n\n";
    for (std::size_t from = 0; from < columns.size(); from += 5) {
        const std::vector<std::string> part(columns.begin() + from, columns.begin() + std::min(columns.size(), from + 5));
        std::vector<std::string> run_columns = {"dt (s)"};
        run_columns.insert(run_columns.end(), part.begin(), part.end());
        md += table_head("scheme", run_columns);
        for (const RunResult* r : runs) {
            md += fmt::format("| {} | {:g} |", r->spec.scheme, r->spec.dt);
            for (const auto& c : part) md += " " + metric_cell(c, r->value(c)) + " |";
            md += "\n";
        }
        md += "\n";
    }
    md += "</details>\n\n";
    for (const RunResult* r : runs)
        if (!r->failure.empty())
            md += fmt::format("- **{} at dt = {:g} failed**: {}.\n", r->spec.scheme, r->spec.dt, r->failure);
    md += "\n";
}

void table1_section(std::string& md, const std::vector<Table1Comparison>& rows) {
    if (rows.empty()) return;
    md += "## Seed Table 1 reproduced\n\n"
          "Published (seed 000, Table 1, \"mean squared error\") and computed error of the body-frame angular "
          "velocity on `cylinder_free`. The published quantity is read as the root mean square over the "
          "steps t = dt, 2 dt, ..., 0.5 s (the initial, exact state excluded) of the difference from the exact "
          "solution: a mean of squares would fall as dt^4, not dt^2 as the table does. Including t = 0 would "
          "shift the dt = 1e-2 row by 1 % and leave the others unchanged. The seed's eq. 65b prints "
          "w'y = sin 50t; Euler's equations give cos 50t for this start. The seed's \"Quaternion int.\" is "
          "`zvw_corrected`; `zvw` gives the same numbers without torque, as the seed says.\n\n";
    const bool shipped_ran = std::any_of(rows.begin(), rows.end(), [](const auto& r) { return r.shipped.has_value(); });
    if (shipped_ran)
        md += "*Kratos as shipped*: the same entry from the seed's own code, Kratos DEM's binary, through the clients of "
              "`examples/clients/kratos` (the seed's schemes under Velocity_Verlet; docs/clients.md), where they ran.\n\n"
              "| dt (s) | scheme | | published | computed | difference | within 1 % | Kratos as shipped | difference | within 1 % |\n"
              "|---:|---|---|---:|---:|---:|---|---:|---:|---|\n";
    else
        md += "| dt (s) | scheme | | published | computed | difference | within 1 % |\n"
              "|---:|---|---|---:|---:|---:|---|\n";
    int agree_main = 0, total_main = 0, shipped_agree = 0, shipped_total = 0;
    std::vector<const Table1Comparison*> noted;
    for (const auto& row : rows) {
        const bool main_range = row.entry.dt >= 1e-5;
        total_main += main_range;
        agree_main += main_range && row.agrees;
        shipped_total += main_range && row.shipped;
        shipped_agree += main_range && row.shipped_agrees;
        md += fmt::format("| {:g} | {} ({}) | w'{} | {:.2e} | {:.4e} | {:+.2f} % | {} |", row.entry.dt,
                          row.entry.published_name, row.entry.scheme, row.entry.component, row.entry.published,
                          row.computed, 100.0 * row.relative_difference, row.agrees ? "yes" : "**no**");
        if (shipped_ran && row.shipped)
            md += fmt::format(" {:.4e} | {:+.2f} % | {} |", *row.shipped, 100.0 * (*row.shipped / row.entry.published - 1.0),
                              row.shipped_agrees ? "yes" : "**no**");
        else if (shipped_ran)
            md += " — | | |";
        md += "\n";
        if (!row.agrees && !row.entry.note.empty()) noted.push_back(&row);
    }
    md += fmt::format("\n{} of {} entries with dt from 1e-2 to 1e-5 agree within 1 %.", agree_main, total_main);
    if (shipped_total > 0)
        md += fmt::format(" Kratos as shipped: {} of {} entries with dt from 1e-2 to 1e-5 agree within 1 % (docs/findings.md says "
                          "where and why not).",
                          shipped_agree, shipped_total);
    md += "\n\n";
    std::set<std::string> explained;
    for (const auto* row : noted) {
        const std::string key = row->entry.scheme + fmt::format("{:g}", row->entry.dt);
        if (!explained.insert(key).second) continue;
        md += fmt::format("- **{} at dt = {:g}**: {}\n", row->entry.published_name, row->entry.dt, row->entry.note);
    }
    md += "\n";
}

void schemes_section(std::string& md, const ResultSet& set, const std::vector<ExpectedOrder>& expected) {
    md += "## Schemes: sources, readings, and what each claims\n\n";
    for (const auto& id : unique_in_order(set.runs, &RunSpec::scheme)) {
        const SchemeInfo* s = set.scheme(id);
        if (!s) {
            md += fmt::format("- **`{}`**: not described (a folder written before rotbench kept schemes.json; pass --plugin).\n", id);
            continue;
        }
        md += fmt::format("- **`{}`**: {}. Source: {}.", id, s->summary, s->source);
        if (!s->plugin_path.empty())
            md += fmt::format(" Plug-in `{}` (FNV-1a {}), built {}.", s->plugin_path, s->plugin_hash, s->plugin_build);
        if (!s->notes.empty()) md += " Reading: " + s->notes;
        for (const auto& e : expected)
            if (e.scheme == id)
                md += fmt::format(" Expected order {} {}: {}.", e.order, e.with_torque ? "with torque" : "without torque", e.reason);
        if (s->claims.exact_without_torque) md += " Exact without torque (round-off only).";
        if (s->claims.conserves_momentum) md += " Keeps the world angular momentum to round-off without torque.";
        if (s->claims.bounded_energy) md += " No secular energy drift (symplectic or time-reversible).";
        md += "\n";
    }
    md += "\n";
}

// A heading's anchor as GitHub makes it: lower case, punctuation dropped, spaces to hyphens.
std::string anchor(const std::string& heading) {
    std::string out;
    for (const char c : heading) {
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (c == ' ') out += '-';
    }
    return out;
}

std::string link(const std::string& text, const std::string& heading) { return "[" + text + "](#" + anchor(heading) + ")"; }


// The opening paragraph: what ran, how much of it failed, and the provenance; a warning for a
// plug-in built otherwise than the built-in schemes.
std::string header(const Analysis& a, const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                   const std::string& command_line) {
    const ResultSet& set = a.set;
    const Provenance p = provenance();
    const auto failed = std::count_if(set.runs.begin(), set.runs.end(), [](const RunResult& r) { return r.value(metric::unstable) != 0.0; });
    std::string md = "# rotbench report\n\n";
    // The count the progress lines gave: the horizon runs of the energy verdicts are runs too.
    const std::string horizon_runs = set.horizons.empty() ? "" : fmt::format(" (besides {} horizon runs for the energy verdicts)", set.horizons.size());
    md += fmt::format(
        "{} runs of {} scheme{} on {} scene{}, {} of them unstable or failed{}: which scheme meets which error at what dt, "
        "and at what cost. Errors are in rad/s (angular velocity) and rad (orientation), drifts relative; the cost figure "
        "is `ns_per_step` (section {}). rotbench {} (commit {}), {} {}, flags `{}`, on {}; generated {} {} UTC by `{}`.\n\n",
        set.runs.size(), schemes.size(), schemes.size() == 1 ? "" : "s", scenes.size(), scenes.size() == 1 ? "" : "s", failed, horizon_runs,
        link("Verdicts", "Verdicts"), p.version, p.commit, p.compiler, p.build_type, p.flags, p.cpu, p.date.substr(0, 10), p.date.substr(11, 5),
        command_line);
    for (const auto& [id, info] : set.schemes)  // the header's flags are rotbench's own: say where a plug-in's differ
        if (!info.plugin_path.empty() && info.plugin_build != ROTBENCH_PLUGIN_BUILD)
            md += fmt::format("**Warning: `{}` comes from a plug-in built {}** (`{}`; the built-in schemes: {}): its cost does not "
                              "compare with theirs. Rebuild it with `rotbench_add_scheme()` and its default flags.\n\n",
                              id, info.plugin_build, info.plugin_path, ROTBENCH_PLUGIN_BUILD);
    return md;
}

std::string contents(const std::vector<std::string>& scenes) {
    const std::string answer_heading = "The answer: the largest dt for a tolerance";
    std::string md = "## Contents\n\n- " + link("Verdicts", "Verdicts") + " · " + link("The answer", answer_heading) + " · " +
                     link("Stability limits", "Stability limits") + " · " + link("Cost", cost_heading) + "\n- Scenes:";
    for (std::size_t i = 0; i < scenes.size(); ++i)
        md += (i ? "," : "") + std::string(" ") + link("`" + scenes[i] + "`", "Scene `" + scenes[i] + "`");
    md += "\n- " + link(answer_details_heading, answer_details_heading) + " · " + link("Seed Table 1", "Seed Table 1 reproduced") + " · " +
          link("Energy against time", "Energy against time") + " · " + link("Schemes", "Schemes: sources, readings, and what each claims") +
          " · " + link("Metrics and the order fit", "Metrics and the order fit") + "\n\n";
    return md;
}

}  // namespace

std::string markdown_report(const Analysis& a, const std::string& command_line, const OutputDir& dir, const ParallelWork& parallel) {
    const ResultSet& set = a.set;
    const std::vector<RunResult>& results = set.runs;
    const auto scenes = unique_in_order(results, &RunSpec::scene);
    const auto schemes = unique_in_order(results, &RunSpec::scheme);
    std::string md = header(a, scenes, schemes, command_line);
    md += recommendation_section(a.recommendation, a.verdicts);
    md += contents(scenes);
    md += verdict_section(set, a.verdicts, !a.stability.empty());
    md += clients_section(a.counterparts);
    md += answer_section(set, a.answers, a.tolerances);
    md += stability_summary(a.stability, set, dir);
    md += cost_section(a.cost, dir.path());
    md += granular_speed_section(a.granular_speed);

    // The overview panel of each scene's plots: per family, the scheme that reaches the
    // strictest tolerance at the least CPU time there (or, without a reference, the smallest
    // plotted error at the finest step).
    const double strictest = *std::min_element(a.tolerances.begin(), a.tolerances.end());
    const auto best_on = [&](const std::string& scene) {
        return best_of_families(set, schemes, [&](const std::string& scheme) {
            for (const auto& answer : a.answers)
                if (answer.scene == scene && answer.scheme == scheme && answer.tolerance == strictest)
                    return std::isfinite(answer.cpu_seconds) ? answer.cpu_seconds : INFINITY;
            double dt = INFINITY, e = INFINITY;
            for (const auto& r : results)
                if (r.spec.scene == scene && r.spec.scheme == scheme && r.spec.dt < dt) dt = r.spec.dt, e = r.value(metric::energy_drift_max);
            return std::isfinite(e) ? e : INFINITY;
        });
    };
    // The scenes' sections on every core: most of their time is gnuplot drawing the plots,
    // one process at a time otherwise. Each section is its own string; they join in order.
    std::vector<std::string> sections(scenes.size());
    parallel(scenes.size(), [&](std::size_t i) {
        scene_section(sections[i], set.scene(scenes[i]), set, a.orders, dir, best_on(scenes[i]), a.expected);
    });
    for (const auto& section : sections) md += section;
    md += answer_details_section(a.answers, a.tolerances);
    table1_section(md, a.table1);
    md += granular_section(set, dir);
    md += energy_series_section(set, dir, parallel);
    schemes_section(md, set, a.expected);
    md += "## Metrics and the order fit\n\n";
    for (const auto& m : metric_table())
        if (!m.meaning.empty()) md += fmt::format("- `{}`{}: {}.\n", m.name, m.unit.empty() ? "" : fmt::format(" ({})", m.unit), m.meaning);
    md += fmt::format(
        "- Timing: `cpu_seconds` (median), `cpu_seconds_min`, `cpu_seconds_max` over `timing_repeats` timing runs made right after "
        "the metrics run (their warm-up), on the per-thread CPU clock. A run of more than {} steps is timed on 32 evenly spaced "
        "stretches of its own trajectory (`timed_steps` steps in all, each started from a state the metrics run kept) and scaled "
        "to its length. An energy that leaves {:g} times the initial energy scale counts as a blow-up.\n"
        "- Observed order (`orders.csv`; local orders between successive steps in `local_orders.csv`): least-squares slope of log "
        "error against log dt with a 95 % Student-t interval, over the asymptotic range only. Failed runs and errors below {:g} "
        "are dropped, and so are the steps coarser than the one of largest error (a saturated error); from that step, the first "
        "error not below {:g} times the previous one starts a round-off plateau, dropped with every finer step; the range is then "
        "the longest run ending at the finest step whose local orders lie within {:g} of their median. Fewer than {} points: "
        "\"insufficient\"; round-off only: \"exact\"; an error that does not halve over a 4x range of dt: \"no_convergence\" "
        "(`orders.csv`'s `status`).\n",
        timing_sample_steps, blowup_energy_factor, order_floor, plateau_ratio, asymptotic_spread, min_fit_points);
    return md;
}

}  // namespace rotbench
