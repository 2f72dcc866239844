// What several verbs share: the output directory, and the outputs of a set of runs.
#pragma once

#include "harness/engine/run.hpp"
#include "harness/io/output_dir.hpp"
#include "reports/executor.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

// Bounds that keep a typo from asking for a million threads or samples.
inline constexpr int max_jobs = 1024, max_series_samples = 1000000;

// The files `rotbench run` writes whose names are known before it starts.
inline const std::vector<std::string> run_files = {"results.csv", "runs.csv", "orders.csv", "local_orders.csv", "report.md"};

// The report's plots drawn on every core.
Executor all_cores();

// results.csv, runs.csv, orders.csv, local_orders.csv and report.md.
void write_outputs(const OutputDir& dir, const std::vector<RunResult>& results,
                   const std::string& command_line, std::ostream& out);

}  // namespace rotbench
