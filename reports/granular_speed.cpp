#include "reports/granular_speed.hpp"

#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string granular_speed_section(const std::vector<GranularSpeedRow>& rows) {
    if (rows.empty()) return "";
    std::map<std::string, std::map<std::string, const GranularSpeedRow*>> by_phase;  // phase -> code -> row
    for (const auto& r : rows) by_phase[r.phase][r.code] = &r;
    const double t_end = rows.back().t_end;
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
        const GranularSpeedRow& r = *found->second.at("rotbench");
        const GranularSpeedRow& l = *found->second.at("liggghts");
        md += fmt::format("| {} | {:.3g} | {:.3g} | {:.2f} | {:.0f} | {:.0f}, {:.0f} |\n", phase, r.cpu_per_sphere_step, l.cpu_per_sphere_step,
                          r.cpu_per_sphere_step / l.cpu_per_sphere_step, r.steps, r.spheres, l.spheres);
    }
    return md + "\n";
}

}  // namespace rotbench
