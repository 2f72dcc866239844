#include "reports/granular_pictures.hpp"

#include "harness/store/series_csv.hpp"
#include "reports/escape.hpp"
#include "reports/gnuplot.hpp"
#include "reports/panels.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {
namespace {

struct Axes {
    std::string x, y, what;
};
Axes axes_of(const std::string& scene) {
    if (scene == "silo_discharge") return {"time since the opening (s)", "mass left in the silo (kg)", "Mass left against time"};
    return {"displacement of the lower half (m)", "shear stress (Pa)", "Shear stress against displacement"};
}

std::string curve_script(const std::string& scene, double dt, const std::vector<const RunResult*>& runs, const std::string& svg,
                         const ResultSet& set) {
    const Axes axes = axes_of(scene);
    std::string s = fmt::format(
        "set terminal svg size 900,560 dynamic noenhanced font 'sans,11'\n{}\n"
        "set datafile separator ','\nset title '{}, {}, dt = {:g} s'\nset xlabel '{}'\nset ylabel '{}'\nset grid\nset key outside right\n"
        "set style fill transparent solid 0.18 noborder\nplot ",
        gnuplot_output(svg), axes.what, scene, dt, axes.x, axes.y);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const RunResult& r = *runs[i];
        const std::string file = "../series/" + series_file_name(r);
        const bool band = r.series_columns.size() == 4;  // x, mean, min, max: an ensemble's
        if (band) s += fmt::format("'{}' using 1:3:4 with filledcurves {} notitle, \\\n     ", file, scheme_colour(set, r.spec.scheme));
        s += fmt::format("'{}' using 1:2 with lines lw 1.8 {} title '{}{}'{}", file, scheme_colour(set, r.spec.scheme), r.spec.scheme,
                         band ? fmt::format(" (mean of {:.0f})", r.value(metric::ensemble_size)) : "", i + 1 < runs.size() ? ", \\\n     " : "\n");
    }
    return s;
}

}  // namespace

std::string snapshot_svg(const std::string& title, const std::vector<std::vector<double>>& rows,
                         const std::vector<std::vector<double>>& walls) {
    std::map<double, std::vector<const std::vector<double>*>> instants, segments;
    double x_lo = INFINITY, x_hi = -INFINITY, z_lo = INFINITY, z_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    for (const auto& r : rows) {
        instants[r[0]].push_back(&r);
        x_lo = std::min(x_lo, r[1] - r[4]), x_hi = std::max(x_hi, r[1] + r[4]);
        y_lo = std::min(y_lo, r[2]), y_hi = std::max(y_hi, r[2]);
        z_lo = std::min(z_lo, r[3] - r[4]), z_hi = std::max(z_hi, r[3] + r[4]);
    }
    for (const auto& w : walls) {
        if (!instants.count(w[0])) continue;  // walls only where there are stones to draw them with
        segments[w[0]].push_back(&w);
        x_lo = std::min({x_lo, w[1], w[3]}), x_hi = std::max({x_hi, w[1], w[3]});
        z_lo = std::min({z_lo, w[2], w[4]}), z_hi = std::max({z_hi, w[2], w[4]});
    }
    // One scale for every panel, so that the instants compare; 360 px for the tallest extent.
    const double pad = 12, head = 46, scale = 360.0 / std::max(z_hi - z_lo, 1e-9);
    const double panel_w = (x_hi - x_lo) * scale + 2 * pad, panel_h = (z_hi - z_lo) * scale + 2 * pad;
    // Wide enough for the title too (about 7 px a character at 13 px).
    const double width = std::max(panel_w * static_cast<double>(std::max<std::size_t>(instants.size(), 1)), 7.0 * static_cast<double>(title.size()) + 2 * pad);
    const double height = panel_h + head;
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
        "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        "<text x=\"{:.0f}\" y=\"18\">{}</text>\n",
        width, height, width, height, pad, xml_text(title));
    std::size_t p = 0;
    for (const auto& [t, spheres] : instants) {
        const double left = static_cast<double>(p++) * panel_w;
        svg += fmt::format("<text x=\"{:.1f}\" y=\"38\">t = {:.3g} s</text>\n<g stroke=\"#333\" stroke-width=\"0.3\">\n", left + pad, t);
        std::vector<const std::vector<double>*> order = spheres;  // the farthest (largest y) first
        std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return (*a)[2] > (*b)[2]; });
        for (const auto* s : order) {
            const double depth = y_hi > y_lo ? ((*s)[2] - y_lo) / (y_hi - y_lo) : 0.0;  // 0 near, 1 far
            const int shade = static_cast<int>(std::lround(95 + 120 * depth));
            svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"rgb({},{},{})\"/>\n",
                               left + pad + ((*s)[1] - x_lo) * scale, head + pad + (z_hi - (*s)[3]) * scale, (*s)[4] * scale,
                               shade, static_cast<int>(shade * 0.85), static_cast<int>(shade * 0.7));
        }
        svg += "</g>\n";
        if (const auto found = segments.find(t); found != segments.end()) {
            svg += "<g stroke=\"#1f4e9c\" stroke-width=\"2\" stroke-linecap=\"square\">\n";
            const auto at = [&](double x, double z) { return std::pair(left + pad + (x - x_lo) * scale, head + pad + (z_hi - z) * scale); };
            for (const auto* w : found->second) {
                const auto [x1, y1] = at((*w)[1], (*w)[2]);
                const auto [x2, y2] = at((*w)[3], (*w)[4]);
                svg += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\"/>\n", x1, y1, x2, y2);
            }
            svg += "</g>\n";
        }
    }
    return svg + "</svg>\n";
}

std::string granular_pictures(const std::string& scene, double dt, const std::vector<const RunResult*>& runs, const ResultSet& set,
                              const OutputDir& dir) {
    std::vector<const RunResult*> curves;
    for (const RunResult* r : runs)
        if (!r->series.empty() && !r->has_energy_series()) curves.push_back(r);
    std::string md;
    if (!curves.empty()) {
        const std::string name = fmt::format("curve_{}_dt{}", scene, dt_tag(dt));
        const Drawn drawn = draw_with_gnuplot(dir, "plots/" + name + ".gp", curve_script(scene, dt, curves, name + ".svg", set), "plots/" + name + ".svg");
        md += fmt::format("{} of each scheme{}. Data: `series/`.\n\n", axes_of(scene).what,
                          curves.front()->series_columns.size() == 4 ? ": the line is the ensemble's mean, the band spans its members" : "");
        md += drawn.ok ? fmt::format("![{}](plots/{}.svg)\n\n", name, name) : fmt::format("(plot not drawn: {}; script `plots/{}.gp`)\n\n", drawn.why, name);
    }
    std::string pictures;
    for (const RunResult* r : runs) {
        if (r->snapshots.empty()) continue;
        const std::string name = fmt::format("snapshot_{}_{}_dt{}", scene, r->spec.scheme, dt_tag(dt));
        dir.write("plots/" + name + ".svg",
                  snapshot_svg(fmt::format("{}, {}, dt = {:g} s{}: spheres seen along +y (lighter: farther), walls in blue", scene, r->spec.scheme, dt,
                                           r->has(metric::ensemble_size) ? ", first member of the ensemble" : ""),
                               r->snapshots, r->walls));
        pictures += fmt::format("![{}](plots/{}.svg)\n\n", name, name);
    }
    if (!pictures.empty()) md += "The stones and, in blue, the walls (data: `snapshots/`, `walls/`):\n\n" + pictures;
    return md;
}

}  // namespace rotbench
