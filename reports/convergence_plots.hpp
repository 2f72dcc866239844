// Per scene: error against dt (convergence, with reference slopes) and error against cost
// (work-precision: CPU time, force evaluations and, where the cost table counted them, the
// scheme's instructions), one line per scheme, drawn by gnuplot.
#pragma once

#include "harness/engine/run.hpp"
#include "harness/io/output_dir.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

// The error a scene's plots show: omega_err_max where the scene has a reference,
// otherwise energy_drift_max.
std::string plotted_error(const std::vector<const RunResult*>& runs);

// `bodies`: the scene's number of bodies. Writes DIR/plots/runs_<scene>.dat and the convergence and work-precision scripts and
// SVGs; returns the Markdown that shows them. `instructions`: per body-step, by scheme
// (reports/cost_table.hpp); empty, or missing a scheme, leaves that panel out.
std::string convergence_plots(const std::string& scene, std::size_t bodies, const std::vector<const RunResult*>& runs,
                              const OutputDir& dir, const std::map<std::string, double>& instructions = {});

}  // namespace rotbench
