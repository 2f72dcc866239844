#include "harness/io/shard.hpp"

#include "harness/io/csv.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/parse.hpp"
#include "harness/io/results_csv.hpp"
#include "schemes/registry.hpp"

#include <charconv>
#include <cstdint>
#include <fmt/format.h>

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
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bit
    const auto feed = [&](const std::string& s) {
        for (unsigned char c : s) {
            h ^= c;
            h *= 1099511628211ull;
        }
    };
    for (const auto& r : plan) {
        feed(fmt::format("{}|{}|{}|{}|{:a}|{:a}|", r.scene, r.scheme, kind_name(r.kind), r.timed ? "timed" : "untimed", r.dt,
                         r.t_end));
        for (const auto& [key, values] : r.params) {
            feed(key);
            for (double v : values) feed(fmt::format("={:a}", v));
        }
        feed("\n");
    }
    return fmt::format("{:016x}", h);
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
            const int k = static_cast<int>(csv_number(f[1], name)), n = static_cast<int>(csv_number(f[2], name));
            const auto size = static_cast<std::size_t>(csv_number(f[3], name));
            const auto index = static_cast<std::size_t>(csv_number(f[4], name));
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
