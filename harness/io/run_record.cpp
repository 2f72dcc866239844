#include "harness/io/run_record.hpp"

#include "harness/io/results_csv.hpp"
#include "harness/io/series_csv.hpp"

#include <charconv>
#include <fmt/format.h>

namespace rotbench {

std::string run_record(std::size_t index, const RunResult& result) {
    const std::string results = results_csv({result}), runs = runs_csv({result});
    const std::string series = result.series.empty() ? "" : series_csv(result);
    return fmt::format("run {} {} {} {}\n{}{}{}end {}\n", index, results.size(), runs.size(), series.size(), results, runs, series,
                       index);
}

namespace {

// "run I R N S": five words, four of them counts; false for anything else.
bool parse_header(const std::string& line, std::size_t& index, std::size_t (&lengths)[3]) {
    std::size_t values[4] = {0, 0, 0, 0};
    std::size_t at = 0;
    if (line.compare(0, 4, "run ") != 0) return false;
    at = 4;
    for (int k = 0; k < 4; ++k) {
        const auto [ptr, ec] = std::from_chars(line.data() + at, line.data() + line.size(), values[k]);
        if (ec != std::errc()) return false;
        at = static_cast<std::size_t>(ptr - line.data());
        if (k < 3) {
            if (at >= line.size() || line[at] != ' ') return false;
            ++at;
        }
    }
    if (at != line.size()) return false;
    index = values[0];
    for (int k = 0; k < 3; ++k) lengths[k] = values[k + 1];
    return true;
}

}  // namespace

RunRecords parse_run_records(const std::string& text, const std::string& name) {
    RunRecords found;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t line_end = text.find('\n', at);
        if (line_end == std::string::npos) break;
        std::size_t index = 0, lengths[3] = {0, 0, 0};
        if (!parse_header(text.substr(at, line_end - at), index, lengths)) break;
        const std::size_t body = line_end + 1;
        const std::size_t remaining = text.size() - body;
        if (lengths[0] > remaining || lengths[1] > remaining - lengths[0] || lengths[2] > remaining - lengths[0] - lengths[1]) break;
        const std::size_t end = body + lengths[0] + lengths[1] + lengths[2];
        const std::string trailer = fmt::format("end {}\n", index);
        if (end + trailer.size() > text.size() || text.compare(end, trailer.size(), trailer) != 0) break;
        const std::string results = text.substr(body, lengths[0]), runs = text.substr(body + lengths[0], lengths[1]);
        auto parsed = parse_results(results, runs, {}, name);
        if (parsed.size() != 1) throw InputError(name + ": a record that does not hold one run");
        if (lengths[2] > 0)  // again, with the series under the name the run gives it
            parsed = parse_results(results, runs, {{series_file_name(parsed.front()), text.substr(body + lengths[0] + lengths[1], lengths[2])}},
                                   name);
        found.runs.emplace_back(index, std::move(parsed.front()));
        at = end + trailer.size();
        found.whole_length = at;
    }
    return found;
}

}  // namespace rotbench
