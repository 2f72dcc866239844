#include "harness/core/fnv1a.hpp"
#include "harness/store/shard.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"
#include "schemes/registry.hpp"

#include <charconv>
#include <cstdint>
#include <fmt/format.h>
#include <limits>
#include <map>

namespace rotbench {

Shard parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    const auto integer = [&](const std::string& part, int& out) {
        const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
    };
    Shard s;
    if (slash == std::string::npos || !integer(text.substr(0, slash), s.index) || !integer(text.substr(slash + 1), s.count) ||
        s.count < 1 || s.index < 1 || s.index > s.count)
        throw InputError("--shard '" + text + "': expected K/N with integers 1 <= K <= N");
    return s;
}

std::vector<std::size_t> shard_indices(std::size_t plan_size, const Shard& shard) {
    std::vector<std::size_t> out;
    for (std::size_t i = static_cast<std::size_t>(shard.index - 1); i < plan_size; i += static_cast<std::size_t>(shard.count))
        out.push_back(i);
    return out;
}

std::string run_id(const RunSpec& spec) { return plan_id({spec}); }

std::string plan_id(const std::vector<RunSpec>& plan) {
    Fnv1a h;
    for (const auto& r : plan) {
        h.feed(fmt::format("{}|{}|{}|{}|{:a}|{:a}|", r.scene, r.scheme, kind_name(r.kind), r.timed ? "timed" : "untimed", r.dt,
                           r.t_end));
        for (const auto& [key, values] : r.params) {
            h.feed(key);
            for (double v : values) h.feed(fmt::format("={:a}", v));
        }
        h.feed("\n");
    }
    return h.hex();
}

std::string shard_csv(const std::string& plan_id, int shard, int shards, const std::vector<RunResult>& results,
                      const std::vector<std::size_t>& plan_indices, std::size_t plan_size) {
    std::string csv = std::string(shard_header) + "\n";
    for (std::size_t i = 0; i < results.size(); ++i)
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", plan_id, shard, shards, plan_size, plan_indices[i], results[i].spec.scene,
                           results[i].spec.scheme, format_number(results[i].spec.dt), run_id(results[i].spec));
    return csv;
}

std::vector<RunResult> merge_shards(const std::vector<std::filesystem::path>& dirs) {
    std::string plan;
    int shards = 0;
    std::size_t plan_size = 0;
    std::vector<int> seen;
    std::map<std::size_t, RunResult> merged;  // by plan index; never sized by a number read from a file
    for (const auto& dir : dirs) {
        const std::string name = (dir / "shard.csv").string();
        if (!std::filesystem::exists(std::filesystem::symlink_status(dir / "shard.csv")))
            throw InputError(dir.string() + " is a whole run, not a slice of `rotbench run --shard K/N`: merge joins either the "
                             "slices of one sharded command or whole runs, not both");
        const auto rows = read_csv(dir / "shard.csv", shard_header);
        const auto results = read_results(dir);
        if (rows.size() != results.size())
            throw InputError(name + ": lists " + std::to_string(rows.size()) + " runs, runs.jsonl " +
                             std::to_string(results.size()));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const auto& f = rows[i];
            const std::string at = name + ":" + std::to_string(i + 2);
            const auto count = [&](const std::string& field, const char* what) {
                std::uint64_t v = 0;
                const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
                if (field.empty() || ec != std::errc() || ptr != field.data() + field.size())
                    throw InputError(at + ": '" + field + "' is not a count (" + what + ")");
                return v;
            };
            const std::uint64_t k = count(f[1], "shard"), n = count(f[2], "shards"), size = count(f[3], "plan_size"),
                                index = count(f[4], "plan_index");
            // Checked before use: a slice holds every n-th run of the plan, so at least
            // floor(plan_size / n) of them.
            if (n < 1 || n > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) || k < 1 || k > n ||
                size / n > rows.size())
                throw InputError(at + ": shard " + f[1] + " of " + f[2] + " in a plan of " + f[3] + " runs cannot hold " +
                                 std::to_string(rows.size()) + " runs");
            if (plan.empty()) {
                plan = f[0], shards = static_cast<int>(n), plan_size = size;
            }
            if (f[0] != plan || static_cast<int>(n) != shards || size != plan_size)
                throw InputError(name + ": a slice of another sweep (plan " + f[0] + ", " +
                                 std::to_string(n) + " shards) than the first directory's (plan " + plan + ", " +
                                 std::to_string(shards) + " shards)");
            if (i == 0) {
                if (std::find(seen.begin(), seen.end(), static_cast<int>(k)) != seen.end())
                    throw InputError(dir.string() + ": shard " + std::to_string(k) + " is given twice");
                seen.push_back(static_cast<int>(k));
            }
            const RunResult& r = results[i];
            if (index >= plan_size || merged.count(index) || r.spec.scene != f[5] || r.spec.scheme != f[6] || run_id(r.spec) != f[8])
                throw InputError(name + ": row " + std::to_string(i + 2) + " does not match runs.jsonl (its run, step, duration or parameters)");
            merged[index] = r;
        }
    }
    if (static_cast<int>(seen.size()) != shards) {
        std::string missing;
        int listed = 0;
        for (int k = 1; k <= shards && listed <= 10; ++k)
            if (std::find(seen.begin(), seen.end(), k) == seen.end())
                missing += (missing.empty() ? "" : ", ") + (++listed > 10 ? std::string("...") : std::to_string(k));
        throw InputError("merge: shard(s) " + missing + " of " + std::to_string(shards) + " missing");
    }
    if (merged.size() != plan_size) throw InputError("merge: the shards do not cover the whole plan");
    std::vector<RunResult> out;
    for (auto& [index, r] : merged) out.push_back(std::move(r));
    return out;
}

std::vector<RunResult> join_runs(const std::vector<std::filesystem::path>& dirs) {
    std::vector<RunResult> out;
    std::map<RunSpec, std::filesystem::path> from;
    for (const auto& dir : dirs) {
        if (std::filesystem::exists(std::filesystem::symlink_status(dir / "shard.csv")))
            throw InputError(dir.string() + " is a slice of `rotbench run --shard K/N`: merge joins either the slices of one "
                             "sharded command or whole runs, not both");
        for (auto& r : read_results(dir)) {
            if (const auto [it, fresh] = from.try_emplace(computed_key(r.spec), dir); !fresh)
                throw InputError(fmt::format("merge: the {} run of {} on {} at dt = {}, with the same parameters, is in both {} and "
                                             "{}: a run is joined once (an ensemble grown in parts takes other seeds: --set SCENE.seed=N)",
                                             kind_name(r.spec.kind), r.spec.scheme, r.spec.scene, format_number(r.spec.dt),
                                             it->second.string(), dir.string()));
            out.push_back(std::move(r));
        }
    }
    return out;
}

}  // namespace rotbench
