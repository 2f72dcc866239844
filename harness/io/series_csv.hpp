// Energy series of runs: DIR/series/energy_SCENE_SCHEME_dtDT.csv, columns t, energy_error,
// then the scene's energy parts by name.
#pragma once

#include "harness/engine/run.hpp"
#include "harness/io/output_dir.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// dt as it appears in file names ("{:g}").
std::string dt_tag(double dt);
// A run's series file: its name (under series/) and its text.
std::string series_file_name(const RunResult& r);
std::string series_csv(const RunResult& r);
void write_series_file(const RunResult& r, const OutputDir& dir);  // dir/series/NAME

// DIR/series/*.csv for every run that recorded a series (a shard keeps them all for merge).
void write_energy_series(const std::vector<RunResult>& results, const OutputDir& dir);

}  // namespace rotbench
