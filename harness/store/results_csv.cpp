#include "harness/store/results_csv.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/run_record.hpp"
#include "harness/store/output_files.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <sstream>

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

// What a run store of rotbench's holds: ids, and steps and durations in range. A store cut,
// edited or written by something else is refused, never taken for results.
void check_run(const RunResult& r, const std::string& at) {
    if (!is_id(r.spec.scene) || !is_id(r.spec.scheme)) throw InputError(at + ": a scene or scheme id that is not one");
    if (!(r.spec.t_end > 0.0) || !std::isfinite(r.spec.t_end) || !std::isfinite(r.spec.dt) || r.spec.dt < 0.0 ||
        (!finds_its_own_dt(r.spec.kind) && !(r.spec.dt > 0.0)))
        throw InputError(at + ": dt or t_end out of range");
    for (const auto& [name, value] : r.metrics)
        if (!is_id(name)) throw InputError(at + ": '" + name + "' is not a metric name");
}

}  // namespace

std::string run_store(const std::vector<RunResult>& runs, const std::vector<PlanPlace>& places) {
    std::string text;
    for (std::size_t i = 0; i < runs.size(); ++i) text += run_record(i, runs[i], places.empty() ? std::nullopt : std::optional(places.at(i)));
    return text;
}

void write_run_files(const OutputDir& dir, const std::vector<RunResult>& runs, const std::vector<RunResult>& tables,
                     const SchemeInfos& recorded, const std::vector<PlanPlace>& places) {
    std::vector<std::string> schemes;
    for (const auto& r : runs) schemes.push_back(r.spec.scheme);
    dir.write("schemes.json", schemes_json(describe_schemes(schemes, recorded)));
    dir.write("runs.jsonl", run_store(runs, places));
    dir.write("results.csv", results_csv(tables));
    dir.write("runs.csv", runs_csv(tables));
}

namespace {

// `size`: the bytes of the store, which its whole records must span.
StoredRuns parse_run_store(std::istream& in, std::size_t size, const std::string& name) {
    RunRecords records = parse_run_records(in, name);
    if (records.whole_length != size)
        throw InputError(fmt::format("{}: cut short or not a run store after {} runs", name, records.runs.size()));
    if (records.runs.empty()) throw InputError(name + ": no run in the store");
    StoredRuns stored{{}, std::move(records.places)};
    for (auto& [index, run] : records.runs) {
        const std::string at = fmt::format("{}: run {}", name, index);
        if (index != stored.runs.size()) throw InputError(fmt::format("{}: run {} where run {} is due", name, index, stored.runs.size()));
        check_run(run, at);
        stored.runs.push_back(std::move(run));
    }
    return stored;
}

}  // namespace

std::vector<RunResult> parse_run_store(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    return parse_run_store(in, text.size(), name).runs;
}

StoredRuns read_run_store(const std::filesystem::path& dir, const std::string& store) {
    const std::filesystem::path path = dir / store;
    std::ifstream in = open_input_stream(path, "cannot read");
    return parse_run_store(in, std::filesystem::file_size(path), path.string());
}

std::vector<RunResult> read_results(const std::filesystem::path& dir, const std::string& store) {
    return read_run_store(dir, store).runs;
}

}  // namespace rotbench
