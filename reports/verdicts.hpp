// The verdict table (one row per scheme, what it claims against what the runs show) and the
// recommendation drawn from it: formatting of harness/analysis/scheme_verdicts.hpp.
#pragma once

#include "harness/analysis/scheme_verdicts.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Markdown: the table and how each column is read.
std::string verdict_section(const ResultSet& set, const std::vector<SchemeVerdict>& verdicts, bool has_stability);

// Markdown: a few sentences on which schemes to use and to avoid and why, Peng's step under
// damping, and where to ask for one's own particle.
std::string recommendation_section(const SchemeChoice& rec, const std::vector<SchemeVerdict>& verdicts);

}  // namespace rotbench
