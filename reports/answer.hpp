// "The answer" (harness/analysis/answer.hpp) as answer.csv and as the report's section.
#pragma once

#include "harness/analysis/answer.hpp"

#include <string>
#include <vector>

namespace rotbench {

// answer.csv: tolerance,scene,scheme,how,dt,cpu_seconds,dt_limit,limit_from.
std::string answer_csv(const std::vector<LargestDt>& answers);

// Markdown: the first screen's table (the two ranking scenes, ranked by the geometric mean of
// their CPU times); and, further down the report, every scene in a collapsed section.
std::string answer_section(const ResultSet& set, const std::vector<LargestDt>& answers, const std::vector<double>& tolerances);
inline const std::string answer_details_heading = "The answer on every scene";
std::string answer_details_section(const std::vector<LargestDt>& answers, const std::vector<double>& tolerances);

}  // namespace rotbench
