// "The answer" (harness/analysis/answer.hpp) as the report's section.
#pragma once

#include "harness/analysis/answer.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Markdown: the first screen's table (the two ranking scenes, ranked by the geometric mean of
// their CPU times); and, further down the report, every scene in a collapsed section.
std::string answer_section(const ResultSet& set, const std::vector<LargestDt>& answers, const std::vector<double>& tolerances);
inline const std::string answer_details_heading = "The answer on every scene";
std::string answer_details_section(const std::vector<LargestDt>& answers, const std::vector<double>& tolerances);

}  // namespace rotbench
