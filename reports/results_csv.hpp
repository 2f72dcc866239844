// results.csv: tidy long format, header exactly `scene,scheme,dt,metric,value`
// (DESIGN.md "Output contract").
#pragma once

#include "harness/run.hpp"

#include <string>
#include <vector>

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results);

}  // namespace rotbench
