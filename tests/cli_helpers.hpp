// Running the CLI in-process from a test: exit status, stdout and stderr as a user sees them.
#pragma once

#include "harness/cli/cli.hpp"
#include "harness/cli/config.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/parse.hpp"
#include "harness/exec/executor.hpp"
#include "harness/exec/run.hpp"
#include "removed_at_exit.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace rotbench::test {

namespace fs = std::filesystem;

struct Cli {
    int status;
    std::string out, err;
};

inline Cli cli(std::vector<std::string> args) {
    args.insert(args.begin(), "rotbench");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int status = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

// One run through the executor (in process, or a client's program), untimed and quiet.
inline RunResult made(const RunSpec& spec) {
    std::ostringstream out, err;
    Executor executor(out, err, {.run = {.measure_time = false}, .quiet = true});
    return executor.run(spec);
}

inline fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("rotbench_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

inline std::string read(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), {}};
}

// A CSV without what times a run: the rows of a timing metric (results.csv), the column of
// timing repeats (runs.csv). What two runs of one command share.
inline std::string without_timing(const std::string& csv) {
    const auto records = parse_csv(csv, "csv");
    if (records.empty()) return "";
    const auto& header = records.front().fields;
    const auto timing_column = std::find(header.begin(), header.end(), "timing") - header.begin();
    std::string out;
    for (const auto& r : records) {
        auto fields = r.fields;
        if (std::any_of(fields.begin(), fields.end(), is_timing_metric)) continue;
        if (timing_column < static_cast<std::ptrdiff_t>(fields.size()) && &r != &records.front()) fields[timing_column].clear();
        out += csv_record(fields);
    }
    return out;
}

inline bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }

// A program started with its arguments, no shell; waited for by wait_program.
inline pid_t start_program(std::vector<std::string> argv_text) {
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (auto& a : argv_text) argv.push_back(a.data());
        argv.push_back(nullptr);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    return pid;
}
// Its exit status (128 + signal if killed).
inline int wait_program(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
inline int run_program(std::vector<std::string> argv_text) { return wait_program(start_program(std::move(argv_text))); }

// The real binary run with `args` (no shell) and, besides the environment of the tests,
// `environment` ("NAME=VALUE"); its status and what it printed. The real binary holds none
// of the test-only schemes that this test program registers.
// `in_child`, when given, runs in the child before the exec (a resource limit, say).
inline Cli binary(const std::vector<std::string>& args, const std::vector<std::string>& environment = {},
                  const std::function<void()>& in_child = {}) {
    static int serial = 0;
    const fs::path base = fs::temp_directory_path() / ("rotbench_binary_" + std::to_string(::getpid()) + "_" + std::to_string(serial++));
    std::vector<std::string> argv_text = {ROTBENCH_EXE};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::fflush(nullptr);  // or the child's freopen writes out what the test had buffered
    const pid_t pid = fork();
    if (pid == 0) {
        if (!freopen((base.string() + ".out").c_str(), "w", stdout) || !freopen((base.string() + ".err").c_str(), "w", stderr)) _exit(126);
        for (const auto& e : environment) putenv(const_cast<char*>(e.c_str()));
        if (in_child) in_child();
        std::vector<char*> argv;
        for (auto& a : argv_text) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    Cli r{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), read(base.string() + ".out"), read(base.string() + ".err")};
    fs::remove(base.string() + ".out");
    fs::remove(base.string() + ".err");
    return r;
}


// The small silo of examples/small_silo.toml: the silo's machinery in seconds, for tests of
// anything but its physics; as options and as a scene's parameters (read when first asked for:
// the file names a scene, which the registry knows only once static initialisation is over).
inline const std::string small_silo_file = ROTBENCH_SOURCE_DIR "/examples/small_silo.toml";
inline const std::vector<std::string> small_silo_settings = {"--config", small_silo_file};
inline const ParamOverrides& small_silo() {
    static const ParamOverrides params = load_config(small_silo_file).params.at("silo_discharge");
    return params;
}

inline void write(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

// The default gate's [[check]] tables that judge CPU-time ratios (max_cost_ratio) alone, or
// (cost = false) everything else, its header included: ratios belong to the CI step that runs
// the whole gate, not to unit tests sharing a machine.
inline std::string default_gate_checks(bool cost) {
    const std::string text = read(DEFAULT_GATE);
    std::string kept;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t next = text.find("[[check]]", at + 1);
        const std::string part = text.substr(at, next == std::string::npos ? std::string::npos : next - at);
        const bool judges_cost = part.find("max_cost_ratio") != std::string::npos;
        if (cost ? part.rfind("[[check]]", 0) == 0 && judges_cost : !judges_cost) kept += part;
        at = next == std::string::npos ? text.size() : next;
    }
    return kept;
}

}  // namespace rotbench::test
