#include "reports/convergence_plots.hpp"

#include "harness/store/output_files.hpp"
#include "reports/gnuplot.hpp"
#include "reports/panels.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace rotbench {

std::string plotted_error(const std::vector<const RunResult*>& runs) {
    for (const RunResult* r : runs)
        if (r->has(metric::omega_err_max)) return metric::omega_err_max;
    return metric::energy_drift_max;
}

std::string error_label(const std::string& name) {
    const MetricInfo* m = find_metric(name);
    return m && !m->label.empty() ? std::string(m->label) : name;
}

namespace {

using Points = std::map<std::string, std::vector<std::pair<double, double>>>;  // each scheme's (dt, error)

// A curve another one of the panel covers (the same errors to 1e-9) says so in the key, on a
// line of its own (a key entry without a sample): two ids side by side overrun the key's column.
std::string same_curve_key(const Points& points, const std::vector<std::string>& panel, std::size_t i) {
    const auto curve = [&](const std::string& scheme) { return points.count(scheme) ? points.at(scheme) : Points::mapped_type{}; };
    const auto mine = curve(panel[i]);
    for (std::size_t j = 0; j < i; ++j) {
        const auto theirs = curve(panel[j]);
        if (!mine.empty() && mine.size() == theirs.size() &&
            std::equal(mine.begin(), mine.end(), theirs.begin(), [](const auto& a, const auto& b) {
                return a.first == b.first && std::abs(a.second - b.second) <= 1e-9 * std::abs(b.second);
            }))
            return fmt::format(", keyentry with lines lt nodraw title '(= {})'", panel[j]);
    }
    return "";
}

// The numbers of the reference slopes 1, 2 and 4 through the middle of the errors, inside the
// frame where each leaves it (its right end, or the top or bottom of the errors).
std::string slope_labels(double lo, double hi, double e_lo, double e_hi) {
    const double dt_mid = std::sqrt(lo * hi), e_mid = std::sqrt(e_lo * e_hi);
    std::string out;
    for (int p : {1, 2, 4}) {
        const double y_top = e_hi * 2, y_bottom = e_lo / 2;  // inside the y range, [e_lo / 3, e_hi * 3]
        double x = hi, y = e_mid * std::pow(hi / dt_mid, p);
        if (y > y_top) x = dt_mid * std::pow(y_top / e_mid, 1.0 / p), y = y_top;
        if (y < y_bottom) x = dt_mid * std::pow(y_bottom / e_mid, 1.0 / p), y = y_bottom;
        out += fmt::format("set label {0} '{0}' at {1},{2} right offset -0.4,0.6 font ',10' tc rgb 'gray20' front\n", p,
                           format_number(x), format_number(y));
    }
    return out;
}

}  // namespace

std::string convergence_plots(const std::string& scene, const std::vector<const RunResult*>& runs, const ResultSet& set,
                              const OutputDir& dir, const std::vector<std::string>& best) {
    const std::string metric = plotted_error(runs);
    std::vector<std::string> schemes;
    for (const RunResult* r : runs)
        if (std::find(schemes.begin(), schemes.end(), r->spec.scheme) == schemes.end()) schemes.push_back(r->spec.scheme);

    // One block per scheme: dt, error, cpu seconds (finite errors only).
    std::string data = fmt::format("# {}: dt {} cpu_seconds, one block per scheme: {}\n", scene, metric, fmt::join(schemes, " "));
    double lo = INFINITY, hi = 0, e_lo = INFINITY, e_hi = 0, c_lo = INFINITY, c_hi = 0;
    Points points;
    for (const auto& scheme : schemes) {
        for (const RunResult* r : runs) {
            const double e = r->value(metric);
            if (r->spec.scheme != scheme || !std::isfinite(e) || !(e > 0)) continue;
            const double cpu = r->value(metric::cpu_seconds);
            points[scheme].push_back({r->spec.dt, e});
            data += fmt::format("{} {} {}\n", format_number(r->spec.dt), format_number(e), format_number(cpu));
            lo = std::min(lo, r->spec.dt), hi = std::max(hi, r->spec.dt);
            e_lo = std::min(e_lo, e), e_hi = std::max(e_hi, e);
            if (cpu > 0) c_lo = std::min(c_lo, cpu), c_hi = std::max(c_hi, cpu);
        }
        data += "\n\n";
    }
    if (!(hi > 0)) return "";
    dir.write(fmt::format("plots/runs_{}.dat", scene), data);

    const auto panels = family_panels(set, schemes, best);
    const auto index_of = [&](const std::string& s) { return std::find(schemes.begin(), schemes.end(), s) - schemes.begin(); };
    const auto series = [&](std::size_t p, const std::string& columns) {
        std::string line = "plot ";
        for (std::size_t i = 0; i < panels[p].schemes.size(); ++i)
            line += fmt::format("{}file index {} using {} with linespoints {} title '{}'{}", i ? ", \\\n     " : "",
                                index_of(panels[p].schemes[i]), columns, scheme_style(set, panels[p].schemes[i], i),
                                panels[p].schemes[i], same_curve_key(points, panels[p].schemes, i));
        return line;
    };
    // Reference slopes 1, 2 and 4 through the middle of the errors, over the data's dt.
    const double dt_mid = std::sqrt(lo * hi), e_mid = std::sqrt(e_lo * e_hi);
    const std::string common = fmt::format(
        "set logscale xy\nset format x '%g'\nset format y '%.0e'\nset grid\nfile = 'runs_{}.dat'\n", scene);
    std::string conv_setup = common + fmt::format(
        "set xlabel 'dt (s)'\nset ylabel '{0}'\ne0 = {1}; d0 = {2}; lo = {3}; hi = {4}\n"
        "slope(x, p) = e0*(x/d0)**p\n"
        "set xrange [lo/1.5:hi*1.5]\nset yrange [{5}/3:{6}*3]\nset samples 2\n",  // a line in log-log: its ends draw it
        error_label(metric), format_number(e_mid), format_number(dt_mid), format_number(lo), format_number(hi),
        format_number(e_lo), format_number(e_hi));
    conv_setup += slope_labels(lo, hi, e_lo, e_hi);
    const std::string conv = panel_grid_script(
        gnuplot_output(fmt::format("convergence_{}.svg", scene)), fmt::format("{}: {} against dt", scene, metric), conv_setup,
        panels, [&](std::size_t p) {
            return series(p, "1:2") + ", \\\n     [x=lo:hi] slope(x, 1) dt 2 lc 'gray50' notitle, [x=lo:hi] slope(x, 2) dt 3 lc 'gray30' "
                                      "notitle, [x=lo:hi] slope(x, 4) dt 4 lc 'gray10' notitle\n";
        });
    const Drawn convergence = draw_with_gnuplot(dir, fmt::format("plots/convergence_{}.gp", scene), conv,
                                                fmt::format("plots/convergence_{}.svg", scene));
    const bool timed = c_hi > 0;  // a client's CPU time is not measured: clients alone have no work-precision plot
    Drawn work_precision{true, ""};
    if (timed) {
        const std::string work_setup = common + fmt::format(
            "set xlabel 'CPU time of the run (s)'\nset ylabel '{}'\nset yrange [{}/3:{}*3]\nset xrange [{}/1.5:{}*1.5]\n",
            error_label(metric), format_number(e_lo), format_number(e_hi), format_number(c_lo), format_number(c_hi));
        const std::string work = panel_grid_script(gnuplot_output(fmt::format("work_precision_{}.svg", scene)),
                                                   fmt::format("{}: {} against CPU time", scene, metric), work_setup, panels,
                                                   [&](std::size_t p) { return series(p, "3:2") + "\n"; });
        work_precision = draw_with_gnuplot(dir, fmt::format("plots/work_precision_{}.gp", scene), work,
                                           fmt::format("plots/work_precision_{}.svg", scene));
    }
    if (!convergence.ok || !work_precision.ok)
        return fmt::format("(plots not drawn: {}; scripts in `plots/`)\n\n", convergence.ok ? work_precision.why : convergence.why);
    std::string shown = fmt::format("![convergence, {0}](plots/convergence_{0}.svg)\n\n", scene);
    if (timed) shown += fmt::format("![work-precision, {0}](plots/work_precision_{0}.svg)\n\n", scene);
    return shown;
}

}  // namespace rotbench
