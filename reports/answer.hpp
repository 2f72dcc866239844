// "The answer" (harness/analysis/answer.hpp) as answer.csv and as the report's section.
#pragma once

#include "harness/analysis/answer.hpp"

#include <string>
#include <vector>

namespace rotbench {

// answer.csv: tolerance,scene,scheme,how,dt,cpu_seconds,dt_limit,limit_from.
std::string answer_csv(const std::vector<LargestDt>& answers);

// Markdown: the first screen's table (the two ranking scenes, ranked by the geometric mean of
// their CPU times), then every scene in a collapsed section.
std::string answer_section(const ResultSet& set, const std::vector<LargestDt>& answers, const std::vector<double>& tolerances);

}  // namespace rotbench
