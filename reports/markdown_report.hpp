// report.md: the verdicts and the answer first, then the stability limits, the cost, a
// section per scene, the seed's Table 1 side by side with the computed values, and the
// readings of the seed's equations.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/store/output_dir.hpp"
#include "reports/answer.hpp"
#include "reports/parallel_work.hpp"

#include <string>
#include <vector>

namespace rotbench {

struct ReportOptions {
    std::vector<double> tolerances = default_tolerances;  // relative angular-velocity errors
    std::vector<StabilityRow> stability;                  // the stability study's rows; empty without one
};

// Also writes the files the report links to (answer.csv, series, plots) under `dir`; the
// plots are drawn through `parallel`.
std::string markdown_report(const ResultSet& set, const std::string& command_line, const OutputDir& dir,
                            const ReportOptions& options = {}, const ParallelWork& parallel = run_serially);

}  // namespace rotbench
