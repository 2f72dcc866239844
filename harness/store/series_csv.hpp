// The series of runs, under DIR/series/: energy_SCENE_SCHEME_dtDT.csv (columns t, energy_error,
// then the scene's energy parts by name) or curve_SCENE_SCHEME_dtDT.csv (a granular scene's
// curve, or an ensemble's band); a member of an ensemble adds _seedS. And the granular scenes'
// snapshots: DIR/snapshots/SCENE_SCHEME_dtDT[_seedS].csv, columns t, x, y, z, radius.
#pragma once

#include "harness/core/run.hpp"
#include "harness/store/output_dir.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// A header of `columns`, then one line per row, every number in its shortest round-trip form.
std::string table_csv(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows);

// dt as it appears in file names ("{:g}").
std::string dt_tag(double dt);
// A run's series file: its name (under series/) and its text.
std::string series_file_name(const RunResult& r);
std::string series_file_name(const RunSpec& spec, bool energy);  // the name either kind would have
std::string series_csv(const RunResult& r);
void write_series_file(const RunResult& r, const OutputDir& dir);  // dir/series/NAME

// A run's snapshot file: its name (under snapshots/) and its text.
std::string snapshot_file_name(const RunSpec& spec);
inline const std::vector<std::string> snapshot_columns = {"t", "x", "y", "z", "radius"};
std::string snapshot_csv(const RunResult& r);
// Its walls at the same instants, seen along +y: the same name, under walls/.
inline const std::vector<std::string> wall_columns = {"t", "x0", "z0", "x1", "z1"};
std::string walls_csv(const RunResult& r);

// DIR/series/*.csv, DIR/snapshots/*.csv and DIR/walls/*.csv for every run that recorded
// them (a shard keeps them all for merge).
void write_run_series(const std::vector<RunResult>& results, const OutputDir& dir);

}  // namespace rotbench
