// The granular scenes' pictures (issue 23): each scheme's curve with its ensemble band (mass
// left against time in the silo, shear stress against displacement in the box), drawn by
// gnuplot from series/curve_*.csv, and the stones themselves at a few instants
// (snapshots/*.csv), drawn here as SVG circles projected onto the x-z plane, with the walls
// (walls/*.csv) as lines.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/store/output_dir.hpp"

#include <string>
#include <vector>

namespace rotbench {

// The runs of one granular scene at one dt: writes their curves, snapshots and walls and draws
// plots/curve_SCENE_dtDT.{gp,svg} and plots/snapshot_SCENE_SCHEME_dtDT.svg; returns the
// Markdown that shows them (empty when no run recorded either).
std::string granular_pictures(const std::string& scene, double dt, const std::vector<const RunResult*>& runs, const ResultSet& set,
                              const OutputDir& dir);

// The SVG of a snapshot's rows {t, x, y, z, radius}: one panel per instant, side by side, the
// spheres seen along +y (the farthest drawn first, lighter with distance), and over them the
// walls of the same instant, rows {t, x0, z0, x1, z1} (RunResult::walls).
std::string snapshot_svg(const std::string& title, const std::vector<std::vector<double>>& rows,
                         const std::vector<std::vector<double>>& walls = {});

}  // namespace rotbench
