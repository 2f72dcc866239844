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

// A fingerprint of the whole plan (ids, steps, durations, parameters; FNV-1a, hex), which each
// run of a slice carries in its record (PlanPlace), so that merge refuses slices of different sweeps.
std::string plan_id(const std::vector<RunSpec>& plan);

// The runs of `dirs` for `rotbench merge`. The N slices of one sharded command, in any order, are
// put back in plan order: InputError unless they are exactly those slices, each once, and their
// runs make the plan whose fingerprint they carry (a store edited to hold another step, duration
// or parameters is refused). Whole runs are joined in the order given, e.g. an ensemble grown in
// parts (seeds 1-5, then 6-10), whose members join into one ensemble once collapsed: InputError
// when a run (its scene, scheme, kind, dt, duration and parameters, seed included) is in two.
// Slices and whole runs do not mix.
std::vector<RunResult> merge_runs(const std::vector<std::filesystem::path>& dirs);

}  // namespace rotbench
