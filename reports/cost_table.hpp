// The report's cost table: per body-step times (Google Benchmark, batched and one body at a
// time) and instruction counts (callgrind) of every scheme, read from DIR/cost.csv, which
// benchmarks/cost.sh writes.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace rotbench {

// Markdown; says how to produce the table when DIR/cost.csv is absent.
std::string cost_section(const std::filesystem::path& dir);

// Instructions per body-step of each scheme stepping one body at a time, as every scene
// does (the work-precision plots' deterministic cost); empty when DIR/cost.csv is absent.
std::map<std::string, double> instructions_per_body_step(const std::filesystem::path& dir);

}  // namespace rotbench
