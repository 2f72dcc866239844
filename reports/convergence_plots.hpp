// Per scene: error against dt (convergence, with reference slopes) and error against the CPU
// time of the run (work-precision), the schemes in panels by family (reports/panels.hpp),
// drawn by gnuplot.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/store/output_dir.hpp"

#include <string>
#include <vector>

namespace rotbench {

// The error a scene's plots show: omega_err_max where the scene has a reference,
// otherwise energy_drift_max.
std::string plotted_error(const std::vector<const RunResult*>& runs);

// Its axis label, with the unit.
std::string error_label(const std::string& metric);

// Writes DIR/plots/runs_<scene>.dat and the convergence and work-precision scripts and SVGs;
// returns the Markdown that shows them. `best`: one scheme per family, for the overview panel.
std::string convergence_plots(const std::string& scene, const std::vector<const RunResult*>& runs, const ResultSet& set,
                              const OutputDir& dir, const std::vector<std::string>& best);

}  // namespace rotbench
