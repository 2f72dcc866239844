#include "harness/analysis/stability_csv.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/store/parse.hpp"
#include "schemes/registry.hpp"

#include <cmath>
#include <limits>

namespace rotbench {
namespace {

const std::string contact_header = "scene,scheme,zeta,kind,dt_empirical,dt_amplification,dt_peng,dt_verlet_normal";
const std::string spin_header = "scene,scheme,omega_max,kind,dt_empirical,dt_peng";

// A row read back must be one `rotbench stability` could have written (the file may be
// hand-edited or forged): a stability scene, an id, predictions that are positive limits, and
// a kind that agrees with the measured limit (stability_kind).
void read_kind(StabilityRow& r, const std::string& kind, const std::string& at) {
    if (kind != "sharp" && kind != "weak" && kind != "none" && kind != "failed")
        throw InputError(at + ": kind '" + kind + "' is not sharp, weak, none or failed");
    try {
        check_stability_scenes({r.scene});
    } catch (const InputError& e) {
        throw InputError(at + ": " + e.what());
    }
    if (!is_id(r.scheme)) throw InputError(at + ": '" + r.scheme + "' is not a scheme id");
    if (!(r.dt_peng > 0) || std::isinf(r.dt_peng)) throw InputError(at + ": dt_peng must be a positive time step");
    if (r.dt_empirical < 0 || r.dt_amplification < 0) throw InputError(at + ": a negative time step");
    const bool sharp = r.dt_empirical > 0 && std::isfinite(r.dt_empirical);
    if ((kind == "sharp" && !sharp) || (kind == "none" && !std::isinf(r.dt_empirical)) ||
        (kind == "weak" && !(r.dt_empirical >= 0 && std::isfinite(r.dt_empirical))))
        throw InputError(at + ": kind '" + kind + "' does not go with dt_empirical " + format_number(r.dt_empirical));
    if (kind == "failed") r.failure = "failed (stability.md, where rotbench stability wrote it, says why)";
    r.unstable_at_every_dt = kind == "weak" && r.dt_empirical != 0.0;
}

// One row per scene, scheme and zeta (or spin rate): a second would be drawn over the first.
void refuse_repeats(const std::vector<StabilityRow>& rows, const std::string& at) {
    const StabilityRow& last = rows.back();
    for (std::size_t i = 0; i + 1 < rows.size(); ++i)
        if (rows[i].scene == last.scene && rows[i].scheme == last.scheme && rows[i].zeta == last.zeta && rows[i].omega_max == last.omega_max)
            throw InputError(at + ": " + last.scene + " " + last.scheme + " is there twice");
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
        if (!(r.zeta >= 0) || std::isinf(r.zeta)) throw InputError(at + ": zeta must be a finite damping ratio, at least 0");
        read_kind(r, f[3], at);
        rows.push_back(r);
        refuse_repeats(rows, at);
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
            refuse_repeats(rows, at);
        }
    return rows;
}

}  // namespace rotbench
