#include "harness/io/run_record.hpp"

#include "harness/io/csv.hpp"
#include "harness/io/results_csv.hpp"
#include "harness/io/series_csv.hpp"

#include <charconv>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string run_record(std::size_t index, const RunResult& result) {
    const std::string results = results_csv({result}), runs = runs_csv({result});
    const std::string series = result.series.empty() ? "" : series_csv(result);
    const std::string snapshots = result.snapshots.empty() ? "" : snapshot_csv(result);
    const std::string walls = result.walls.empty() ? "" : walls_csv(result);
    return fmt::format("run {} {} {} {} {} {}\n{}{}{}{}{}end {}\n", index, results.size(), runs.size(), series.size(), snapshots.size(),
                       walls.size(), results, runs, series, snapshots, walls, index);
}

namespace {

// The texts of a record, in order: results, runs, series, snapshots, walls.
constexpr int parts = 5;

// "run I R N S P W": seven words, the index and the parts' lengths; false for anything else.
bool parse_header(const std::string& line, std::size_t& index, std::size_t (&lengths)[parts]) {
    std::size_t values[parts + 1] = {};
    if (line.compare(0, 4, "run ") != 0) return false;
    std::size_t at = 4;
    int count = 0;
    for (; count < parts + 1; ++count) {
        const auto [ptr, ec] = std::from_chars(line.data() + at, line.data() + line.size(), values[count]);
        if (ec != std::errc()) return false;
        at = static_cast<std::size_t>(ptr - line.data());
        if (at == line.size()) break;
        if (line[at] != ' ') return false;
        ++at;
    }
    if (at != line.size() || count != parts) return false;  // 6 numbers, the last one ending the line
    index = values[0];
    for (int k = 0; k < parts; ++k) lengths[k] = values[k + 1];
    return true;
}

}  // namespace

RunRecords parse_run_records(const std::string& text, const std::string& name) {
    RunRecords found;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t line_end = text.find('\n', at);
        if (line_end == std::string::npos) break;
        std::size_t index = 0, lengths[parts] = {};
        if (!parse_header(text.substr(at, line_end - at), index, lengths)) break;
        const std::size_t body = line_end + 1;
        std::size_t remaining = text.size() - body, offsets[parts] = {};
        bool fits = true;
        for (int k = 0; k < parts && fits; ++k) {
            fits = lengths[k] <= remaining;
            remaining -= fits ? lengths[k] : 0;
            if (k + 1 < parts) offsets[k + 1] = offsets[k] + lengths[k];
        }
        if (!fits) break;
        const std::size_t end = body + offsets[parts - 1] + lengths[parts - 1];
        const std::string trailer = fmt::format("end {}\n", index);
        if (end + trailer.size() > text.size() || text.compare(end, trailer.size(), trailer) != 0) break;
        const std::string results = text.substr(body, lengths[0]), runs = text.substr(body + offsets[1], lengths[1]);
        auto parsed = parse_results(results, runs, {}, name);
        if (parsed.size() != 1) throw InputError(name + ": a record that does not hold one run");
        if (lengths[2] > 0 || lengths[3] > 0 || lengths[4] > 0) {  // again, with the pictures' files under the names the run gives them
            const std::string series = text.substr(body + offsets[2], lengths[2]);
            const auto header = parse_csv(series.substr(0, series.find('\n') + 1), name);
            const bool energy = !header.empty() && RunResult::is_energy_series(header.front().fields);
            std::map<std::string, std::string> files;
            if (lengths[2] > 0) files["series/" + series_file_name(parsed.front().spec, energy)] = series;
            if (lengths[3] > 0) files["snapshots/" + snapshot_file_name(parsed.front().spec)] = text.substr(body + offsets[3], lengths[3]);
            if (lengths[4] > 0) files["walls/" + snapshot_file_name(parsed.front().spec)] = text.substr(body + offsets[4], lengths[4]);
            parsed = parse_results(results, runs, files, name);
        }
        found.runs.emplace_back(index, std::move(parsed.front()));
        at = end + trailer.size();
        found.whole_length = at;
    }
    return found;
}

}  // namespace rotbench
