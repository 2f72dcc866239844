// The one way a scheme is run. Every run (a sweep's, a reversal, a horizon, a stability search,
// an amplification limit, a spectral curve, an advice rung, a trajectory export) is a task, its
// RunSpec, submitted here: the executor takes it from the journal when a resumed command has it
// there, otherwise makes it in process (a built-in scheme) or in an isolated worker (a plug-in's,
// harness/exec/isolation.hpp), journals it, reports progress and failures, and honours --jobs,
// the run limits and interrupts. How a task is computed is the executor's choice alone.
#pragma once

#include "harness/exec/interrupt.hpp"
#include "harness/exec/run.hpp"
#include "harness/store/journal.hpp"
#include "harness/store/output_files.hpp"

#include <cstddef>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

struct ExecOptions {
    RunOptions run;
    int jobs = 1;
    bool quiet = false;        // no progress on stderr and no line per failed run
    bool timed_alone = false;  // the timed runs go last, one at a time, so that they do not compete for the cores
    std::string verb = "run";  // what the progress line calls the work
};

class Executor {
public:
    // `journal`: where finished runs go first, and where a resumed command finds them (none: no --out).
    Executor(std::ostream& out, std::ostream& err, ExecOptions options, std::optional<Journal> journal = std::nullopt);

    // The tasks' results in their order; a task given twice is made once. A failing run is
    // recorded and the others go on; once SIGINT, SIGTERM or SIGHUP is caught no task starts, those in
    // flight stop, and their results are marked interrupted. Progress goes to err, a line per
    // failed run to out. A journal that cannot be written (a full disk) stops the tasks: the
    // ones in flight finish, and an OutputError says what is kept and how to resume.
    std::vector<RunResult> run(const std::vector<RunSpec>& tasks);
    // One task, from any thread (a command whose next run depends on the last, advise); quiet.
    RunResult run(const RunSpec& task);
    // work(i) for i < count on --jobs threads, each free to submit tasks with run(task).
    void for_each(std::size_t count, const std::function<void(std::size_t)>& work) const;

    // The signal that stopped the tasks (0: none). Once it is set, interrupted() says on err what
    // is kept and how to resume, and returns the exit status (128 + signal).
    int signal() const;
    int interrupted() const;
    const ExecOptions& options() const { return options_; }

private:
    RunResult make(const RunSpec& task);  // journaled, or an interrupted result

    const InterruptGuard guard_;  // while the executor lives, a signal stops its tasks instead of the process
    std::ostream& out_;
    std::ostream& err_;
    ExecOptions options_;
    std::optional<Journal> journal_;
    std::map<RunSpec, RunResult> finished_;  // in the journal, or made by this executor
    std::optional<OutputError> write_failure_;
    mutable std::mutex mutex_;
};

}  // namespace rotbench
