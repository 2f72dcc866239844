// The energy-against-time part of the report (the seed's Figures 8-11 counterpart): each
// run's series as CSV, one plot per scene and time step with a line per scheme, and a
// table of the final and largest energy errors with the ordering of the schemes, set
// against the ordering the seed publishes.
#pragma once

#include "harness/run.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// Writes DIR/series/*.csv and DIR/plots/energy_*.{gp,svg}; returns the Markdown section
// (empty when no run recorded a series).
std::string energy_series_section(const std::vector<RunResult>& results, const std::filesystem::path& dir);

// A run's series file: its name (energy_SCENE_SCHEME_dtDT.csv, under series/) and its text.
std::string series_file_name(const RunResult& r);
std::string series_csv(const RunResult& r);

// DIR/series/*.csv for every run that recorded a series (a shard keeps them all for merge).
void write_energy_series(const std::vector<RunResult>& results, const std::filesystem::path& dir);

}  // namespace rotbench
