#include "harness/exec/client_trajectory.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

std::string read_trajectory(const std::filesystem::path& file, const TrajectoryLayout& layout, std::int64_t steps, double dt,
                            std::vector<TrajectoryRow>& rows) {
    const std::string name = "its trajectory.csv";
    const auto columns = split_commas(layout.header);
    const auto per_step = static_cast<std::int64_t>(layout.bodies);
    const std::int64_t due = per_step * (steps + 1);
    // Sized before it is read: the rows due, at 64 bytes a number at most, bound it; the reader
    // would otherwise hold the whole file and a string per field (40-75 bytes a byte).
    const double most_bytes = 4096.0 + 64.0 * static_cast<double>(columns.size()) * static_cast<double>(due);
    std::string text;
    if (const std::string why = read_program_output(file, name, most_bytes, fmt::format("{} rows of {} numbers", due, columns.size()), text);
        !why.empty())
        return why;
    try {
        const auto records = read_csv(text, name, layout.header);
        // Row by row first, so that a wrong value is named by its line and column (FILE:LINE:COLUMN).
        for (std::int64_t k = 0; k < std::ssize(records) && k < due; ++k) {
            const auto& record = records[static_cast<std::size_t>(k)];
            TrajectoryRow row(columns.size());
            for (std::size_t c = 0; c < row.size(); ++c) {
                const std::string at = fmt::format("{}:{} ({})", where(name, record), c + 1, columns[c]);
                row[c] = csv_number(record[c], at);
                if (layout.finite && !std::isfinite(row[c])) return fmt::format("{}: a value that is not finite ({})", at, record[c]);
            }
            const double t = static_cast<double>(k / per_step) * dt;
            if (!(std::abs(row[0] - t) <= 1e-9 * std::max(1.0, std::abs(t))))
                return fmt::format("{}: t = {} where step {} is at t = {}", where(name, record), record[0], k / per_step, format_number(t));
            if (per_step > 1 && row[1] != static_cast<double>(k % per_step))
                return fmt::format("{}: body {} where body {} is due (each step's rows in order, body 0 first)", where(name, record), record[1],
                                   k % per_step);
            rows.push_back(std::move(row));
        }
        if (std::ssize(records) != due)
            return fmt::format("its trajectory has {} rows; {} are due, {} at every step t = k dt, k = 0 ... {}", records.size(), due,
                               per_step == 1 ? "one" : fmt::format("{} (one a body)", per_step), steps);
    } catch (const InputError& e) {
        return std::string("its trajectory is malformed: ") + e.what();
    }
    return "";
}

}  // namespace rotbench
