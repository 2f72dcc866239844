#include "harness/exec/executor.hpp"

#include "harness/exec/client_run.hpp"
#include "harness/exec/isolation.hpp"
#include "harness/store/client.hpp"
#include "harness/exec/parallel.hpp"
#include "harness/store/progress.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

// What progress counts a task as: its steps; a search or a curve (dt = 0) as one.
double weight(const RunSpec& task) { return task.dt > 0 ? task.t_end / task.dt : 1.0; }

// The key a task's result carries: every kind records the scene's duration, so a task given
// without one (t_end = 0) is keyed by it.
RunSpec key_of(RunSpec task) {
    if (task.t_end == 0.0) task.t_end = scene_of(task)->t_end();
    return task;
}

}  // namespace

Executor::Executor(std::ostream& out, std::ostream& err, ExecOptions options, std::optional<Journal> journal)
    : out_(out), err_(err), options_(std::move(options)), journal_(std::move(journal)) {
    if (journal_) finished_ = journal_->finished();
}

int Executor::signal() const { return interrupt_signal(); }

RunResult Executor::make(const RunSpec& task) {
    {
        std::lock_guard lock(mutex_);
        if (const auto found = finished_.find(task); found != finished_.end()) return found->second;
    }
    if (interrupt_signal()) return RunResult{task, {}, {}, true};
    const IsolationLimits limits{options_.run.run_timeout,
                                 options_.run.run_memory_mb ? options_.run.run_memory_mb : isolation_memory(options_.jobs)};
    // How a task is made is decided here alone: a client's by its program, a plug-in's in a worker,
    // a built-in's in process. A failing scheme is recorded; what they throw is bad input, passed on.
    RunResult result = client_of(task.scheme) ? run_client(task, options_.run, limits)
                       : isolated(task.scheme) ? run_isolated(task, options_.run, limits)
                                               : run_one(task, options_.run);
    if (result.interrupted || !journal_) return result;
    try {
        journal_->record(result);
    } catch (const OutputError& e) {
        std::lock_guard lock(mutex_);
        if (!write_failure_) write_failure_ = e;
        request_stop();  // no new task starts; the ones in flight stop
        result.interrupted = true;
    }
    return result;
}

RunResult Executor::run(const RunSpec& task) {
    RunResult result = make(key_of(task));
    std::lock_guard lock(mutex_);
    if (write_failure_) throw *write_failure_;
    return result;
}

void Executor::for_each(std::size_t count, const std::function<void(std::size_t)>& work) const {
    parallel_for(count, options_.jobs, [&](std::size_t i) {
        if (!interrupt_signal()) work(i);
    });
}

std::vector<RunResult> Executor::run(const std::vector<RunSpec>& given) {
    // Each distinct task once, in the order given; what is left, in two phases when the timed ones go alone.
    std::vector<RunSpec> tasks;
    std::vector<std::size_t> task_of;
    std::map<RunSpec, std::size_t> index;
    for (const RunSpec& g : given) {
        const auto [at, added] = index.emplace(key_of(g), tasks.size());
        if (added) tasks.push_back(at->first);
        task_of.push_back(at->second);
    }
    std::vector<RunResult> results(tasks.size());
    std::vector<std::vector<std::size_t>> phases(2);
    std::size_t found = 0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        if (const auto f = finished_.find(tasks[i]); f != finished_.end()) {
            results[i] = f->second;
            ++found;
        } else {
            phases[options_.timed_alone && tasks[i].timed ? 1 : 0].push_back(i);
        }
    }
    if (journal_ && !finished_.empty()) out_ << fmt::format("resuming: {} of {} runs were finished\n", found, tasks.size());
    std::vector<double> weights;  // of what is left, in the order it runs
    std::vector<std::size_t> item_of(tasks.size());
    for (const auto& phase : phases)
        for (std::size_t i : phase) {
            item_of[i] = weights.size();
            weights.push_back(weight(tasks[i]));
        }
    {
        Progress progress(err_, Progress::mode_for(err_, options_.quiet), options_.verb, std::move(weights));
        for (int phase = 0; phase < 2 && !interrupt_signal(); ++phase)
            parallel_for(phases[phase].size(), phase == 1 ? 1 : options_.jobs, [&](std::size_t k) {
                const std::size_t i = phases[phase][k];
                if (interrupt_signal()) {
                    results[i].spec = tasks[i], results[i].interrupted = true;
                    return;
                }
                const RunSpec& s = tasks[i];
                progress.started(item_of[i], fmt::format("{} {} dt={:g}", s.scene, s.scheme, s.dt));
                results[i] = make(s);
                if (results[i].interrupted) return;
                const bool declined = results[i].declined();  // a client's "not mine": skipped
                if (!results[i].failure.empty() && !options_.quiet)
                    progress.note(out_, declined ? fmt::format("skipped: {} {} {} dt={:g}: client {}", s.scene, s.scheme, kind_name(s.kind),
                                                               s.dt, results[i].failure)
                                                 : fmt::format("{} {} {} dt={:g} FAILED: {}", s.scene, s.scheme, kind_name(s.kind), s.dt,
                                                               results[i].failure));
                progress.finished(item_of[i], !results[i].failure.empty() && !declined);
            });
        for (const auto& phase : phases)  // the tasks of a phase that did not start
            for (std::size_t i : phase)
                if (results[i].spec.scene.empty()) results[i].spec = tasks[i], results[i].interrupted = true;
    }
    if (write_failure_) {
        std::size_t kept = 0;
        try {
            kept = journal_->finished().size();
        } catch (const std::exception&) {}
        throw OutputError(
            fmt::format("{}; {} of {} runs are kept in the journal, and rotbench run --resume {} finishes the work once "
                        "it can write",
                        write_failure_->what(), kept, tasks.size(), journal_->directory().string()));
    }
    std::vector<RunResult> in_order;
    for (std::size_t t : task_of) in_order.push_back(results[t]);
    return in_order;
}

int Executor::interrupted() const {
    const int signal = interrupt_signal();
    std::size_t kept = 0;
    if (journal_) {
        try {
            kept = journal_->finished().size();
        } catch (const std::exception&) {}
    }
    err_ << fmt::format("rotbench: interrupted by signal {}: {}\n", signal,
                        journal_ ? fmt::format("{} runs are kept in {}; rotbench run --resume {} finishes the work", kept,
                                               (journal_->directory() / "partial").string(), journal_->directory().string())
                                 : "nothing is kept (give --out to keep the finished runs)");
    return signal > 0 ? 128 + signal : 1;
}

}  // namespace rotbench
