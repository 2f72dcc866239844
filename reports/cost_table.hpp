// The report's cost table: per body-step times (Google Benchmark, batched and one body at a
// time) and instruction counts (callgrind) of every scheme (harness/analysis/cost_tables.hpp).
#pragma once

#include "harness/analysis/cost_tables.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace rotbench {

// The heading of its section.
inline const std::string cost_heading = "Cost: the batched benchmark and instruction counts";

// Markdown; says how to produce the table in `dir` when there is none.
std::string cost_section(const std::optional<CostTable>& table, const std::filesystem::path& dir);

}  // namespace rotbench
