// `rotbench run` and `rotbench merge`: the sweep from the options, its outputs, and the
// journal that lets an interrupted run be resumed (harness/journal.hpp).
#pragma once

#include "harness/run.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

// Bounds that keep a typo from asking for a million threads or samples.
inline constexpr int max_jobs = 1024, max_series_samples = 1000000;

struct RunOptionsText {
    std::string scenes, schemes, dts, t_end, config, shard, resume, out = "rotbench-out";
    std::vector<std::string> settings;
    int energy_series = 400;
    int jobs = default_jobs();
    bool overwrite = false, quick = false;
    static int default_jobs();
};

void add_run_options(CLI::App& command, RunOptionsText& options);

// The output directory of a command, made if missing. Refused before any work is done when
// it already holds `marker` (unless overwrite), holds an interrupted run, or cannot be
// written.
std::filesystem::path prepare_output(const std::string& dir, const std::string& marker, bool overwrite);

// results.csv, runs.csv, orders.csv, local_orders.csv and report.md.
void write_outputs(const std::filesystem::path& dir, const std::vector<RunResult>& results,
                   const std::string& command_line, std::ostream& out);

// `rotbench run`. `arguments` are the command's (saved for --resume); `resuming` is the
// directory of the interrupted run being finished. Returns the exit status: 0, or 128 +
// the signal when SIGINT or SIGTERM cut the sweep short (the finished runs are kept).
int run_command(const RunOptionsText& options, const std::vector<std::string>& arguments,
                const std::string& command_line, std::ostream& out, std::ostream& err,
                const std::optional<std::filesystem::path>& resuming);

}  // namespace rotbench
