// report.md: the verdicts and the answer first, then the stability limits, the cost, a
// section per scene, the seed's Table 1 side by side with the computed values, and the
// readings of the seed's equations. Formatting only: every figure comes from the Analysis.
#pragma once

#include "harness/analysis/analysis.hpp"
#include "harness/store/output_dir.hpp"
#include "reports/parallel_work.hpp"

#include <string>

namespace rotbench {

// Draws the plots the report links to under `dir`, through `parallel`.
std::string markdown_report(const Analysis& analysis, const std::string& command_line, const OutputDir& dir,
                            const ParallelWork& parallel = run_serially);

}  // namespace rotbench
