#include "reports/results_csv.hpp"

#include "harness/parse.hpp"
#include "reports/energy_series.hpp"
#include "reports/output_files.hpp"

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

std::vector<std::vector<std::string>> read_csv(const std::string& text, const std::string& name, const std::string& header) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != header) throw InputError(name + ":1: expected the header '" + header + "'");
    std::vector<std::vector<std::string>> rows;
    for (int number = 2; std::getline(in, line); ++number) {
        auto fields = split_commas(line);
        if (fields.size() != split_commas(header).size())
            throw InputError(fmt::format("{}:{}: expected {} fields", name, number, split_commas(header).size()));
        rows.push_back(std::move(fields));
    }
    return rows;
}

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path, const std::string& header) {
    const auto text = read_file(path);
    if (!text) throw InputError("cannot read " + path.string());
    return read_csv(*text, path.string(), header);
}

double number(const std::string& text, const std::string& name) {
    double v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size()) throw InputError(name + ": '" + text + "' is not a number");
    return v;
}

// The three parts of reading runs back, in the order the files depend on each other.
std::vector<RunResult> parse_runs(const std::string& runs_text, const std::string& source) {
    const std::string name = source + "/runs.csv";
    std::vector<RunResult> results;
    for (const auto& f : read_csv(runs_text, name, "scene,scheme,dt,t_end,params,failure")) {
        RunResult r;
        r.spec.scene = f[0];
        r.spec.scheme = f[1];
        r.spec.dt = number(f[2], name);
        r.spec.t_end = number(f[3], name);
        for (const auto& item : split_on(f[4], ';')) {
            if (item.empty()) continue;
            const auto eq = item.find('=');
            std::vector<double> values;
            for (const auto& v : split_on(item.substr(eq + 1), ' ')) values.push_back(number(v, name));
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
        const auto it = index.find({f[0], f[1], number(f[2], name)});
        if (it == index.end()) throw InputError(name + ": a run that runs.csv does not list");
        results[it->second].metrics.emplace_back(f[3], number(f[4], name));
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
            for (const auto& v : split_commas(line)) row.push_back(number(v, name));
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

std::string shard_csv(const std::string& plan_id, int shard, int shards, const std::vector<RunResult>& results,
                      const std::vector<std::size_t>& plan_indices, std::size_t plan_size) {
    std::string csv = "plan_id,shard,shards,plan_size,plan_index,scene,scheme,dt\n";
    for (std::size_t i = 0; i < results.size(); ++i)
        csv += fmt::format("{},{},{},{},{},{},{},{}\n", plan_id, shard, shards, plan_size, plan_indices[i], results[i].spec.scene,
                           results[i].spec.scheme, format_number(results[i].spec.dt));
    return csv;
}

std::vector<RunResult> merge_shards(const std::vector<std::filesystem::path>& dirs) {
    std::string plan;
    int shards = 0;
    std::size_t plan_size = 0;
    std::vector<int> seen;
    std::vector<std::optional<RunResult>> merged;
    for (const auto& dir : dirs) {
        const std::string name = (dir / "shard.csv").string();
        const auto rows = read_csv(dir / "shard.csv", "plan_id,shard,shards,plan_size,plan_index,scene,scheme,dt");
        const auto results = read_results(dir);
        if (rows.size() != results.size())
            throw InputError(name + ": lists " + std::to_string(rows.size()) + " runs, runs.csv " +
                             std::to_string(results.size()));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const auto& f = rows[i];
            const int k = static_cast<int>(number(f[1], name)), n = static_cast<int>(number(f[2], name));
            const auto size = static_cast<std::size_t>(number(f[3], name));
            const auto index = static_cast<std::size_t>(number(f[4], name));
            if (plan.empty()) {
                plan = f[0], shards = n, plan_size = size;
                merged.resize(plan_size);
            }
            if (f[0] != plan || n != shards || size != plan_size)
                throw InputError(name + ": a slice of another sweep (plan " + f[0] + ", " +
                                 std::to_string(n) + " shards) than the first directory's (plan " + plan + ", " +
                                 std::to_string(shards) + " shards)");
            if (i == 0) {
                if (std::find(seen.begin(), seen.end(), k) != seen.end())
                    throw InputError(dir.string() + ": shard " + std::to_string(k) + " is given twice");
                seen.push_back(k);
            }
            const RunResult& r = results[i];
            if (index >= plan_size || merged[index] || r.spec.scene != f[5] || r.spec.scheme != f[6])
                throw InputError(name + ": row " + std::to_string(i + 2) + " does not match runs.csv");
            merged[index] = r;
        }
    }
    if (static_cast<int>(seen.size()) != shards) {
        std::string missing;
        for (int k = 1; k <= shards; ++k)
            if (std::find(seen.begin(), seen.end(), k) == seen.end()) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
        throw InputError("merge: shard(s) " + missing + " of " + std::to_string(shards) + " missing");
    }
    std::vector<RunResult> out;
    for (auto& r : merged) {
        if (!r) throw InputError("merge: the shards do not cover the whole plan");
        out.push_back(std::move(*r));
    }
    return out;
}

}  // namespace rotbench
