#include "harness/cli/sweep_command.hpp"

#include "harness/engine/interrupt.hpp"
#include "harness/engine/sweep.hpp"
#include "harness/io/journal.hpp"
#include "harness/io/parse.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/progress.hpp"
#include "harness/io/results_csv.hpp"
#include "harness/io/series_csv.hpp"

#include <fmt/format.h>
#include <mutex>

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

SweepOutcome sweep_plan(const PlanSlice& slice, const OutputDir* dir, const Invocation& how, const RunOptions& options, int jobs,
                        bool timed_alone, bool quiet) {
    const Shard shard = slice.shard.value_or(Shard{});
    const std::string journal_id = fmt::format("{}/{}/{}", slice.plan_id, shard.index, shard.count);
    std::optional<Journal> journal;
    if (dir) journal = how.resuming ? Journal::reopen(*dir, journal_id, slice.runs)
                                    : Journal::start(*dir, how.arguments, journal_id, slice.runs);
    std::map<std::size_t, RunResult> finished;
    if (journal) finished = journal->finished();
    if (how.resuming) how.out << fmt::format("resuming: {} of {} runs were finished\n", finished.size(), slice.runs.size());

    // What is left, in two phases when the timed runs go alone.
    std::vector<std::vector<std::size_t>> phases(2);
    for (std::size_t i = 0; i < slice.runs.size(); ++i)
        if (!finished.count(i)) phases[timed_alone && slice.runs[i].timed ? 1 : 0].push_back(i);
    std::mutex mutex;
    std::optional<OutputError> write_failure;  // the first; the sweep stops at it
    const InterruptGuard guard;
    std::vector<double> weights;  // the progress counts what is left to run, weighted by steps
    std::map<std::size_t, std::size_t> item_of;
    for (const auto& phase : phases)
        for (std::size_t i : phase) {
            item_of[i] = weights.size();
            weights.push_back(slice.runs[i].t_end / slice.runs[i].dt);
        }
    Progress progress(how.err, Progress::mode_for(how.err, quiet), "run", std::move(weights));
    for (int phase = 0; phase < 2 && !interrupt_signal() && !write_failure; ++phase) {
        const auto& todo = phases[phase];
        std::vector<RunSpec> specs;
        for (std::size_t i : todo) specs.push_back(slice.runs[i]);
        run_sweep(
            specs, options,
            [&](std::size_t k, const RunResult& r) {
                try {
                    if (journal) journal->record(todo[k], r);
                } catch (const OutputError& e) {
                    std::lock_guard lock(mutex);
                    if (!write_failure) write_failure = e;
                    request_stop();  // no new run starts; the ones in flight stop
                    return;
                }
                if (!r.failure.empty() && !quiet)
                    progress.note(how.out, fmt::format("{} {} {} dt={:g} FAILED: {}", r.spec.scene, r.spec.scheme,
                                                       kind_name(r.spec.kind), r.spec.dt, r.failure));
                progress.finished(item_of.at(todo[k]), !r.failure.empty());
                std::lock_guard lock(mutex);
                finished.insert_or_assign(todo[k], r);
            },
            phase == 1 ? 1 : jobs,
            [&](std::size_t k) {
                const RunSpec& s = slice.runs[todo[k]];
                progress.started(item_of.at(todo[k]), fmt::format("{} {} dt={:g}", s.scene, s.scheme, s.dt));
            });
    }
    if (write_failure) {
        std::size_t kept = 0;
        if (journal) {
            try {
                kept = journal->finished().size();
            } catch (const std::exception&) {
            }
        }
        throw OutputError(fmt::format("{}; {} of {} runs are kept in the journal, and rotbench run --resume {} finishes the sweep "
                                      "once it can write",
                                      write_failure->what(), kept, slice.runs.size(), dir->path().string()));
    }
    SweepOutcome outcome;
    if (const int signal = interrupt_signal()) {
        how.err << fmt::format("rotbench: interrupted by signal {}: {} of {} runs are kept{}\n", signal, finished.size(),
                               slice.runs.size(),
                               dir ? fmt::format(" in {}; rotbench run --resume {} finishes the sweep", (dir->path() / "partial").string(),
                                                 dir->path().string())
                                   : " (none on disk: give --out to keep them)");
        outcome.exit_status = 128 + signal;
        return outcome;
    }
    // The results come from the journal where there is one, as a resumed run's do: both
    // give the same files.
    if (journal) finished = journal->finished();
    for (auto& [index, r] : finished) outcome.results.push_back(std::move(r));
    return outcome;
}

void write_slice(const OutputDir& dir, const PlanSlice& slice, const std::vector<RunResult>& results, std::ostream& out) {
    write_run_files(dir, results);
    write_run_series(results, dir);
    dir.write("shard.csv", shard_csv(slice.plan_id, slice.shard->index, slice.shard->count, results, slice.indices, slice.plan_size));
    out << fmt::format("wrote shard {}/{} ({} of {} runs) to {}; combine the shards with rotbench merge\n", slice.shard->index,
                       slice.shard->count, results.size(), slice.plan_size, dir.path().string());
}


}  // namespace rotbench
