// What the verbs that run a plan share (run, gate): slicing it into shards, running it
// through the journal of its output directory (so that a signal or a kill loses at most the
// runs in flight, and `rotbench run --resume DIR` finishes it), and the files of a slice.
#pragma once

#include "harness/cli/verb.hpp"
#include "harness/engine/run.hpp"
#include "harness/io/output_dir.hpp"
#include "harness/io/shard.hpp"

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

struct SweepOutcome {
    std::vector<RunResult> results;  // in the slice's order, every run (when not interrupted)
    int exit_status = 0;             // 128 + signal when SIGINT or SIGTERM cut the sweep short
};

// --run-timeout and --run-memory, the limits of a plug-in's run in its worker, as given.
struct IsolationOptions {
    std::string run_timeout;
    int run_memory = 0;
    void add_to(CLI::App& command, const std::string& timeout_default = "ten times a slow step, and a minute");
    void apply(RunOptions& options) const;  // InputError for a bad --run-timeout
};

// Runs the slice, `jobs` at a time, with progress on how.err (harness/io/progress.hpp) and a
// line per failed run on how.out, none of either when `quiet`. With a directory
// every finished run goes to its journal (DIR/partial) first, and a resumed invocation
// (how.resuming) runs only what is missing. `timed_alone`: the runs that are timed go last,
// one at a time, so that they do not compete for the cores.
// A file that cannot be written (a full disk) stops the sweep: the runs in flight finish, the
// finished ones are kept in the journal, and the OutputError is rethrown.
SweepOutcome sweep_plan(const PlanSlice& slice, const OutputDir* dir, const Invocation& how, const RunOptions& options, int jobs,
                        bool timed_alone, bool quiet = false);

// A slice's files for `rotbench merge`: results.csv, runs.csv, the energy series, shard.csv.
inline const std::vector<std::string> slice_files = {"runs.jsonl", "results.csv", "runs.csv", "shard.csv"};
void write_slice(const OutputDir& dir, const PlanSlice& slice, const std::vector<RunResult>& results, std::ostream& out);


}  // namespace rotbench
