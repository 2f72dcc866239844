#include "harness/analysis/stability_csv.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

namespace rotbench {
namespace {

const std::string contact_header = "scene,scheme,zeta,kind,dt_empirical,dt_amplification,dt_peng,dt_verlet_normal";
const std::string spin_header = "scene,scheme,omega_max,kind,dt_empirical,dt_peng";

}  // namespace

std::string stability_csv(const std::vector<StabilityRow>& rows) {
    std::string csv = contact_header + "\n";
    for (const auto& r : rows)
        if (r.omega_max == 0)
            csv += csv_record({r.scene, r.scheme, format_number(r.zeta), stability_kind(r), format_number(r.dt_empirical),
                               format_number(r.dt_amplification), format_number(r.dt_peng), format_number(r.dt_verlet_normal)});
    return csv;
}

std::string stability_spin_csv(const std::vector<StabilityRow>& rows) {
    std::string csv = spin_header + "\n";
    for (const auto& r : rows)
        if (r.omega_max > 0)
            csv += csv_record({r.scene, r.scheme, format_number(r.omega_max), stability_kind(r), format_number(r.dt_empirical),
                               format_number(r.dt_peng)});
    return csv;
}

}  // namespace rotbench
