// Splitting a sweep across machines: `rotbench run --shard K/N` runs the K-th of N
// deterministic slices of the plan, `rotbench merge DIR...` puts the slices back together
// in plan order, so that the merged outputs equal an unsharded run's (timings aside).
#pragma once

#include "harness/core/run.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

struct Shard {
    int index = 1;  // K, from 1
    int count = 1;  // N
};

// "K/N" with integers 1 <= K <= N; InputError otherwise.
Shard parse_shard(const std::string& text);

// The plan indices of shard K of N: every N-th run from K - 1. Round-robin, so that each
// slice gets its share of every scene's costly small steps.
std::vector<std::size_t> shard_indices(std::size_t plan_size, const Shard& shard);

// A fingerprint of the whole plan (ids, steps, durations, parameters; FNV-1a, hex), so that
// merge refuses slices of different sweeps.
std::string plan_id(const std::vector<RunSpec>& plan);

// One run's fingerprint: plan_id of it alone, as made (its step, duration and parameters).
std::string run_id(const RunSpec& spec);

// shard.csv, written by `rotbench run --shard K/N` beside its results.csv and runs.csv: a row per
// run of the slice, in the order of runs.csv, with the run's id, which merge checks against the run
// store (a store edited to hold another step, duration or parameters is refused).
inline constexpr const char* shard_header = "plan_id,shard,shards,plan_size,plan_index,scene,scheme,dt,run";
std::string shard_csv(const std::string& plan_id, int shard, int shards, const std::vector<RunResult>& results,
                      const std::vector<std::size_t>& plan_indices, std::size_t plan_size);

// The results of the shard directories, in plan order. InputError unless they are the N
// slices of one sweep (same plan_id and N), each exactly once.
std::vector<RunResult> merge_shards(const std::vector<std::filesystem::path>& dirs);

// The runs of whole run directories (no shard.csv), in the order given: e.g. an ensemble grown in
// parts (seeds 1-5, then 6-10), whose members join into one ensemble once collapsed. InputError
// when a run (its scene, scheme, kind, dt, duration and parameters, seed included) is in two.
std::vector<RunResult> join_runs(const std::vector<std::filesystem::path>& dirs);

}  // namespace rotbench
