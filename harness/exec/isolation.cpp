#include "harness/exec/isolation.hpp"

#include "harness/store/parse.hpp"

#include "harness/exec/interrupt.hpp"
#include "harness/exec/machine.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/program_path.hpp"
#include "harness/store/run_record.hpp"
#include "harness/scenes/scene.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <pthread.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <string_view>
#include <unistd.h>

namespace rotbench {
namespace {

std::string& worker() {
    static std::string path;
    return path;
}

// Ten minutes for a stability search, an amplification limit or a spectral curve; otherwise
// the time limit of its body-steps (each way of a reversal, both stretches of a horizon run).
double default_timeout(const RunSpec& spec, const Scene& scene) {
    if (finds_its_own_dt(spec.kind)) return 600.0;
    const double body_steps = static_cast<double>(step_count(scene.t_end(), spec.dt)) * static_cast<double>(scene.initial_state().size());
    const double ways = spec.kind == RunKind::reversal  ? 2.0
                        : spec.kind == RunKind::horizon ? 1.0 + energy_horizon
                        : spec.kind == RunKind::cost    ? 2.0 * (cost_pairs + 1)
                                                        : 1.0;
    return steps_timeout(body_steps * ways);
}

// A run's record is a few kB (its energy series included); a worker that writes more is broken.
constexpr std::size_t max_worker_output = std::size_t(64) << 20;

// What a non-blocking pipe holds now; false once it is at its end.
bool drain(int fd, std::string& into, std::size_t keep) {
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK;
        if (n == 0) return false;
        into.append(buffer, static_cast<std::size_t>(n));
        if (keep && into.size() > keep) into.erase(0, into.size() - keep);
    }
}

}  // namespace

double steps_timeout(double body_steps) { return 60.0 + 10.0 * 1e-5 * body_steps; }

void set_worker_executable(std::string path) { worker() = std::move(path); }
const std::string& worker_executable() { return worker(); }

bool isolated(const std::string& scheme) { return !worker().empty() && plugin_of(scheme) != nullptr; }


bool memory_limit_enforced() {
#if defined(__SANITIZE_ADDRESS__)
    return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return false;
#endif
#endif
    return true;
}

std::size_t isolation_memory(int jobs) {
    return static_cast<std::size_t>(std::max(1024.0, memory_bytes() / 2 / std::max(1, jobs) / (1 << 20)));
}

WorkerOutput run_worker(const std::vector<std::string>& verb_arguments, double seconds, std::size_t megabytes) {
    std::vector<std::string> args = {worker()};
    for (const auto& p : loaded_plugins()) args.insert(args.end(), {"--plugin", p.path});
    args.insert(args.end(), verb_arguments.begin(), verb_arguments.end());
    return run_program(args, "", seconds, megabytes, "worker");
}

namespace {

// A started program: its pid, which leads its own process group, the read ends of its standard
// output and error, and the mark its environment carries to every descendant (run_mark_variable).
struct Child {
    pid_t pid = -1;
    int out = -1, err = -1;
    std::string mark;
};

// ROTBENCH_RUN=<rotbench's pid>-<a count>, set in a started program's environment, which its
// descendants inherit: one that leaves the program's process group (setsid, setpgid, as MPI
// launchers and daemons do) is still found by it when the run ends, and killed.
constexpr const char* run_mark_variable = "ROTBENCH_RUN";
std::atomic<unsigned long> runs_started{0};

// The environment a program starts with: rotbench's, with the run's mark.
std::vector<std::string> marked_environment(const std::string& mark) {
    std::vector<std::string> env;
    const std::string prefix = std::string(run_mark_variable) + "=";
    for (char** e = environ; e && *e; ++e)
        if (std::string_view(*e).rfind(prefix, 0) != 0) env.emplace_back(*e);
    env.push_back(prefix + mark);
    return env;
}

// Kills every process of this user whose environment carries `mark`: what a program left behind
// outside its group. Scanned again after each kill, since one may fork while the others die; a
// zombie's environment reads empty, so the dead are not found twice.
void kill_marked(const std::string& mark) {
    const std::string needle = std::string(run_mark_variable) + "=" + mark;
    for (int round = 0; round < 16; ++round) {
        std::vector<pid_t> found;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
            const std::string name = entry.path().filename().string();
            if (name.empty() || !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isdigit(c); })) continue;
            const auto environment = read_file(entry.path() / "environ");
            if (!environment) continue;  // gone, or another user's
            for (std::size_t begin = 0; begin < environment->size();) {
                const std::size_t end = std::min(environment->find('\0', begin), environment->size());
                if (environment->compare(begin, end - begin, needle) == 0) {
                    found.push_back(static_cast<pid_t>(std::stol(name)));
                    break;
                }
                begin = end + 1;
            }
        }
        if (found.empty()) return;
        for (pid_t pid : found) ::kill(pid, SIGKILL);
    }
}

// The null-terminated array of C strings execve takes, pointing into `strings`.
std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> pointers;
    for (auto& text : strings) pointers.push_back(text.data());
    pointers.push_back(nullptr);
    return pointers;
}

// args.front() as execv needs it: looked up on PATH here, as execvp would, or a relative path made
// absolute (it is the caller's, not the folder the child starts in). Why not, or "".
std::string resolve_program(std::vector<std::string>& args, const std::string& what) {
    if (args.empty() || args.front().empty()) return "no program to start";
    if (args.front().find('/') == std::string::npos) {
        const std::string found = find_on_path(args.front());
        if (found.empty()) return "its " + what + " '" + args.front() + "' is not found on PATH";
        args.front() = found;
    } else {
        args.front() = std::filesystem::absolute(args.front()).string();
    }
    return "";
}

// Forks and execs args in `directory` (none: here) with its address space limited to
// `megabytes`, in a process group of its own that a signal to rotbench kills (list_child_group).
// Why it could not start, or "" with `child` set.
std::string start_child(std::vector<std::string>& args, const std::string& directory, std::size_t megabytes, const std::string& what,
                        Child& child) {
    // Everything the child needs is built before fork: after it, only chdir and exec.
    const std::string mark = fmt::format("{}-{}", ::getpid(), runs_started++);
    std::vector<std::string> environment = marked_environment(mark);
    const std::vector<char*> argv = c_strings(args), envp = c_strings(environment);
    // started: closed by a successful exec (close-on-exec), or given the errno of the chdir or the
    // exec that failed, so that the reason is said rather than an exit status.
    int out[2], err[2], started[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return "could not start its " + what + ": " + std::strerror(errno);
    if (::pipe2(err, O_CLOEXEC) != 0) {
        ::close(out[0]), ::close(out[1]);
        return "could not start its " + what + ": " + std::strerror(errno);
    }
    if (::pipe2(started, O_CLOEXEC) != 0) {
        ::close(out[0]), ::close(out[1]), ::close(err[0]), ::close(err[1]);
        return "could not start its " + what + ": " + std::strerror(errno);
    }
    const rlim_t address_space = static_cast<rlim_t>(megabytes) << 20;
    const bool limit_memory = memory_limit_enforced();
    // A signal between the fork and the group's listing would miss the child: held off until it
    // is listed; and a rotbench that dies all the same (another thread took the signal) takes
    // the child along.
    sigset_t ending, before;
    sigemptyset(&ending);
    sigaddset(&ending, SIGINT);
    sigaddset(&ending, SIGTERM);
    sigaddset(&ending, SIGHUP);
    ::pthread_sigmask(SIG_BLOCK, &ending, &before);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid > 0) {
        ::setpgid(pid, pid);  // as the child does: whichever runs first, the group exists before a kill
        list_child_group(pid);
    }
    if (pid != 0) ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
    if (pid == 0) {
        ::sigprocmask(SIG_SETMASK, &before, nullptr);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) ::_exit(127);  // rotbench died before the line above
        const rlimit limit{address_space, address_space};
        if (limit_memory) ::setrlimit(RLIMIT_AS, &limit);
        ::dup2(out[1], 1);
        ::dup2(err[1], 2);
        ::setpgid(0, 0);  // its own group: the terminal's Ctrl-C reaches the parent, which stops it
        const auto report = [&](int stage) {
            const int failed[2] = {stage, errno};
            [[maybe_unused]] const auto n = ::write(started[1], failed, sizeof failed);
            ::_exit(127);
        };
        if (!directory.empty() && ::chdir(directory.c_str()) != 0) report(0);
        ::execve(argv[0], argv.data(), envp.data());
        report(1);
    }
    ::close(out[1]);
    ::close(err[1]);
    ::close(started[1]);
    if (pid < 0) {
        ::close(out[0]), ::close(err[0]), ::close(started[0]);
        return "could not start its " + what + ": " + std::strerror(errno);
    }
    int failed[2] = {0, 0};
    ssize_t got;
    while ((got = ::read(started[0], failed, sizeof failed)) < 0 && errno == EINTR) {
    }
    ::close(started[0]);
    if (got == static_cast<ssize_t>(sizeof failed)) {  // it never ran: reaped here, said why
        ::kill(-pid, SIGKILL);
        release_child_group(pid);
        ::close(out[0]), ::close(err[0]);
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        return failed[0] == 0 ? fmt::format("could not enter the folder {} for its {}: {}", directory, what, std::strerror(failed[1]))
                              : fmt::format("could not start its {} '{}': {}", what, args.front(), std::strerror(failed[1]));
    }
    child = {pid, out[0], err[0], mark};
    return "";
}

enum class Watched { ended, timed_out, interrupted, too_much };

// Reads the child's output into `text` (and the last 4 kB of its errors into `errors`) until
// both pipes end or it has exited (a process it started may hold them), it runs past `seconds`,
// a signal asks rotbench to stop, or it writes too much. Closes the pipes; kills nothing.
Watched watch_child(const Child& child, double seconds, std::string& text, std::string& errors) {
    ::fcntl(child.out, F_SETFL, O_NONBLOCK);
    ::fcntl(child.err, F_SETFL, O_NONBLOCK);
    const auto start = std::chrono::steady_clock::now();
    Watched how = Watched::ended;
    bool exited = false;
    pollfd fds[2] = {{child.out, POLLIN, 0}, {child.err, POLLIN, 0}};
    for (int open_fds = 2; open_fds > 0 && !exited;) {
        if (interrupt_signal()) {
            how = Watched::interrupted;
            break;
        }
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) {
            how = Watched::timed_out;
            break;
        }
        const int ready = ::poll(fds, 2, 100);  // a tenth of a second: signals and limits are looked at that often
        siginfo_t info{};  // WNOWAIT: seen to have exited, not reaped, so its pid stays its own
        exited = ::waitid(P_PID, static_cast<id_t>(child.pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == child.pid;
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || (!exited && !(ready > 0 && (fds[k].revents & (POLLIN | POLLHUP | POLLERR))))) continue;
            if (!drain(fds[k].fd, k == 0 ? text : errors, k == 0 ? 0 : 4096)) {
                ::close(fds[k].fd);
                fds[k].fd = -1;
                --open_fds;
            }
        }
        if (text.size() > max_worker_output) {
            how = Watched::too_much;
            break;
        }
    }
    for (auto& f : fds)
        if (f.fd >= 0) ::close(f.fd);
    return how;
}

}  // namespace

WorkerOutput run_program(std::vector<std::string> args, const std::string& directory, double seconds, std::size_t megabytes,
                         const std::string& what) {
    WorkerOutput result;
    const auto fail = [&](const std::string& why) {
        result.failure = why;
        return result;
    };
    Child child;
    if (std::string why = resolve_program(args, what); !why.empty()) return fail(why);
    if (std::string why = start_child(args, directory, megabytes, what, child); !why.empty()) return fail(why);
    const auto start = std::chrono::steady_clock::now();
    std::string errors;
    const Watched watched = watch_child(child, seconds, result.text, errors);
    // The child's whole process group: it, and anything it started, whether it has exited or
    // not. Its pid is not free for reuse until it is reaped below, so no other group is hit.
    ::kill(-child.pid, SIGKILL);
    release_child_group(child.pid);  // killed: a signal now need not
    int status = 0;
    rusage usage{};
    while (::wait4(child.pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    kill_marked(child.mark);  // and what left the group
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    if (WIFEXITED(status)) result.exit_status = WEXITSTATUS(status);
    if (const auto end = errors.find_last_not_of("\n"); end != std::string::npos) {
        const auto line_break = errors.rfind('\n', end);
        const std::size_t begin = line_break == std::string::npos ? 0 : line_break + 1;
        result.last_error_line = ": " + errors.substr(begin, end - begin + 1);
    }
    switch (watched) {
        case Watched::interrupted: result.interrupted = true; return result;
        case Watched::timed_out:
            return fail(fmt::format("exceeded the run time limit of {:g} s (--run-timeout); its {} was killed", seconds, what));
        case Watched::too_much:
            return fail(fmt::format("its {} wrote more than {} MB on its standard output; it was killed", what, max_worker_output >> 20));
        case Watched::ended: break;
    }
    if (WIFSIGNALED(status))
        return fail(fmt::format("crashed: signal {} ({}) in its {} process", WTERMSIG(status), ::strsignal(WTERMSIG(status)), what));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return fail(fmt::format("its {} exited with status {} without a result{}", what, WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                result.last_error_line));
    return result;
}

RunResult run_isolated(const RunSpec& spec, const RunOptions& options, const IsolationLimits& limits) {
    RunResult failed{spec, {}, {}};
    const auto fail = [&](const std::string& why) {
        failed.failure = why;
        failed.metrics = {{metric::unstable, 1.0}};
        return failed;
    };
    const auto scene = scene_of(spec);
    const double seconds = limits.seconds > 0 ? limits.seconds : default_timeout(spec, *scene);
    const std::size_t megabytes = limits.megabytes > 0 ? limits.megabytes : isolation_memory(1);
    std::vector<std::string> args = {"__run", "--spec", spec_record(spec), "--series", std::to_string(options.series_samples)};
    if (!options.measure_time || !spec.timed) args.push_back("--untimed");
    const WorkerOutput worker = run_worker(args, seconds, megabytes);
    if (worker.interrupted) {
        failed.interrupted = true;
        return failed;
    }
    if (!worker.failure.empty()) return fail(worker.failure);
    const std::string& text = worker.text;
    const std::string& last_line = worker.last_error_line;
    RunRecords records;
    try {
        records = parse_run_records(text, "the worker's output");
    } catch (const InputError& e) {
        return fail(std::string("its worker's output was not a run: ") + e.what());
    }
    if (records.runs.size() != 1 || records.whole_length != text.size())
        return fail("its worker's output was not one whole run" + last_line);
    RunResult result = std::move(records.runs.front().second);
    RunSpec made = spec;
    made.t_end = scene->t_end();  // every kind of run records the scene's duration, as in process
    if (result.spec != made) return fail("its worker's output was the record of another run" + last_line);
    if (memory_limit_enforced() && result.failure.find("bad_alloc") != std::string::npos)
        result.failure += fmt::format(" (its worker's memory is limited to {} MB, --run-memory)", megabytes);
    return result;
}

}  // namespace rotbench
