#include "harness/io/stability_csv.hpp"

#include "harness/io/output_files.hpp"

#include <fmt/format.h>

namespace rotbench {

std::string stability_csv(const std::vector<StabilityRow>& rows) {
    std::string csv = "scene,scheme,zeta,dt_empirical,dt_amplification,dt_peng\n";
    for (const auto& r : rows)
        if (r.omega_max == 0)
            csv += fmt::format("{},{},{},{},{},{}\n", r.scene, r.scheme, format_number(r.zeta), format_number(r.dt_empirical),
                           format_number(r.dt_amplification), format_number(r.dt_peng));
    return csv;
}

std::string stability_spin_csv(const std::vector<StabilityRow>& rows) {
    std::string csv = "scene,scheme,omega_max,dt_empirical,dt_peng\n";
    for (const auto& r : rows)
        if (r.omega_max > 0)
            csv += fmt::format("{},{},{},{},{}\n", r.scene, r.scheme, format_number(r.omega_max), format_number(r.dt_empirical),
                               format_number(r.dt_peng));
    return csv;
}

}  // namespace rotbench
