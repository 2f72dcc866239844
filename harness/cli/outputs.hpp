// What several verbs share: the output directory, and the outputs of a set of runs.
#pragma once

#include "harness/engine/run.hpp"
#include "reports/executor.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

// Bounds that keep a typo from asking for a million threads or samples.
inline constexpr int max_jobs = 1024, max_series_samples = 1000000;

// The output directory of a command, made if missing. Refused before any work is done when
// it already holds `marker` (unless overwrite), holds an interrupted run, or cannot be
// written.
std::filesystem::path prepare_output(const std::string& dir, const std::string& marker, bool overwrite);

// The report's plots drawn on every core.
Executor all_cores();

// results.csv, runs.csv, orders.csv, local_orders.csv and report.md.
void write_outputs(const std::filesystem::path& dir, const std::vector<RunResult>& results,
                   const std::string& command_line, std::ostream& out);

}  // namespace rotbench
