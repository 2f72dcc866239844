#include "reports/stability_report.hpp"

#include "harness/exec/stability.hpp"
#include "harness/store/output_files.hpp"
#include "reports/gnuplot.hpp"
#include "reports/panels.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

namespace {

std::string limit_cell(double v) {
    return std::isnan(v) ? std::string("—") : std::isinf(v) ? std::string("none found") : fmt::format("{:.4e}", v);
}

std::vector<std::string> schemes_of(const std::vector<StabilityRow>& rows) {
    std::vector<std::string> out;
    for (const auto& r : rows)
        if (std::find(out.begin(), out.end(), r.scheme) == out.end()) out.push_back(r.scheme);
    return out;
}

// The limits against zeta on one contact scene: a line per scheme, Peng's prediction in each panel.
// `stem`: the files' name before the scene's (the report's and stability.md's are apart, each
// command replacing only its own files).
std::string limit_plot(const std::string& stem, const std::string& scene, const std::vector<const StabilityRow*>& list,
                       const ResultSet& set, const OutputDir& dir) {
    const std::string name = stem + scene;
    std::vector<std::string> schemes;
    for (const auto* r : list)
        if (std::find(schemes.begin(), schemes.end(), r->scheme) == schemes.end()) schemes.push_back(r->scheme);
    std::string data;
    for (const auto& s : schemes) {
        for (const auto* r : list)
            if (r->scheme == s) data += fmt::format("{} {} {}\n", r->zeta, format_number(r->dt_empirical), format_number(r->dt_peng));
        data += "\n\n";
    }
    dir.write("plots/" + name + ".dat", data);
    const auto panels = family_panels(set, schemes);
    const std::string setup = fmt::format("set xlabel 'damping ratio zeta (-)'\nset ylabel 'largest stable dt (s)'\nset logscale y\n"
                                          "set format y '%g'\nset grid\nfile = '{}.dat'\n", name);
    const std::string script = panel_grid_script(
        gnuplot_output(name + ".svg"), scene + ": stability limit against damping ratio", setup, panels,
        [&](std::size_t p) {
            std::string line = "plot ";
            for (std::size_t i = 0; i < panels[p].schemes.size(); ++i)
                line += fmt::format("file index {} using 1:2 with linespoints {} title '{}', ",
                                    std::find(schemes.begin(), schemes.end(), panels[p].schemes[i]) - schemes.begin(),
                                    scheme_style(set, panels[p].schemes[i], i), panels[p].schemes[i]);
            return line + "file index 0 using 1:3 with lines dt 2 lc 'black' title 'Peng (eq. 46)'\n";
        });
    const Drawn drawn = draw_with_gnuplot(dir, "plots/" + name + ".gp", script, "plots/" + name + ".svg");
    return drawn.ok ? fmt::format("![stability, {}](plots/{}.svg)\n\n", scene, name) : fmt::format("(plot not drawn: {})\n\n", drawn.why);
}

const char* criterion_text =
    "Criterion, the same for the runs and the eigenvalues: unstable when the energy grows by {:g} within {:g} periods "
    "of the fastest contact mode (2 pi / sqrt(k A_max)), i.e. rho^(2N) >= {:g} over those N steps. *weak*: rho > 1 at "
    "every dt (rho - 1 ~ dt^2): such a scheme gains energy at any step, and its limit is only where the gain over the "
    "horizon reaches the criterion. Peng's step is safe where it is at most the measured limit (measured / Peng >= 1). "
    "`fast_spin` (rotation-dominant, eq. 57) has no eigenvalue limit: a spin is not a state at rest to linearise about; "
    "its horizon counts spin periods, and its limits scale as 1/w_max, so they are given as dt w_max (rad).";

}  // namespace

std::string spectral_radius_plots(const std::vector<SpectralCurve>& curves, const ResultSet& set, const OutputDir& dir) {
    std::string md;
    std::vector<std::string> scenes;
    for (const auto& c : curves)
        if (std::find(scenes.begin(), scenes.end(), c.scene) == scenes.end()) scenes.push_back(c.scene);
    for (const auto& id : scenes) {
        std::string data;
        std::vector<std::string> schemes;
        double dt_peng = 0;
        std::string failed;
        for (const auto& c : curves) {
            if (c.scene != id) continue;
            // No finite point: left out of the plot (gnuplot stops at a panel with nothing to draw), named below it.
            const bool bounded = std::any_of(c.points.begin(), c.points.end(), [](const auto& p) { return std::isfinite(p.second); });
            if (!c.failure.empty() || !bounded) {
                failed += fmt::format("- `{}`: no spectral curve; {}\n", c.scheme,
                                      c.failure.empty() ? "its step map is unbounded (it threw or blew up) at every dt" : c.failure);
                continue;
            }
            for (const auto& [dt, rho] : c.points) data += fmt::format("{} {}\n", format_number(dt), format_number(rho));
            data += "\n\n";
            schemes.push_back(c.scheme);
            dt_peng = c.dt_peng;
        }
        dir.write(fmt::format("plots/spectral_radius_{}.dat", id), data);
        const auto panels = family_panels(set, schemes);
        const std::string setup = fmt::format(
            "set xlabel 'dt (s)'\nset ylabel 'rho - 1 (-)'\nset logscale xy\nset format x '%g'\nset format y '%.0e'\nset grid\n"
            "set yrange [1e-10:*]\nfile = 'spectral_radius_{0}.dat'\n"
            "set arrow 1 from {1},graph 0 to {1},graph 1 nohead dt 2 lc 'black'\nset label 1 'Peng' at {1},graph 0.95 offset 0.5,0\n",
            id, format_number(dt_peng));
        const std::string script = panel_grid_script(
            gnuplot_output(fmt::format("spectral_radius_{}.svg", id)), id + " (undamped): spectral radius of the step map", setup, panels,
            [&](std::size_t p) {
                std::string line = "plot ";
                for (std::size_t i = 0; i < panels[p].schemes.size(); ++i)
                    line += fmt::format("{}file index {} using 1:($2-1) with linespoints {} title '{}'", i ? ", " : "",
                                        std::find(schemes.begin(), schemes.end(), panels[p].schemes[i]) - schemes.begin(),
                                        scheme_style(set, panels[p].schemes[i], i), panels[p].schemes[i]);
                return line + "\n";
            });
        const Drawn drawn = draw_with_gnuplot(dir, fmt::format("plots/spectral_radius_{}.gp", id), script,
                                              fmt::format("plots/spectral_radius_{}.svg", id));
        md += drawn.ok ? fmt::format("![spectral radius, {0}](plots/spectral_radius_{0}.svg)\n\n", id)
                       : fmt::format("(plot not drawn: {})\n\n", drawn.why);
        if (!failed.empty()) md += failed + "\n";
    }
    return md;
}

std::string stability_section(const std::vector<StabilityRow>& rows, const ResultSet& set, const OutputDir& dir) {
    std::string md = "## Stability limits\n\n" +
                     fmt::format(fmt::runtime(std::string("For each scene (damping ratio zeta or spin rate w_max) and scheme: the largest "
                                 "stable dt measured (bracketing and bisection to 0.5 %), the limit from the eigenvalues of the "
                                 "scheme's own linearised step map, and the prediction of Peng et al. (seed 004, eq. 46; eq. 47 "
                                 "undamped); `stability.csv` adds the textbook Verlet limit of the normal mode. ") + criterion_text),
                                 stability_growth, stability_horizon_periods, stability_growth) +
                     "\n\n| scene | zeta or w_max | scheme | kind | measured (s) | eigenvalues (s) | Peng (s) |\n"
                     "|---|---:|---|---|---:|---:|---:|\n";
    for (const auto& r : rows)
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", r.scene,
                          r.omega_max > 0 ? fmt::format("w {:g} rad/s", r.omega_max) : fmt::format("zeta {:g}", r.zeta), r.scheme,
                          stability_kind(r), limit_cell(r.dt_empirical), limit_cell(r.dt_amplification), limit_cell(r.dt_peng));
    md += "\n";
    std::string failures;
    for (const auto& r : rows)
        if (!r.failure.empty()) failures += fmt::format("- `{}` on `{}` failed: {}\n", r.scheme, r.scene, r.failure);
    if (!failures.empty()) md += failures + "\n";
    std::map<std::string, std::vector<const StabilityRow*>> by_scene;
    for (const auto& r : rows)
        if (r.omega_max == 0 && r.failure.empty()) by_scene[r.scene].push_back(&r);
    for (const auto& [scene, list] : by_scene) md += limit_plot("stability_", scene, list, set, dir);
    return md;
}

namespace {

// A spinning scene's table: per scheme, the least dt w_max over the spin rates against Peng's.
std::string spin_table(const std::vector<StabilityRow>& rows, const std::vector<const StabilityRow*>& list) {
    std::string md = "| scheme | kind | measured dt w_max (rad) | Peng dt w_max (rad) | measured / Peng |\n|---|---|---:|---:|---:|\n";
    for (const auto& scheme : schemes_of(rows)) {
        const StabilityRow* least = nullptr;  // the smallest dt w_max over the spin rates
        bool failed = false;
        for (const auto* r : list) {
            failed = failed || (r->scheme == scheme && !r->failure.empty());
            if (r->scheme == scheme && r->failure.empty() && (!least || r->dt_empirical * r->omega_max < least->dt_empirical * least->omega_max)) least = r;
        }
        if (!least) {
            if (failed) md += fmt::format("| {} | failed | — | — | — |\n", scheme);
            continue;
        }
        const double m = least->dt_empirical * least->omega_max, p = least->dt_peng * least->omega_max;
        md += fmt::format("| {} | {} | {} | {:.4g} | {} |\n", scheme, stability_kind(*least),
                          std::isinf(m) ? std::string("none found") : fmt::format("{:.4g}", m), p,
                          std::isinf(m) ? std::string("∞") : fmt::format("{:.3f}", m / p));
    }
    return md;
}

// A contact scene's table: per scheme and damping ratio (at most five), the measured limit over Peng's.
std::string damping_table(const std::vector<StabilityRow>& rows, const std::vector<const StabilityRow*>& list) {
    std::vector<double> keys;
    for (const auto* r : list)
        if (std::find(keys.begin(), keys.end(), r->zeta) == keys.end()) keys.push_back(r->zeta);
    if (keys.size() > 5) keys.resize(5);  // at most 7 columns; every value is in stability.csv
    std::string md = "| scheme |";
    for (double z : keys) md += fmt::format(" zeta = {:g} |", z);
    md += "\n|---|";
    for (std::size_t i = 0; i < keys.size(); ++i) md += "---:|";
    md += "\n| *Peng's dt (s)* |";
    for (double z : keys) {
        const auto it = std::find_if(list.begin(), list.end(), [&](const StabilityRow* r) { return r->zeta == z; });
        md += fmt::format(" *{:.3g}* |", (*it)->dt_peng);
    }
    md += "\n";
    for (const auto& scheme : schemes_of(rows)) {
        std::string line = "| " + scheme + " |";
        bool any = false;
        for (double z : keys) {
            const auto it = std::find_if(list.begin(), list.end(), [&](const StabilityRow* r) { return r->scheme == scheme && r->zeta == z; });
            if (it == list.end()) { line += " — |"; continue; }
            any = true;
            if (!(*it)->failure.empty()) { line += " failed |"; continue; }
            const double ratio = (*it)->dt_empirical / (*it)->dt_peng;
            const std::string kind = stability_kind(**it) == "sharp" ? "" : " (" + stability_kind(**it) + ")";
            line += std::isinf(ratio) ? " ∞" + kind + " |"
                    : ratio >= 1.0   ? fmt::format(" {:.3f}{} |", ratio, kind)
                                     : fmt::format(" **{:.3f}**{} |", ratio, kind);
        }
        if (any) md += line + "\n";
    }
    return md + "\nMeasured / Peng; **bold** where Peng's dt is above the measured limit (unsafe); (weak): see above.\n\n";
}

}  // namespace

std::string stability_summary(const std::vector<StabilityRow>& rows, const ResultSet& set, const OutputDir& dir) {
    if (rows.empty())
        return "## Stability limits\n\nNo stability study here: `rotbench stability --out DIR` writes `stability.csv` beside "
               "the runs, and `rotbench report DIR` then includes it.\n\n";
    std::string md = "## Stability limits\n\n" +
                     fmt::format(fmt::runtime(std::string("Measured limit over Peng et al.'s prediction (seed 004, eq. 46; eq. 47 "
                                 "undamped) for each contact scene and damping ratio, from `stability.csv` (the limits themselves, "
                                 "the eigenvalue limits and the spectral radii are in `stability.md` where `rotbench stability` "
                                 "wrote it). ") + criterion_text),
                                 stability_growth, stability_horizon_periods, stability_growth) + "\n\n";
    std::map<std::string, std::vector<const StabilityRow*>> by_scene;
    std::vector<std::string> scene_order;
    for (const auto& r : rows) {
        if (!by_scene.count(r.scene)) scene_order.push_back(r.scene);
        by_scene[r.scene].push_back(&r);
    }
    for (const auto& scene : scene_order) {
        const auto& list = by_scene[scene];
        md += fmt::format("### `{}`\n\n", scene);
        if (list.front()->omega_max > 0) {
            md += spin_table(rows, list);
        } else {
            md += damping_table(rows, list);
            std::vector<const StabilityRow*> finished;
            for (const auto* r : list)
                if (r->failure.empty()) finished.push_back(r);
            md += limit_plot("report_stability_", scene, finished, set, dir);
        }
        md += "\n";
    }
    return md;
}

}  // namespace rotbench
