// Plots are drawn by gnuplot (SVG terminal) from scripts kept beside them, so that a reader
// can redraw or restyle any plot. gnuplot is started with an argument vector, never through
// a shell, so any path works; it writes to a temporary name that is renamed once the SVG is
// whole, so a full disk or a kill never leaves half a plot.
#pragma once

#include "harness/store/output_dir.hpp"

#include <string>

namespace rotbench {

// The line a script sets its output with: `out` when rotbench passes one (gnuplot -e), the
// SVG's own name when a reader runs the script.
std::string gnuplot_output(const std::string& svg_name);

struct Drawn {
    bool ok = false;
    std::string why;  // when not: "gnuplot is not installed" or what failed
};

// Writes `script` to dir/relative_script and runs gnuplot on it in that script's folder, the
// SVG going to dir/relative_svg. Without gnuplot the script (and its data) stays.
Drawn draw_with_gnuplot(const OutputDir& dir, const std::string& relative_script, const std::string& script,
                        const std::string& relative_svg);

}  // namespace rotbench
