// Plots are drawn by gnuplot (SVG terminal) from scripts kept beside them, so a reader
// can redraw or restyle any plot. Without gnuplot the scripts and data are still written.
#pragma once

#include <filesystem>
#include <string>

namespace rotbench {

// Writes `script` to `path` (a .gp file) and runs gnuplot on it in its directory.
// Returns false when gnuplot is missing or fails; the script stays either way.
bool draw_with_gnuplot(const std::filesystem::path& path, const std::string& script);

}  // namespace rotbench
