// Per scene: error against dt (convergence, with reference slopes) and error against cost
// (work-precision: CPU time and force evaluations), one line per scheme, drawn by gnuplot.
#pragma once

#include "harness/run.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// The error a scene's plots show: omega_err_max where the scene has a reference,
// otherwise energy_drift_max.
std::string plotted_error(const std::vector<const RunResult*>& runs);

// Writes DIR/plots/runs_<scene>.dat and the convergence and work-precision scripts and
// SVGs; returns the Markdown that shows them.
std::string convergence_plots(const std::string& scene, const std::vector<const RunResult*>& runs,
                              const std::filesystem::path& dir);

}  // namespace rotbench
