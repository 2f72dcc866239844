// The report's table of the granular step beside LIGGGHTS's: CPU seconds per sphere-step of each
// code on one silo, filling and discharge apart (harness/analysis/cost_tables.hpp).
#pragma once

#include "harness/analysis/cost_tables.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Markdown; empty without rows (the measurement is optional).
std::string granular_speed_section(const std::vector<GranularSpeedRow>& rows);

}  // namespace rotbench
