#include "harness/store/run_record.hpp"

#include <cmath>
#include <sstream>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

using json = nlohmann::json;

json number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}

double number_of(const json& j) {
    if (j.is_number()) return j.get<double>();
    if (j == "nan") return std::nan("");
    if (j == "inf") return INFINITY;
    if (j == "-inf") return -INFINITY;
    throw InputError("not a number: " + j.dump());
}

json numbers(const std::vector<double>& values) {
    json out = json::array();
    for (double v : values) out.push_back(number(v));
    return out;
}

std::vector<double> numbers_of(const json& j) {
    std::vector<double> out;
    for (const auto& v : j) out.push_back(number_of(v));
    return out;
}

json rows(const std::vector<std::vector<double>>& table) {
    json out = json::array();
    for (const auto& row : table) out.push_back(numbers(row));
    return out;
}

std::vector<std::vector<double>> rows_of(const json& j) {
    std::vector<std::vector<double>> out;
    for (const auto& row : j) out.push_back(numbers_of(row));
    return out;
}

json spec_json(const RunSpec& s) {
    json params = json::array();
    for (const auto& [key, values] : s.params) params.push_back({key, numbers(values)});
    return {{"scene", s.scene},         {"scheme", s.scheme}, {"kind", kind_name(s.kind)}, {"dt", number(s.dt)},
            {"t_end", number(s.t_end)}, {"params", params},   {"timed", s.timed}};
}

RunSpec spec_of(const json& j) {
    RunSpec s;
    s.scene = j.at("scene").get<std::string>();
    s.scheme = j.at("scheme").get<std::string>();
    s.kind = kind_from_name(j.at("kind").get<std::string>());
    s.dt = number_of(j.at("dt"));
    s.t_end = number_of(j.at("t_end"));
    for (const auto& p : j.at("params")) s.params.push_back({p.at(0).get<std::string>(), numbers_of(p.at(1))});
    s.timed = j.at("timed").get<bool>();
    return s;
}

json run_json(const RunResult& r) {
    json metrics = json::array();
    for (const auto& [name, value] : r.metrics) metrics.push_back({name, number(value)});
    return {{"spec", spec_json(r.spec)}, {"metrics", metrics},
            {"failure", r.failure},      {"series_columns", r.series_columns},
            {"series", rows(r.series)},  {"snapshots", rows(r.snapshots)},
            {"walls", rows(r.walls)},    {"timing_samples", numbers(r.timing_samples)}};
}

RunResult run_of(const json& j) {
    RunResult r;
    r.spec = spec_of(j.at("spec"));
    for (const auto& m : j.at("metrics")) r.metrics.emplace_back(m.at(0).get<std::string>(), number_of(m.at(1)));
    r.failure = j.at("failure").get<std::string>();
    r.series_columns = j.at("series_columns").get<std::vector<std::string>>();
    r.series = rows_of(j.at("series"));
    r.snapshots = rows_of(j.at("snapshots"));
    r.walls = rows_of(j.at("walls"));
    r.timing_samples = numbers_of(j.at("timing_samples"));
    return r;
}

json place_json(const PlanPlace& p) {
    return {{"id", p.plan_id}, {"shard", p.shard}, {"shards", p.shards}, {"size", p.plan_size}, {"index", p.plan_index}};
}

PlanPlace place_of(const json& j) {
    const auto count = [&](const char* key) {
        const json& v = j.at(key);
        if (!v.is_number_unsigned()) throw InputError(fmt::format("plan {} {} is not a count", key, v.dump()));
        return v.get<std::uint64_t>();
    };
    return {j.at("id").get<std::string>(), count("shard"), count("shards"), count("size"), count("index")};
}

// The record's shape: whatever else a line holds, it is not a record of this store.
bool is_record(const json& j) { return j.is_object() && j.contains("index") && j.at("index").is_number_unsigned() && j.contains("run"); }

}  // namespace

std::string run_record(std::size_t index, const RunResult& result, const std::optional<PlanPlace>& place) {
    json record = {{"index", index}};
    if (place) record["plan"] = place_json(*place);
    record["run"] = run_json(result);
    return record.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

RunRecords parse_run_records(std::istream& in, const std::string& name) {
    RunRecords found;
    std::string line;
    while (std::getline(in, line)) {
        if (in.eof()) break;  // no line break after it: cut short
        const json j = json::parse(line, nullptr, false);
        if (j.is_discarded() || !is_record(j)) break;
        try {
            found.runs.emplace_back(j.at("index").get<std::size_t>(), run_of(j.at("run")));
            found.places.push_back(j.contains("plan") ? std::optional(place_of(j.at("plan"))) : std::nullopt);
        } catch (const json::exception& e) {
            throw InputError(fmt::format("{}: the record of run {} is malformed: {}", name, j.at("index").get<std::size_t>(), e.what()));
        } catch (const InputError& e) {
            throw InputError(fmt::format("{}: the record of run {} is malformed: {}", name, j.at("index").get<std::size_t>(), e.what()));
        }
        found.whole_length += line.size() + 1;
    }
    return found;
}

RunRecords parse_run_records(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    return parse_run_records(in, name);
}

std::string spec_record(const RunSpec& spec) { return spec_json(spec).dump(); }

RunSpec parse_spec_record(const std::string& text, const std::string& name) {
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded()) throw InputError(name + ": not JSON");
    try {
        return spec_of(j);
    } catch (const json::exception& e) {
        throw InputError(fmt::format("{}: malformed: {}", name, e.what()));
    }
}

}  // namespace rotbench
