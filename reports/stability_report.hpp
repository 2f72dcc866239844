// The stability study in Markdown, with its plots: the limits against the damping ratio and
// the spectral radius of each scheme's step map against dt.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/store/output_dir.hpp"

#include <string>
#include <vector>

namespace rotbench {

// `set` names the schemes' families for the plots' panels (its runs are not read).
// Data, gnuplot scripts and SVGs under dir/plots, and the Markdown that shows them.
std::string spectral_radius_plots(const std::vector<SpectralCurve>& curves, const ResultSet& set, const OutputDir& dir);

// stability.md's section: every row, and the limits against zeta.
std::string stability_section(const std::vector<StabilityRow>& rows, const ResultSet& set, const OutputDir& dir);

// report.md's section: per scene, measured over Peng per scheme and damping ratio (or dt w_max
// for the spin scene), and the limits against zeta.
std::string stability_summary(const std::vector<StabilityRow>& rows, const ResultSet& set, const OutputDir& dir);

}  // namespace rotbench
