#include "harness/analysis/cost_tables.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"

#include <cmath>

namespace rotbench {

double CostRow::value(const std::string& column) const {
    const auto found = values.find(column);
    return found == values.end() ? NAN : found->second;
}

std::optional<CostTable> read_cost_table(const std::filesystem::path& dir) {
    const std::string name = (dir / "cost.csv").string();
    const auto text = read_file(dir / "cost.csv");
    if (!text) return std::nullopt;
    const std::vector<CsvRow> records = parse_csv(*text, name);
    CostTable table;
    if (records.empty()) return table;
    const std::vector<std::string>& header = records.front().fields;
    for (auto record = records.begin() + 1; record != records.end(); ++record) {
        if (record->size() == 1 && (*record)[0].empty()) continue;  // a blank line
        CostRow row;
        std::string mode;
        for (std::size_t i = 0; i < header.size() && i < record->size(); ++i) {
            const std::string& field = (*record)[i];
            if (header[i] == "scheme") row.scheme = field;
            else if (header[i] == "public") row.public_code = field;
            else if (header[i] == "failure") row.failure = field;
            else if (header[i] == "mode") mode = field;
            else row.values[header[i]] = field.empty() ? NAN : parse_finite(field, where(name, *record) + ": column " + header[i]);
        }
        if (row.failure.empty() && table.rows.empty()) table.thorough = mode == "thorough";
        (row.failure.empty() ? table.rows : table.failed).push_back(std::move(row));
    }
    return table;
}

std::vector<GranularSpeedRow> read_granular_speed(const std::filesystem::path& dir) {
    const auto text = read_file(dir / "granular_speed.csv");
    if (!text) return {};
    const std::string name = (dir / "granular_speed.csv").string();
    std::vector<GranularSpeedRow> rows;
    for (const CsvRow& r : read_csv(*text, name, "code,phase,t_end,steps,spheres,cpu_s,cpu_per_sphere_step")) {
        const auto number = [&](std::size_t c, const char* column) { return parse_finite(r[c], where(name, r) + ": column " + column); };
        rows.push_back({r[0], r[1], number(2, "t_end"), number(3, "steps"), number(4, "spheres"), number(5, "cpu_s"),
                        number(6, "cpu_per_sphere_step")});
    }
    return rows;
}

}  // namespace rotbench
