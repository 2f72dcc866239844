// The report's cost table: per body-step times (Google Benchmark, batched and one body at a
// time) and instruction counts (callgrind) of every scheme, read from DIR/cost.csv, which
// benchmarks/cost.py writes.
#pragma once

#include <filesystem>
#include <string>

namespace rotbench {

// The heading of its section.
inline const std::string cost_heading = "Cost: the batched benchmark and instruction counts";

// Markdown; says how to produce the table when DIR/cost.csv is absent.
std::string cost_section(const std::filesystem::path& dir);

}  // namespace rotbench
