// The energy-against-time part of the report (the seed's Figures 8-11 counterpart): each
// run's series as CSV, one plot per scene and time step with a line per scheme, and a
// table of the final and largest energy errors with the ordering of the schemes, set
// against the ordering the seed publishes.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/store/output_dir.hpp"
#include "reports/parallel_work.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// Writes DIR/series/*.csv and DIR/plots/energy_*.{gp,svg}; returns the Markdown section
// (empty when no run recorded a series); the plots are drawn through `parallel`.
std::string energy_series_section(const ResultSet& set, const OutputDir& dir,
                                  const ParallelWork& parallel = run_serially);

}  // namespace rotbench
