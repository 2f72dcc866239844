#include "reports/convergence_plots.hpp"

#include "reports/gnuplot.hpp"
#include "harness/io/output_files.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

std::string plotted_error(const std::vector<const RunResult*>& runs) {
    for (const RunResult* r : runs)
        if (r->has("omega_err_max")) return "omega_err_max";
    return "energy_drift_max";
}

std::string convergence_plots(const std::string& scene, std::size_t body_count, const std::vector<const RunResult*>& runs,
                              const OutputDir& dir, const std::map<std::string, double>& instructions) {
    const std::string metric = plotted_error(runs);
    std::vector<std::string> schemes;
    for (const RunResult* r : runs)
        if (std::find(schemes.begin(), schemes.end(), r->spec.scheme) == schemes.end()) schemes.push_back(r->spec.scheme);

    // The deterministic cost of a run: the scheme's instructions per body-step (one body at a
    // time, as scenes step; callgrind, cost.csv) times its body-steps. Drawn when every scheme
    // plotted has a count.
    const bool counted = std::all_of(schemes.begin(), schemes.end(), [&](const auto& s) { return instructions.count(s); }) &&
                         instructions.count("direct");
    const double bodies = static_cast<double>(body_count);

    // One block per scheme: dt, error, cpu seconds, force evaluations, scheme instructions (finite errors only).
    std::string data = fmt::format("# {}: dt {} cpu_seconds force_evals scheme_instructions, one block per scheme: {}\n",
                                   scene, metric, fmt::format("{}", fmt::join(schemes, " ")));
    double lo = INFINITY, hi = 0, e_mid = 0, dt_mid = 0, e_lo = INFINITY, e_hi = 0;
    for (const auto& scheme : schemes) {
        for (const RunResult* r : runs) {
            const double e = r->value(metric);
            if (r->spec.scheme != scheme || !std::isfinite(e) || !(e > 0)) continue;
            const double instr = counted ? instructions.at(scheme) * r->value("steps") * bodies : NAN;
            data += fmt::format("{} {} {} {} {}\n", format_number(r->spec.dt), format_number(e),
                                format_number(r->value("cpu_seconds")), format_number(r->value("force_evals")),
                                format_number(instr));
            lo = std::min(lo, r->spec.dt);
            hi = std::max(hi, r->spec.dt);
            e_lo = std::min(e_lo, e);
            e_hi = std::max(e_hi, e);
        }
        data += "\n\n";
    }
    if (!(hi > 0)) return "";
    // Reference slopes pass through the geometric middle of the first scheme's errors.
    for (const RunResult* r : runs)
        if (r->spec.scheme == schemes.front() && std::isfinite(r->value(metric)) && r->value(metric) > 0 &&
            (dt_mid == 0 || std::abs(std::log(r->spec.dt / std::sqrt(lo * hi))) < std::abs(std::log(dt_mid / std::sqrt(lo * hi))))) {
            dt_mid = r->spec.dt;
            e_mid = r->value(metric);
        }
    dir.write(fmt::format("plots/runs_{}.dat", scene), data);

    const std::string names = fmt::format("{}", fmt::join(schemes, " "));
    std::vector<std::string> titles;  // with the instruction ratio to direct, where counted
    for (const auto& s : schemes)
        titles.push_back(counted ? fmt::format("{}({:.2f}x)", s, instructions.at(s) / instructions.at("direct")) : s);
    const std::string head = fmt::format(
        "set terminal svg size {} dynamic noenhanced font 'sans,12'\n"
        "set logscale xy\nset format x '%g'\nset format y '%.0e'\nset grid\nset key outside right\n"
        "names = '{}'\ntitles = '{}'\nfile = 'runs_{}.dat'\n",
        counted ? "1200,480" : "800,480", names, fmt::join(titles, " "), scene);
    const std::string conv = head + fmt::format(
        "{8}set title '{0}: {1} against dt'\nset xlabel 'dt (s)'\nset ylabel '{1}'\n"
        "e0 = {2}; d0 = {3}; lo = {4}; hi = {5}\n"
        "slope(x, p) = (x >= lo && x <= hi) ? e0*(x/d0)**p : 1/0  # drawn over the data's dt only\n"
        "set xrange [lo/1.5:hi*1.5]\nset yrange [{6}/3:{7}*3]\nset samples 200\n"
        "plot for [i=1:words(names)] file index (i-1) using 1:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(names, i), \\\n"
        "     slope(x, 1) dt 2 lc 'gray50' title 'slope 1', slope(x, 2) dt 3 lc 'gray30' title 'slope 2', \\\n"
        "     slope(x, 4) dt 4 lc 'gray10' title 'slope 4'\n",
        scene, metric, format_number(e_mid), format_number(dt_mid), format_number(lo), format_number(hi),
        format_number(e_lo), format_number(e_hi), gnuplot_output(fmt::format("convergence_{}.svg", scene)));
    const std::string line = "with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(titles, i)\n";
    std::string work = head + fmt::format(
        "{6}set multiplot layout 1,{2} title '{0}: {1} against cost{3}'\n"
        "set xlabel 'CPU time (s)'\nset ylabel '{1}'\nunset key\n"
        "plot for [i=1:words(names)] file index (i-1) using 3:2 {4}"
        "set xlabel 'force evaluations'\n{5}"
        "plot for [i=1:words(names)] file index (i-1) using 4:2 {4}",
        scene, metric, counted ? 3 : 2, counted ? " (legend: instructions per body-step / direct)" : "", line,
        counted ? "" : "set key outside right\n", gnuplot_output(fmt::format("work_precision_{}.svg", scene)));
    if (counted)
        work += "set xlabel 'scheme instructions (callgrind)'\nset key outside right\n"
                "plot for [i=1:words(names)] file index (i-1) using 5:2 " + line;
    work += "unset multiplot\n";
    const Drawn convergence = draw_with_gnuplot(dir, fmt::format("plots/convergence_{}.gp", scene), conv,
                                                fmt::format("plots/convergence_{}.svg", scene));
    const Drawn work_precision = draw_with_gnuplot(dir, fmt::format("plots/work_precision_{}.gp", scene), work,
                                                   fmt::format("plots/work_precision_{}.svg", scene));
    if (!convergence.ok || !work_precision.ok)
        return fmt::format("(plots not drawn: {}; scripts in `plots/`)\n\n", convergence.ok ? work_precision.why : convergence.why);
    return fmt::format("![convergence, {0}](plots/convergence_{0}.svg)\n\n![work-precision, {0}](plots/work_precision_{0}.svg)\n\n",
                       scene);
}

}  // namespace rotbench
