#include "reports/granular_speed.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string granular_speed_section(const std::filesystem::path& dir) {
    const auto text = read_file(dir / "granular_speed.csv");
    if (!text) return "";
    const std::string name = (dir / "granular_speed.csv").string();
    // phase -> code -> (CPU s per sphere-step, spheres, steps, t_end)
    std::map<std::string, std::map<std::string, std::array<double, 4>>> by_phase;
    for (const CsvRow& r : read_csv(*text, name, "code,phase,t_end,steps,spheres,cpu_s,cpu_per_sphere_step")) {
        const auto number = [&](std::size_t c, const char* column) { return parse_finite(r[c], where(name, r) + ": column " + column); };
        by_phase[r[1]][r[0]] = {number(6, "cpu_per_sphere_step"), number(4, "spheres"), number(3, "steps"), number(2, "t_end")};
    }
    double t_end = NAN;
    for (const auto& [phase, codes] : by_phase)
        for (const auto& [code, row] : codes) t_end = row[3];
    std::string md = fmt::format(
        "\n### The granular step beside LIGGGHTS\n\n"
        "CPU seconds per sphere-step of each code on the same silo (`silo_discharge`, {} s; `richardson` in rotbench, `fix "
        "multisphere` in LIGGGHTS 3.8.0), run at the same time on one core each by `benchmarks/granular_speed.py`; each code over "
        "its own packing.\n\n| phase | rotbench | LIGGGHTS | rotbench / LIGGGHTS | steps | spheres (rotbench, LIGGGHTS) |\n"
        "|---|--:|--:|--:|--:|---|\n",
        t_end);
    for (const char* phase : {"fill", "discharge"}) {
        const auto found = by_phase.find(phase);
        if (found == by_phase.end() || !found->second.count("rotbench") || !found->second.count("liggghts")) continue;
        const auto& r = found->second.at("rotbench");
        const auto& l = found->second.at("liggghts");
        md +=
            fmt::format("| {} | {:.3g} | {:.3g} | {:.2f} | {:.0f} | {:.0f}, {:.0f} |\n", phase, r[0], l[0], r[0] / l[0], r[2], r[1], l[1]);
    }
    return md + "\n";
}

}  // namespace rotbench
