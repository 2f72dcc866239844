// results.csv: tidy long format, header exactly `scene,scheme,dt,metric,value`
// (DESIGN.md "Output contract").
#pragma once

#include "harness/run.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results);

// runs.csv: what results.csv does not hold, so that `rotbench report DIR` can re-render:
// header scene,scheme,dt,t_end,params,failure; params as KEY=V1 V2 ...;KEY=... and the
// failure text with commas replaced by semicolons.
std::string runs_csv(const std::vector<RunResult>& results);

// Reads results.csv and runs.csv (and the energy series under series/) back. InputError
// when a file is missing or malformed.
std::vector<RunResult> read_results(const std::filesystem::path& dir);
// The same from the files' texts (a run journal keeps them so), `series` mapping a series
// file's name to its text; `source` stands for the directory in error messages.
std::vector<RunResult> parse_results(const std::string& results_text, const std::string& runs_text,
                                     const std::map<std::string, std::string>& series, const std::string& source);

// shard.csv, written by `rotbench run --shard K/N` beside its results.csv and runs.csv:
// header plan_id,shard,shards,plan_size,plan_index,scene,scheme,dt, a row per run of the
// slice, in the order of runs.csv.
std::string shard_csv(const std::string& plan_id, int shard, int shards, const std::vector<RunResult>& results,
                      const std::vector<std::size_t>& plan_indices, std::size_t plan_size);

// The results of the shard directories, in plan order. InputError unless they are the N
// slices of one sweep (same plan_id and N), each exactly once.
std::vector<RunResult> merge_shards(const std::vector<std::filesystem::path>& dirs);

}  // namespace rotbench
