// report.md: what was run, a table per scene, the seed's Table 1 side by side with the
// computed values, and the readings of the seed's equations.
#pragma once

#include "harness/run.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// Also writes the files the report links to (series, plots) under `dir`.
std::string markdown_report(const std::vector<RunResult>& results, const std::string& command_line,
                            const std::filesystem::path& dir);

}  // namespace rotbench
