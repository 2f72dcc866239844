// What the verbs that make runs share (run, gate, stability, advise): slicing a plan into
// shards, an executor that journals into the output directory (so that a signal or a kill
// loses at most the runs in flight, and `rotbench run --resume DIR` finishes the command), the
// run limits' options, and the files of a slice.
#pragma once

#include "harness/cli/verb.hpp"
#include "harness/exec/executor.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/shard.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotbench {

// A plan, or the slice of it that --shard K/N asks for.
struct PlanSlice {
    std::vector<RunSpec> runs;
    std::string plan_id;                 // of the whole plan
    std::size_t plan_size = 0;
    std::optional<Shard> shard;          // none: the whole plan
    std::vector<std::size_t> indices;    // of the slice's runs in the whole plan
};
PlanSlice slice_plan(std::vector<RunSpec> plan, const std::string& shard_text);

// --run-timeout and --run-memory, the limits of a plug-in's run in its worker, as given.
struct IsolationOptions {
    std::string run_timeout;
    int run_memory = 0;
    void add_to(CLI::App& command, const std::string& timeout_default = "ten times a slow step, and a minute");
    void apply(RunOptions& options) const;  // InputError for a bad --run-timeout
};

// The executor of a command that writes into `dir` (none: no --out): its runs are journaled
// there, and found there again when the command is resumed (how.resuming).
Executor make_executor(const Invocation& how, const OutputDir* dir, ExecOptions options);

// A slice's files for `rotbench merge`: its run store, each run with its place in the plan, and
// results.csv, runs.csv, the energy series.
inline const std::vector<std::string> slice_files = {"runs.jsonl", "schemes.json", "results.csv", "runs.csv"};
void write_slice(const OutputDir& dir, const PlanSlice& slice, const std::vector<RunResult>& results, std::ostream& out);


}  // namespace rotbench
