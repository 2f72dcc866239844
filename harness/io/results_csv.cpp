#include "harness/io/results_csv.hpp"

#include "harness/io/csv.hpp"
#include "harness/io/parse.hpp"
#include "harness/io/series_csv.hpp"
#include "harness/io/output_files.hpp"

#include <algorithm>
#include <charconv>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results) {
    std::string csv = "scene,scheme,dt,metric,value\n";
    for (const auto& r : results)
        for (const auto& [metric, value] : r.metrics)
            csv += r.spec.scene + "," + r.spec.scheme + "," + format_number(r.spec.dt) + "," + metric + "," +
                   format_number(value) + "\n";
    return csv;
}

std::string runs_csv(const std::vector<RunResult>& results) {
    std::string csv = "scene,scheme,dt,t_end,params,failure\n";
    for (const auto& r : results) {
        std::string params;
        for (const auto& [key, values] : r.spec.params) {
            params += (params.empty() ? "" : ";") + key + "=";
            for (std::size_t i = 0; i < values.size(); ++i) params += (i ? " " : "") + format_number(values[i]);
        }
        std::string failure = r.failure;
        std::replace(failure.begin(), failure.end(), ',', ';');
        std::replace(failure.begin(), failure.end(), '\n', ' ');
        csv += r.spec.scene + "," + r.spec.scheme + "," + format_number(r.spec.dt) + "," + format_number(r.spec.t_end) +
               "," + params + "," + failure + "\n";
    }
    return csv;
}

namespace {

// The three parts of reading runs back, in the order the files depend on each other.
std::vector<RunResult> parse_runs(const std::string& runs_text, const std::string& source) {
    const std::string name = source + "/runs.csv";
    std::vector<RunResult> results;
    for (const auto& f : read_csv(runs_text, name, "scene,scheme,dt,t_end,params,failure")) {
        RunResult r;
        r.spec.scene = f[0];
        r.spec.scheme = f[1];
        r.spec.dt = csv_number(f[2], name);
        r.spec.t_end = csv_number(f[3], name);
        for (const auto& item : split_on(f[4], ';')) {
            if (item.empty()) continue;
            const auto eq = item.find('=');
            std::vector<double> values;
            for (const auto& v : split_on(item.substr(eq + 1), ' ')) values.push_back(csv_number(v, name));
            r.spec.params.push_back({item.substr(0, eq), values});
        }
        r.failure = f[5];
        results.push_back(std::move(r));
    }
    return results;
}

void add_metrics(const std::string& results_text, const std::string& source, std::vector<RunResult>& results) {
    const std::string name = source + "/results.csv";
    std::map<std::tuple<std::string, std::string, double>, std::size_t> index;
    for (std::size_t i = 0; i < results.size(); ++i) index[{results[i].spec.scene, results[i].spec.scheme, results[i].spec.dt}] = i;
    for (const auto& f : read_csv(results_text, name, "scene,scheme,dt,metric,value")) {
        const auto it = index.find({f[0], f[1], csv_number(f[2], name)});
        if (it == index.end()) throw InputError(name + ": a run that runs.csv does not list");
        results[it->second].metrics.emplace_back(f[3], csv_number(f[4], name));
    }
}

void add_series(const std::map<std::string, std::string>& series, const std::string& source, std::vector<RunResult>& results) {
    for (auto& r : results) {  // energy series, where the run recorded one
        const auto found = series.find(series_file_name(r));
        if (found == series.end()) continue;
        std::istringstream in(found->second);
        const std::string name = source + "/series/" + found->first;
        std::string line;
        if (!std::getline(in, line)) continue;
        r.series_columns = split_commas(line);
        while (std::getline(in, line)) {
            std::vector<double> row;
            for (const auto& v : split_commas(line)) row.push_back(csv_number(v, name));
            r.series.push_back(std::move(row));
        }
    }
}

}  // namespace

std::vector<RunResult> parse_results(const std::string& results_text, const std::string& runs_text,
                                     const std::map<std::string, std::string>& series, const std::string& source) {
    auto results = parse_runs(runs_text, source);
    add_metrics(results_text, source, results);
    add_series(series, source, results);
    return results;
}

std::vector<RunResult> read_results(const std::filesystem::path& dir) {
    auto text = [&](const std::filesystem::path& path) {
        auto content = read_file(path);
        if (!content) throw InputError("cannot read " + path.string());
        return std::move(*content);
    };
    // Not parse_results: runs.csv is parsed before results.csv is read, so that a malformed
    // runs.csv is the error named even when results.csv is missing (tests/test_bad_input.cpp).
    auto results = parse_runs(text(dir / "runs.csv"), dir.string());
    add_metrics(text(dir / "results.csv"), dir.string(), results);
    std::map<std::string, std::string> series;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir / "series", ec))
        if (auto content = read_file(e.path())) series.emplace(e.path().filename().string(), std::move(*content));
    add_series(series, dir.string(), results);
    return results;
}

}  // namespace rotbench
