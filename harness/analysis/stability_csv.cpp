#include "harness/analysis/stability_csv.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "schemes/registry.hpp"

#include <limits>

namespace rotbench {
namespace {

const std::string contact_header = "scene,scheme,zeta,kind,dt_empirical,dt_amplification,dt_peng,dt_verlet_normal";
const std::string spin_header = "scene,scheme,omega_max,kind,dt_empirical,dt_peng";

void read_kind(StabilityRow& r, const std::string& kind, const std::string& at) {
    if (kind != "sharp" && kind != "weak" && kind != "none" && kind != "failed")
        throw InputError(at + ": kind '" + kind + "' is not sharp, weak, none or failed");
    if (kind == "failed") r.failure = "failed (stability.md, where rotbench stability wrote it, says why)";
    r.unstable_at_every_dt = kind == "weak" && r.dt_empirical != 0.0;
}

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

std::vector<StabilityRow> read_stability(const std::filesystem::path& dir) {
    std::vector<StabilityRow> rows;
    const auto contact = dir / "stability.csv";
    for (const auto& f : read_csv(contact, contact_header)) {
        const std::string at = where(contact.string(), f);
        StabilityRow r{f[0], f[1], csv_number(f[2], at), 0, csv_number(f[4], at), csv_number(f[5], at), csv_number(f[6], at),
                       csv_number(f[7], at)};
        read_kind(r, f[3], at);
        rows.push_back(r);
    }
    const auto spin = dir / "stability_spin.csv";
    if (std::filesystem::exists(spin))
        for (const auto& f : read_csv(spin, spin_header)) {
            const std::string at = where(spin.string(), f);
            StabilityRow r{f[0], f[1], 0, csv_number(f[2], at), csv_number(f[4], at), std::numeric_limits<double>::quiet_NaN(),
                           csv_number(f[5], at), std::numeric_limits<double>::quiet_NaN()};
            if (!(r.omega_max > 0)) throw InputError(at + ": omega_max must be positive");
            read_kind(r, f[3], at);
            rows.push_back(r);
        }
    return rows;
}

}  // namespace rotbench
