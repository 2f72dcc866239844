#include "harness/core/fnv1a.hpp"
#include "harness/store/shard.hpp"

#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"

#include <algorithm>
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

namespace {

namespace fs = std::filesystem;
using Stores = std::vector<std::pair<fs::path, StoredRuns>>;

std::vector<RunResult> merge_slices(Stores& stores) {
    const PlanPlace first = *stores.front().second.places.front();
    std::vector<std::uint64_t> seen;
    std::map<std::uint64_t, RunResult> merged;  // by plan index; never sized by a number read from a file
    for (auto& [dir, store] : stores) {
        const std::string name = (dir / "runs.jsonl").string();
        const std::uint64_t k = store.places.front() ? store.places.front()->shard : 0;
        if (std::find(seen.begin(), seen.end(), k) != seen.end()) throw InputError(fmt::format("{}: shard {} is given twice", dir.string(), k));
        seen.push_back(k);
        for (std::size_t i = 0; i < store.runs.size(); ++i) {
            const std::string at = fmt::format("{}: run {}", name, i);
            if (!store.places[i])
                throw InputError(dir.string() + " is a whole run, not a slice of `rotbench run --shard K/N`: merge joins either the "
                                 "slices of one sharded command or whole runs, not both");
            const PlanPlace& p = *store.places[i];
            // Checked before use: a slice holds every n-th run of the plan, so at least floor(plan_size / n) of them.
            if (p.shards < 1 || p.shards > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) || p.shard < 1 ||
                p.shard > p.shards || p.plan_size / p.shards > store.runs.size())
                throw InputError(fmt::format("{}: shard {} of {} in a plan of {} runs cannot hold {} runs", at, p.shard, p.shards,
                                             p.plan_size, store.runs.size()));
            if (p.plan_id != first.plan_id || p.shards != first.shards || p.plan_size != first.plan_size)
                throw InputError(fmt::format("{}: a slice of another sweep (plan {}, {} shards) than the first directory's (plan {}, {} shards)",
                                             name, p.plan_id, p.shards, first.plan_id, first.shards));
            if (p.shard != k || p.plan_index >= p.plan_size || p.plan_index % p.shards != k - 1 ||
                !merged.emplace(p.plan_index, std::move(store.runs[i])).second)
                throw InputError(fmt::format("{}: plan index {} is not a place of shard {} of {}", at, p.plan_index, k, p.shards));
        }
    }
    if (seen.size() != first.shards) {
        std::string missing;
        int listed = 0;
        for (std::uint64_t k = 1; k <= first.shards && listed <= 10; ++k)
            if (std::find(seen.begin(), seen.end(), k) == seen.end())
                missing += (missing.empty() ? "" : ", ") + (++listed > 10 ? std::string("...") : std::to_string(k));
        throw InputError(fmt::format("merge: shard(s) {} of {} missing", missing, first.shards));
    }
    if (merged.size() != first.plan_size) throw InputError("merge: the shards do not cover the whole plan");
    std::vector<RunResult> out;
    std::vector<RunSpec> plan;
    for (auto& [index, r] : merged) plan.push_back(r.spec), out.push_back(std::move(r));
    if (plan_id(plan) != first.plan_id)
        throw InputError("merge: the slices' runs do not make the plan they name (plan " + first.plan_id +
                         "): a run store edited to hold another step, duration or parameters");
    return out;
}

std::vector<RunResult> join_runs(Stores& stores) {
    std::vector<RunResult> out;
    std::map<RunSpec, fs::path> from;
    for (auto& [dir, store] : stores) {
        if (std::any_of(store.places.begin(), store.places.end(), [](const auto& place) { return place.has_value(); }))
            throw InputError(dir.string() + " is a slice of `rotbench run --shard K/N`: merge joins either the slices of one "
                             "sharded command or whole runs, not both");
        for (auto& r : store.runs) {
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

}  // namespace

std::vector<RunResult> merge_runs(const std::vector<std::filesystem::path>& dirs) {
    Stores stores;
    for (const auto& dir : dirs) stores.emplace_back(dir, read_run_store(dir));
    return stores.front().second.places.front() ? merge_slices(stores) : join_runs(stores);
}

}  // namespace rotbench
