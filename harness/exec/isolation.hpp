// Runs of plug-in schemes happen in a child process: a plug-in that crashes, aborts, exits,
// loops forever or exhausts memory takes down only its own run, which is recorded as failed
// with the signal or the limit named; the sweep goes on. Built-in schemes run in process.
// The child is the rotbench executable itself (`rotbench --plugin ... __run ...`, which
// loads the same plug-ins and hands its run back as a record on its standard output).
#pragma once

#include "harness/exec/run.hpp"

#include <cstddef>
#include <cmath>
#include <string>
#include <vector>

namespace rotbench {

struct IsolationLimits {
    double seconds = 0;        // wall time of one run; 0: ten times a slow plug-in's (10 us per body-step) and a minute
    std::size_t megabytes = 0; // address space of the child; 0: derived from the machine (isolation_memory)
};

// The rotbench executable to start as the worker; empty (the default) runs every scheme in
// process. main() sets it to its own executable; the tests set it to the built binary.
void set_worker_executable(std::string path);
const std::string& worker_executable();

// Whether a scheme's runs go to a child process: it comes from a plug-in, and there is a worker.
bool isolated(const std::string& scheme);

// The default time limit of `body_steps` steps of a body: ten times what a slow plug-in (10 us per
// body-step) would take, and a minute more.
double steps_timeout(double body_steps);

// The default memory limit: half of the machine's memory over `jobs`, at least 1 GB. (The
// default time limit is derived from the run: IsolationLimits.)
std::size_t isolation_memory(int jobs);

// False in a build with AddressSanitizer, which reserves terabytes of address space for its
// shadow memory at start: a worker there runs without the memory limit.
bool memory_limit_enforced();

// What a worker wrote on its standard output, once it has exited with status 0; otherwise
// `failure` names the signal, the exit status or the limit that stopped it. `verb_arguments`
// follow `rotbench --plugin P ...` (every loaded plug-in): a hidden verb and its options.
// The worker runs in its own process group under the time and memory limits, and all of the
// group is killed when it ends; an interrupt kills it and sets `interrupted`.
struct WorkerOutput {
    std::string text, failure, last_error_line;  // the last line ": ..." of its standard error, if any
    bool interrupted = false;
    double cpu_seconds = NAN;   // user + system of the process and the children it waited for (wait4)
    double wall_seconds = NAN;  // from its start to its exit
    int exit_status = -1;       // its exit status when it exited (not killed, not signalled)
};
WorkerOutput run_worker(const std::vector<std::string>& verb_arguments, double seconds, std::size_t megabytes);
// The same for any program (a client's): `args` is its argument vector (the first looked up on
// PATH when it holds no '/'), started in `directory` (empty: this one); messages call it `what`.
WorkerOutput run_program(std::vector<std::string> args, const std::string& directory, double seconds, std::size_t megabytes,
                         const std::string& what);

// The run made by a worker. Never throws for the run's own failure; an interrupt (SIGINT,
// SIGTERM) kills the worker and returns an interrupted result within a tenth of a second.
RunResult run_isolated(const RunSpec& spec, const RunOptions& options, const IsolationLimits& limits);

}  // namespace rotbench
