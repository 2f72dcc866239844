#include "harness/io/results_csv.hpp"

#include "harness/io/csv.hpp"
#include "harness/io/parse.hpp"
#include "harness/io/series_csv.hpp"
#include "harness/io/output_files.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace rotbench {

namespace {

constexpr const char* results_header = "scene,scheme,dt,metric,value";
constexpr const char* runs_header = "scene,scheme,kind,dt,t_end,params,metrics,timing,failure";

std::string params_field(const ParamOverrides& params) {
    std::string out;
    for (const auto& [key, values] : params) {
        out += (out.empty() ? "" : ";") + key + "=";
        for (std::size_t i = 0; i < values.size(); ++i) out += (i ? " " : "") + format_number(values[i]);
    }
    return out;
}

}  // namespace

std::string results_csv(const std::vector<RunResult>& results) {
    std::string csv = std::string(results_header) + "\n";
    for (const auto& r : results)
        for (const auto& [metric, value] : r.metrics)
            csv += csv_record({r.spec.scene, r.spec.scheme, format_number(r.spec.dt), metric, format_number(value)});
    return csv;
}

std::string runs_csv(const std::vector<RunResult>& results) {
    std::string csv = std::string(runs_header) + "\n";
    for (const auto& r : results) {
        std::string timing;
        for (double t : r.timing_samples) timing += (timing.empty() ? "" : " ") + format_number(t);
        csv += csv_record({r.spec.scene, r.spec.scheme, kind_name(r.spec.kind), format_number(r.spec.dt),
                           format_number(r.spec.t_end), params_field(r.spec.params), std::to_string(r.metrics.size()), timing,
                           r.failure});
    }
    return csv;
}

namespace {

// An id as the registries hold them: letters, digits and underscores.
bool is_id(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// The three parts of reading runs back, in the order the files depend on each other. Every
// field is checked: a file that was cut, edited or written by something else is refused
// with its file and line, never taken for results.
std::vector<RunResult> parse_runs(const std::string& runs_text, const std::string& source, std::vector<std::size_t>& counts) {
    const std::string name = source + "/runs.csv";
    std::vector<RunResult> results;
    const auto rows = read_csv(runs_text, name, runs_header);
    if (rows.empty()) throw InputError(name + ": no run in the file (only its header)");
    for (const auto& f : rows) {
        const std::string at = where(name, f);
        RunResult r;
        r.spec.scene = f[0];
        r.spec.scheme = f[1];
        if (!is_id(r.spec.scene) || !is_id(r.spec.scheme)) throw InputError(at + ": a scene or scheme id that is not one");
        r.spec.kind = kind_from_name(f[2]);
        r.spec.dt = csv_number(f[3], at);
        r.spec.t_end = csv_number(f[4], at);
        if (!(r.spec.t_end > 0.0) || !std::isfinite(r.spec.t_end) || !std::isfinite(r.spec.dt) || r.spec.dt < 0.0 ||
            (r.spec.kind != RunKind::stability && !(r.spec.dt > 0.0)))
            throw InputError(at + ": dt or t_end out of range");
        for (const auto& item : split_on(f[5], ';')) {
            if (item.empty()) continue;
            const auto eq = item.find('=');
            if (eq == std::string::npos || eq == 0) throw InputError(at + ": a parameter without KEY=VALUE");
            std::vector<double> values;
            for (const auto& v : split_on(item.substr(eq + 1), ' ')) values.push_back(csv_number(v, at));
            r.spec.params.push_back({item.substr(0, eq), values});
        }
        std::size_t count = 0;
        const auto [ptr, ec] = std::from_chars(f[6].data(), f[6].data() + f[6].size(), count);
        if (f[6].empty() || ec != std::errc() || ptr != f[6].data() + f[6].size()) throw InputError(at + ": 'metrics' is not a count");
        counts.push_back(count);
        if (!f[7].empty())
            for (const auto& v : split_on(f[7], ' ')) r.timing_samples.push_back(csv_number(v, at));
        r.failure = f[8];
        results.push_back(std::move(r));
    }
    return results;
}

// results.csv holds each run's metrics, run after run in the order of runs.csv: each run
// takes the next `metrics` rows, which must name its scene, scheme and dt.
void add_metrics(const std::string& results_text, const std::string& source, const std::vector<std::size_t>& counts,
                 std::vector<RunResult>& results) {
    const std::string name = source + "/results.csv";
    const auto rows = read_csv(results_text, name, results_header);
    std::size_t next = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        RunResult& r = results[i];
        for (std::size_t k = 0; k < counts[i]; ++k, ++next) {
            if (next >= rows.size())
                throw InputError(fmt::format("{}: ends before the metrics of run {} of runs.csv ({} {} dt={})", name, i + 1,
                                             r.spec.scene, r.spec.scheme, format_number(r.spec.dt)));
            const auto& f = rows[next];
            const std::string at = where(name, f);
            if (f[0] != r.spec.scene || f[1] != r.spec.scheme || csv_number(f[2], at) != r.spec.dt)
                throw InputError(at + ": a row of another run than runs.csv lists there");
            if (!is_id(f[3])) throw InputError(at + ": '" + f[3] + "' is not a metric name");
            r.metrics.emplace_back(f[3], csv_number(f[4], at));
        }
    }
    if (next != rows.size()) throw InputError(where(name, rows[next]) + ": a row that no run of runs.csv accounts for");
}

std::vector<std::vector<double>> parse_table(const std::string& text, const std::string& name, std::vector<std::string>& columns) {
    const auto records = parse_csv(text, name);
    if (records.empty() || text.back() != '\n') throw InputError(name + ": empty or cut short");
    columns = records.front().fields;
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 1; k < records.size(); ++k) {
        if (records[k].size() != columns.size())
            throw InputError(fmt::format("{}: expected {} fields", where(name, records[k]), columns.size()));
        std::vector<double> row;
        for (const auto& v : records[k].fields) row.push_back(csv_number(v, where(name, records[k])));
        rows.push_back(std::move(row));
    }
    return rows;
}

// The series, snapshots and walls of the runs that recorded them (`files`: path under the directory -> text).
void add_series(const std::map<std::string, std::string>& files, const std::string& source, std::vector<RunResult>& results) {
    for (auto& r : results) {
        if (r.spec.kind != RunKind::trajectory) continue;
        for (const bool energy : {true, false}) {
            const auto found = files.find("series/" + series_file_name(r.spec, energy));
            if (found == files.end()) continue;
            r.series = parse_table(found->second, source + "/" + found->first, r.series_columns);
            if (r.has_energy_series() != energy) throw InputError(source + "/" + found->first + ": its columns do not name its kind");
            break;
        }
        if (const auto found = files.find("snapshots/" + snapshot_file_name(r.spec)); found != files.end()) {
            std::vector<std::string> columns;
            r.snapshots = parse_table(found->second, source + "/" + found->first, columns);
            if (columns != snapshot_columns) throw InputError(source + "/" + found->first + ": expected the columns t,x,y,z,radius");
        }
        if (const auto found = files.find("walls/" + snapshot_file_name(r.spec)); found != files.end()) {
            std::vector<std::string> columns;
            r.walls = parse_table(found->second, source + "/" + found->first, columns);
            if (columns != wall_columns) throw InputError(source + "/" + found->first + ": expected the columns t,x0,z0,x1,z1");
        }
    }
}

}  // namespace

std::vector<RunResult> parse_results(const std::string& results_text, const std::string& runs_text,
                                     const std::map<std::string, std::string>& series, const std::string& source) {
    std::vector<std::size_t> counts;
    auto results = parse_runs(runs_text, source, counts);
    add_metrics(results_text, source, counts, results);
    add_series(series, source, results);
    return results;
}

std::vector<RunResult> read_results(const std::filesystem::path& dir) {
    auto text = [&](const std::filesystem::path& path) { return read_input_file(path, "cannot read"); };
    // Not parse_results: runs.csv is parsed before results.csv is read, so that a malformed
    // runs.csv is the error named even when results.csv is missing (tests/test_bad_input.cpp).
    std::vector<std::size_t> counts;
    auto results = parse_runs(text(dir / "runs.csv"), dir.string(), counts);
    add_metrics(text(dir / "results.csv"), dir.string(), counts, results);
    std::map<std::string, std::string> files;
    for (const std::string folder : {"series", "snapshots", "walls"}) {
        std::error_code ec;
        for (const auto& e : std::filesystem::directory_iterator(dir / folder, ec))
            if (e.path().extension() == ".csv") files.emplace(folder + "/" + e.path().filename().string(), read_input_file(e.path(), "cannot read"));
    }
    add_series(files, dir.string(), results);
    return results;
}

}  // namespace rotbench
