// The report's table of the granular step beside LIGGGHTS's: CPU seconds per sphere-step of each
// code on one silo, filling and discharge apart, read from DIR/granular_speed.csv, which
// benchmarks/granular_speed.py writes.
#pragma once

#include <filesystem>
#include <string>

namespace rotbench {

// Markdown; empty when DIR holds no granular_speed.csv (the measurement is optional).
std::string granular_speed_section(const std::filesystem::path& dir);

}  // namespace rotbench
