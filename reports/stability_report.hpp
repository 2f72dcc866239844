// The stability study in Markdown, with its plots: the limits against the damping ratio and
// the spectral radius of each scheme's step map against dt.
#pragma once

#include "harness/analysis/stability_study.hpp"
#include "harness/io/output_dir.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// Data, gnuplot scripts and SVGs under dir/plots, and the Markdown that shows them.
std::string spectral_radius_plots(const std::vector<SpectralCurve>& curves, const OutputDir& dir);

// The report section (Markdown), with plots drawn under dir/plots.
std::string stability_section(const std::vector<StabilityRow>& rows, const OutputDir& dir);

}  // namespace rotbench
