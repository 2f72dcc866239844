// report.md: what was run, a table per scene, the seed's Table 1 side by side with the
// computed values, and the readings of the seed's equations.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/io/output_dir.hpp"
#include "reports/executor.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// Also writes the files the report links to (series, plots) under `dir`; the plots are drawn
// through `executor`.
std::string markdown_report(const ResultSet& set, const std::string& command_line, const OutputDir& dir,
                            const Executor& executor = run_serially);

}  // namespace rotbench
