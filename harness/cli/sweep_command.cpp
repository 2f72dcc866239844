#include "harness/cli/sweep_command.hpp"

#include "harness/store/journal.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/store/series_csv.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

void IsolationOptions::add_to(CLI::App& command, const std::string& timeout_default) {
    command.add_option("--run-timeout", run_timeout, "SECONDS: a plug-in's run is stopped after this long (default: " + timeout_default + ")");
    command.add_option("--run-memory", run_memory, "MB: the memory a plug-in's run may take (default: half the machine over --jobs)")
        ->check(CLI::Range(64, 1 << 30));
}

void IsolationOptions::apply(RunOptions& options) const {
    options.run_timeout = run_timeout.empty() ? 0.0 : parse_positive(run_timeout, "--run-timeout");
    options.run_memory_mb = static_cast<std::size_t>(run_memory);
}

PlanSlice slice_plan(std::vector<RunSpec> plan, const std::string& shard_text) {
    PlanSlice slice;
    slice.plan_size = plan.size();
    slice.plan_id = plan_id(plan);
    if (shard_text.empty()) {
        slice.runs = std::move(plan);
        for (std::size_t i = 0; i < slice.runs.size(); ++i) slice.indices.push_back(i);
        return slice;
    }
    const Shard shard = parse_shard(shard_text);
    // An empty slice would leave merge nothing to recognise it by.
    if (static_cast<std::size_t>(shard.count) > plan.size())
        throw InputError(fmt::format("--shard {}: the sweep has only {} run(s), so at most {} shard(s)", shard_text, plan.size(),
                                     plan.size()));
    slice.shard = shard;
    slice.indices = shard_indices(plan.size(), shard);
    for (std::size_t i : slice.indices) slice.runs.push_back(plan[i]);
    return slice;
}

Executor make_executor(const Invocation& how, const OutputDir* dir, ExecOptions options) {
    std::optional<Journal> journal;
    if (dir) journal = how.resuming ? Journal::reopen(*dir) : Journal::start(*dir, how.arguments);
    return Executor(how.out, how.err, std::move(options), std::move(journal));
}

void write_slice(const OutputDir& dir, const PlanSlice& slice, const std::vector<RunResult>& results, std::ostream& out) {
    std::vector<PlanPlace> places;
    for (std::size_t index : slice.indices)
        places.push_back({slice.plan_id, static_cast<std::uint64_t>(slice.shard->index), static_cast<std::uint64_t>(slice.shard->count),
                          slice.plan_size, index});
    write_run_files(dir, results, results, {}, places);  // the members of an ensemble: collapsed once merged
    write_run_series(results, dir);
    out << fmt::format("wrote shard {}/{} ({} of {} runs) to {}; combine the shards with rotbench merge\n", slice.shard->index,
                       slice.shard->count, results.size(), slice.plan_size, dir.path().string());
}


}  // namespace rotbench
