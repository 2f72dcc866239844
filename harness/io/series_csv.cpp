#include "harness/io/series_csv.hpp"

#include "harness/io/output_files.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {

std::string dt_tag(double dt) { return fmt::format("{:g}", dt); }

std::string series_file_name(const RunResult& r) {
    return fmt::format("energy_{}_{}_dt{}.csv", r.spec.scene, r.spec.scheme, dt_tag(r.spec.dt));
}

std::string series_csv(const RunResult& r) {
    std::string csv;
    for (std::size_t c = 0; c < r.series_columns.size(); ++c) csv += (c ? "," : "") + r.series_columns[c];
    csv += "\n";
    for (const auto& row : r.series) {
        for (std::size_t c = 0; c < row.size(); ++c) csv += (c ? "," : "") + format_number(row[c]);
        csv += "\n";
    }
    return csv;
}

void write_series_file(const RunResult& r, const OutputDir& dir) { dir.write("series/" + series_file_name(r), series_csv(r)); }

void write_energy_series(const std::vector<RunResult>& results, const OutputDir& dir) {
    for (const auto& r : results)
        if (!r.series.empty()) write_series_file(r, dir);
}

}  // namespace rotbench
