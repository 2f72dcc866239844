// ensemble.csv: every ensemble member's metrics (harness/analysis/ensemble.hpp), beside the
// results.csv that holds their means and intervals.
#pragma once

#include "harness/exec/run.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Header `scene,scheme,dt,seed,metric,value`; empty when no run belongs to an ensemble.
std::string ensemble_csv(const std::vector<RunResult>& runs);

}  // namespace rotbench
