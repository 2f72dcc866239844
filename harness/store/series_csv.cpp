#include "harness/store/series_csv.hpp"

#include "harness/store/output_files.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {

std::string dt_tag(double dt) { return fmt::format("{:g}", dt); }

namespace {

// SCENE_SCHEME_dtDT, and _seedS for a run that sets its scene's seed (an ensemble's member).
std::string run_tag(const RunSpec& spec) {
    std::string tag = fmt::format("{}_{}_dt{}", spec.scene, spec.scheme, dt_tag(spec.dt));
    for (const auto& [key, values] : spec.params)
        if (key == "seed" && values.size() == 1) tag += fmt::format("_seed{:g}", values[0]);
    return tag;
}

}  // namespace

std::string table_csv(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows) {
    std::string csv;
    for (std::size_t c = 0; c < columns.size(); ++c) csv += (c ? "," : "") + columns[c];
    csv += "\n";
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < row.size(); ++c) csv += (c ? "," : "") + format_number(row[c]);
        csv += "\n";
    }
    return csv;
}

std::string series_file_name(const RunSpec& spec, bool energy) { return fmt::format("{}_{}.csv", energy ? "energy" : "curve", run_tag(spec)); }
std::string series_file_name(const RunResult& r) { return series_file_name(r.spec, r.has_energy_series()); }
std::string series_csv(const RunResult& r) { return table_csv(r.series_columns, r.series); }
void write_series_file(const RunResult& r, const OutputDir& dir) { dir.write("series/" + series_file_name(r), series_csv(r)); }

std::string snapshot_file_name(const RunSpec& spec) { return run_tag(spec) + ".csv"; }
std::string snapshot_csv(const RunResult& r) { return table_csv(snapshot_columns, r.snapshots); }
std::string walls_csv(const RunResult& r) { return table_csv(wall_columns, r.walls); }

void write_run_series(const std::vector<RunResult>& results, const OutputDir& dir) {
    for (const auto& r : results) {
        if (!r.series.empty()) write_series_file(r, dir);
        if (!r.snapshots.empty()) dir.write("snapshots/" + snapshot_file_name(r.spec), snapshot_csv(r));
        if (!r.walls.empty()) dir.write("walls/" + snapshot_file_name(r.spec), walls_csv(r));
    }
}

}  // namespace rotbench
