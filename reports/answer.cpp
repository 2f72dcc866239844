#include "reports/answer.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

std::vector<std::string> ranking_scenes(const std::vector<LargestDt>& answers) {
    std::vector<std::string> found;
    for (const auto& a : answers)
        if (std::find(found.begin(), found.end(), a.scene) == found.end()) found.push_back(a.scene);
    std::vector<std::string> chosen;
    for (const char* preferred : {"asymmetric_free", "dipole_top"})  // a free top, and a torque T(q)
        if (std::find(found.begin(), found.end(), preferred) != found.end()) chosen.push_back(preferred);
    for (const auto& s : found)
        if (chosen.size() < 2 && std::find(chosen.begin(), chosen.end(), s) == chosen.end()) chosen.push_back(s);
    return chosen;
}

std::string dt_cell(const LargestDt& a) {
    if (a.how == "never") return "never";
    if (a.how == "exact") return fmt::format("exact (≥ {:.3g})", a.dt);
    if (a.how == "at most") return fmt::format("≥ {:.3g}", a.dt);
    if (a.how == "extrapolated") return fmt::format("{:.3g} (extrap.)", a.dt);
    return fmt::format("{:.3g}", a.dt);
}
std::string cpu_cell(const LargestDt& a) {
    if (std::isfinite(a.cpu_seconds)) return fmt::format("{:.2e}", a.cpu_seconds);
    return a.how == "never" ? "—" : "not timed";
}
bool below(const LargestDt& a) { return a.how != "never" && a.dt < a.dt_limit; }
std::string limit_cell(const LargestDt& a) {
    if (a.how == "never") return "—";
    if (std::isnan(a.dt_limit)) return "unknown";
    if (std::isinf(a.dt_limit)) return "yes (no limit found)";
    return below(a) ? fmt::format("yes ({:.3g})", a.dt_limit) : fmt::format("**no** ({:.3g})", a.dt_limit);
}

}  // namespace

std::string answer_section(const ResultSet& set, const std::vector<LargestDt>& answers, const std::vector<double>& tolerances) {
    if (answers.empty()) return "";
    const auto scenes = ranking_scenes(answers);
    std::string md = fmt::format(
        "## The answer: the largest dt for a tolerance\n\n"
        "For a tolerance on the relative angular-velocity error (`{1}` / `{2}`, the largest error "
        "over the run against the largest |w|), the largest dt at which each scheme meets it, and the CPU time a whole run "
        "at that dt takes (the scheme's `ns_per_step` on that scene times the steps). The dt is interpolated (log-log) "
        "between the two measured steps around the tolerance; \"≥\": the coarsest step measured already meets it; "
        "\"extrap.\": no measured step does, and the finest one is extended with the observed order; \"exact\": round-off "
        "only at every step, so only stability limits dt; \"never\": no step meets it and the error does not converge. "
        "*Stable*: whether that dt lies below the measured stability limit (section [Stability](#stability-limits); "
        "\"unknown\" without a stability study). Ranked by the geometric mean of the CPU times on {0}, schemes \"not timed\" "
        "(clients: their program's cost is their own) after those timed; all scenes and `answer.csv` follow.\n\n",
        fmt::format("`{}`", fmt::join(scenes, "` and `")), metric::omega_err_max, metric::omega_ref_max);
    for (const double tol : tolerances) {
        struct Row {
            std::string scheme;
            std::vector<const LargestDt*> cells;
            double score = 0;
        };
        std::vector<Row> rows;
        for (const auto& a : answers) {
            if (a.tolerance != tol || std::find(scenes.begin(), scenes.end(), a.scene) == scenes.end()) continue;
            auto it = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.scheme == a.scheme; });
            if (it == rows.end()) it = rows.insert(rows.end(), Row{a.scheme, std::vector<const LargestDt*>(scenes.size()), 0});
            it->cells[std::find(scenes.begin(), scenes.end(), a.scene) - scenes.begin()] = &a;
        }
        for (auto& row : rows) {
            double log_sum = 0;
            for (const LargestDt* c : row.cells) log_sum += c && std::isfinite(c->cpu_seconds) ? std::log(c->cpu_seconds) : INFINITY;
            row.score = std::exp(log_sum / static_cast<double>(scenes.size()));
        }
        std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.score < b.score; });
        md += fmt::format("### Relative error {:g}\n\n| rank | scheme |", tol);
        for (const auto& s : scenes) md += fmt::format(" {}: dt (s) | CPU (s) |", s);
        md += " stable |\n|---:|---|";
        for (std::size_t i = 0; i < scenes.size(); ++i) md += "---:|---:|";
        md += "---|\n";
        int rank = 0;
        for (const auto& row : rows) {
            const SchemeInfo* info = set.scheme(row.scheme);
            md += fmt::format("| {} | `{}`{} |", ++rank, row.scheme, info && !info->claims.sound ? " (control)" : "");
            std::string stable = "—";  // stays so when no scene has a dt to judge
            for (std::size_t i = 0; i < scenes.size(); ++i) {
                const LargestDt* c = row.cells[i];
                md += c ? fmt::format(" {} | {} |", dt_cell(*c), cpu_cell(*c)) : " — | — |";
                if (!c || c->how == "never") continue;
                if (stable == "—") stable = "yes";
                if (std::isnan(c->dt_limit)) { if (stable == "yes") stable = "unknown"; }
                else if (!below(*c)) stable = fmt::format("**no** on {}", scenes[i]);
            }
            md += " " + stable + " |\n";
        }
        md += "\n";
    }
    return md + "Every scene's answer: section " + answer_details_heading + ", after the scenes.\n\n";
}

std::string answer_details_section(const std::vector<LargestDt>& answers, const std::vector<double>& tolerances) {
    std::string md = "## " + answer_details_heading + "\n\n<details><summary>Every scene</summary>\n\n";
    for (const double tol : tolerances) {
        std::vector<std::string> all;
        for (const auto& a : answers)
            if (a.tolerance == tol && std::find(all.begin(), all.end(), a.scene) == all.end()) all.push_back(a.scene);
        for (const auto& scene : all) {
            md += fmt::format("#### `{}`, relative error {:g}\n\n| scheme | dt (s) | CPU (s) | stable (limit, s) | limit from |\n"
                              "|---|---:|---:|---|---|\n", scene, tol);
            for (const auto& a : answers)
                if (a.tolerance == tol && a.scene == scene)
                    md += fmt::format("| {} | {} | {} | {} | {} |\n", a.scheme, dt_cell(a), cpu_cell(a), limit_cell(a),
                                      a.limit_from.empty() ? "—" : a.limit_from);
            md += "\n";
        }
    }
    return md + "</details>\n\n";
}

}  // namespace rotbench
