// results.csv: tidy long format, header exactly `scene,scheme,dt,metric,value`
// (docs/outputs.md).
#pragma once

#include "harness/engine/run.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results);

// runs.csv: what results.csv does not hold, so that `rotbench report DIR` can re-render:
// header scene,scheme,kind,dt,t_end,params,metrics,timing,failure; params as
// KEY=V1 V2 ...;KEY=..., metrics the number of the run's rows in results.csv (whose rows
// follow the runs' order), timing the CPU seconds of each timing repeat. RFC 4180 quoting
// (harness/io/csv.hpp).
std::string runs_csv(const std::vector<RunResult>& results);

// Reads results.csv and runs.csv (and the series under series/, the snapshots under
// snapshots/) back. InputError when a file is missing or malformed.
std::vector<RunResult> read_results(const std::filesystem::path& dir);
// The same from the files' texts (a run journal keeps them so), `series` mapping a series or
// snapshot file's path under the directory ("series/NAME", "snapshots/NAME") to its text; `source` stands for the directory in error messages.
std::vector<RunResult> parse_results(const std::string& results_text, const std::string& runs_text,
                                     const std::map<std::string, std::string>& series, const std::string& source);

}  // namespace rotbench
