// The report's section on the granular scenes (silo_discharge, direct_shear): each metric per
// scheme with its ensemble interval, each scheme's difference from the seed's reference scheme
// with its paired interval and whether it exceeds the scatter, the cost of a whole DEM step and
// the rotation's share of it, beside seed Tables 4 and 5; then the pictures.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/store/output_dir.hpp"

#include <string>

namespace rotbench {

inline const std::string granular_heading = "Granular scenes: schemes against the scatter of an ensemble";

// Empty when no run is of a granular scene. Writes the runs' curves, snapshots and their
// pictures under `dir` (reports/granular_pictures.hpp).
std::string granular_section(const ResultSet& set, const OutputDir& dir);

}  // namespace rotbench
