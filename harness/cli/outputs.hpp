// What several verbs share: the output directory, and the outputs of a set of runs.
#pragma once

#include "harness/exec/run.hpp"
#include "harness/store/output_dir.hpp"
#include "reports/parallel_work.hpp"
#include "reports/markdown_report.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

// Bounds that keep a typo from asking for a million threads or samples.
inline constexpr int max_jobs = 1024, max_series_samples = 1000000;

// The files `rotbench run` writes whose names are known before it starts.
inline const std::vector<std::string> run_files = {"runs.jsonl", "schemes.json", "results.csv", "runs.csv", "orders.csv",
                                                   "local_orders.csv", "answer.csv", "ensemble.csv", "report.md"};

// The report's plots drawn on every core.
ParallelWork all_cores();

// --tolerance (repeatable): the report's tolerances on the relative angular-velocity error.
void add_tolerance_option(CLI::App& command, std::vector<std::string>& texts);
// Each in (0, 1) (InputError otherwise); the defaults when none is given.
std::vector<double> parse_tolerances(const std::vector<std::string>& texts);

// The analysis's options: the tolerances, the cost tables in `run_dir` (benchmarks/cost.py and
// granular_speed.py write them beside a run) and the stability study in `stability_dir` when it
// holds its store.
AnalysisOptions analysis_options(const std::vector<std::string>& tolerances, const std::filesystem::path& run_dir,
                                 const std::filesystem::path& stability_dir);

// The run files (harness/store/output_files.hpp), the analysis's (export_analysis) and report.md;
// the schemes not registered in this process described as `recorded` (earlier commands' schemes.json).
void write_outputs(const OutputDir& dir, const std::vector<RunResult>& results, const std::string& command_line,
                   const AnalysisOptions& options, std::ostream& out, const SchemeInfos& recorded = {});

}  // namespace rotbench
