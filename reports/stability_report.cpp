#include "reports/stability_report.hpp"

#include "harness/io/output_files.hpp"
#include "reports/gnuplot.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string spectral_radius_plots(const std::vector<SpectralCurve>& curves, const OutputDir& dir) {
    std::string md;
    std::vector<std::string> scenes;
    for (const auto& c : curves)
        if (std::find(scenes.begin(), scenes.end(), c.scene) == scenes.end()) scenes.push_back(c.scene);
    for (const auto& id : scenes) {
        std::string data, names;
        double dt_peng = 0;
        for (const auto& c : curves) {
            if (c.scene != id) continue;
            for (const auto& [dt, rho] : c.points) data += fmt::format("{} {}\n", format_number(dt), format_number(rho));
            data += "\n\n";
            names += (names.empty() ? "" : " ") + c.scheme;
            dt_peng = c.dt_peng;
        }
        dir.write(fmt::format("plots/spectral_radius_{}.dat", id), data);
        const std::string script = fmt::format(
            "set terminal svg size 800,450 dynamic noenhanced font 'sans,12'\n{3}"
            "set title '{0} (undamped): spectral radius of the step map'\nset xlabel 'dt (s)'\nset ylabel 'rho - 1'\n"
            "set logscale xy\nset format y '%.0e'\nset grid\nset key outside right\nset yrange [1e-10:*]\n"
            "names = '{1}'\nfile = 'spectral_radius_{0}.dat'\n"
            "set arrow from {2},graph 0 to {2},graph 1 nohead dt 2 lc 'black'\n"
            "set label 'Peng' at {2},graph 0.95 offset 0.5,0\n"
            "plot for [i=1:words(names)] file index (i-1) using 1:($2-1) with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.5 title word(names, i)\n",
            id, names, format_number(dt_peng), gnuplot_output(fmt::format("spectral_radius_{}.svg", id)));
        const Drawn drawn = draw_with_gnuplot(dir, fmt::format("plots/spectral_radius_{}.gp", id), script,
                                              fmt::format("plots/spectral_radius_{}.svg", id));
        md += drawn.ok ? fmt::format("![spectral radius, {0}](plots/spectral_radius_{0}.svg)\n\n", id)
                       : fmt::format("(plot not drawn: {})\n\n", drawn.why);
    }
    return md;
}

std::string stability_section(const std::vector<StabilityRow>& rows, const OutputDir& dir) {
    std::string md = fmt::format(
        "## Stability limits\n\n"
        "For each scene (damping ratio zeta or spin rate w_max) and scheme: the largest stable dt measured (bracketing and "
        "bisection to 0.5 %), the limit from the eigenvalues of the scheme's own linearised step map, and the "
        "prediction of Peng et al. (seed 004, eq. 46; eq. 47 undamped). Criterion, the same for both: unstable "
        "when the energy grows by {:g} within {:g} periods of the fastest contact mode (2 pi / sqrt(k A_max)), "
        "i.e. rho^(2N) >= {:g} over those N steps. \"weak\": rho > 1 at every dt (rho - 1 ~ dt^2): such a scheme "
        "gains energy at any step, and its limit is only where the gain over the horizon reaches the criterion. "
        "Peng's step is conservative where it is at most the measured limit. `fast_spin` (rotation-dominant, eq. 57) "
        "has no eigenvalue limit here: a spin is not a state at rest to linearise about; its horizon counts spin "
        "periods.\n\n"
        "| scene | zeta | w_max (rad/s) | scheme | measured (s) | eigenvalues (s) | Peng (s) | measured / Peng | Peng conservative? | Verlet, normal mode (s) |\n"
        "|---|---:|---:|---|---:|---:|---:|---:|---|---:|\n",
        stability_growth, stability_horizon_periods, stability_growth);
    for (const auto& r : rows) {
        const double ratio = r.dt_empirical / r.dt_peng;
        auto number = [](double v) {
            return std::isnan(v) ? std::string("—") : std::isinf(v) ? std::string("none found") : fmt::format("{:.4e}", v);
        };
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.scene,
                          r.omega_max > 0 ? "—" : fmt::format("{:g}", r.zeta), r.omega_max > 0 ? fmt::format("{:g}", r.omega_max) : "—",
                          r.scheme + (r.unstable_at_every_dt ? " (weak)" : ""), number(r.dt_empirical),
                          number(r.dt_amplification), number(r.dt_peng),
                          std::isinf(ratio) ? std::string("∞") : fmt::format("{:.3f}", ratio), ratio >= 1.0 ? "yes" : "**no**",
                          number(r.dt_verlet_normal));
    }
    // Limit against zeta, per scene: one line per scheme and Peng's prediction.
    std::map<std::string, std::vector<const StabilityRow*>> by_scene;
    for (const auto& r : rows)
        if (r.omega_max == 0) by_scene[r.scene].push_back(&r);
    md += "\n";
    for (const auto& [scene, list] : by_scene) {
        std::string data, names;
        std::vector<std::string> schemes;
        for (const auto* r : list)
            if (std::find(schemes.begin(), schemes.end(), r->scheme) == schemes.end()) schemes.push_back(r->scheme);
        for (const auto& s : schemes) {
            names += (names.empty() ? "" : " ") + s;
            for (const auto* r : list)
                if (r->scheme == s) data += fmt::format("{} {} {} {}\n", r->zeta, format_number(r->dt_empirical),
                                                        format_number(r->dt_amplification), format_number(r->dt_peng));
            data += "\n\n";
        }
        dir.write(fmt::format("plots/stability_{}.dat", scene), data);
        const std::string script = fmt::format(
            "set terminal svg size 800,450 dynamic noenhanced font 'sans,12'\n{2}"
            "set title '{0}: stability limit against damping ratio'\nset xlabel 'zeta'\nset ylabel 'dt (s)'\n"
            "set logscale y\nset grid\nset key outside right\nnames = '{1}'\nfile = 'stability_{0}.dat'\n"
            "plot for [i=1:words(names)] file index (i-1) using 1:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 title word(names, i), "
            "file index 0 using 1:4 with lines dt 2 lc 'black' title 'Peng (eq. 46)'\n",
            scene, names, gnuplot_output(fmt::format("stability_{}.svg", scene)));
        const Drawn drawn = draw_with_gnuplot(dir, fmt::format("plots/stability_{}.gp", scene), script,
                                              fmt::format("plots/stability_{}.svg", scene));
        md += drawn.ok ? fmt::format("![stability, {0}](plots/stability_{0}.svg)\n\n", scene)
                       : fmt::format("(plot not drawn: {})\n\n", drawn.why);
    }
    return md;
}

}  // namespace rotbench
