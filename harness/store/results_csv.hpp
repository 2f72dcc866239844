// results.csv: tidy long format, header exactly `scene,scheme,dt,metric,value`
// (docs/outputs.md).
#pragma once

#include "harness/core/run.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/run_record.hpp"
#include "harness/store/scheme_record.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results);

// runs.csv: what results.csv does not hold, for a reader of the CSVs:
// header scene,scheme,kind,dt,t_end,params,metrics,timing,failure; params as
// KEY=V1 V2 ...;KEY=..., metrics the number of the run's rows in results.csv (whose rows
// follow the runs' order), timing the CPU seconds of each timing repeat. RFC 4180 quoting
// (harness/store/csv.hpp).
std::string runs_csv(const std::vector<RunResult>& results);

// runs.jsonl, the run store of an output folder: one record per run as it was made (an
// ensemble's members each; harness/store/run_record.hpp), indexed from 0; a slice's runs each
// with its place in the whole plan (`places`, one per run, or none).
std::string run_store(const std::vector<RunResult>& runs, const std::vector<PlanPlace>& places = {});
// Writes runs.jsonl of `runs` and schemes.json (their schemes as registered in this process,
// else as `recorded`, harness/store/scheme_record.hpp), and results.csv and runs.csv of
// `tables`: the same runs with each ensemble's members collapsed (harness/analysis/ensemble.hpp),
// whose rows follow the order of the tables.
void write_run_files(const OutputDir& dir, const std::vector<RunResult>& runs, const std::vector<RunResult>& tables,
                     const SchemeInfos& recorded = {}, const std::vector<PlanPlace>& places = {});

// Reads a folder's runs back from its store (`store`: runs.jsonl, or the stability study's), as they
// were made (an ensemble's members each). InputError when the store is missing, cut, or not
// rotbench's (an id that is not one, a step out of range); `name` stands for the file in messages.
std::vector<RunResult> read_results(const std::filesystem::path& dir, const std::string& store = "runs.jsonl");
std::vector<RunResult> parse_run_store(const std::string& text, const std::string& name);
// The same, with each run's place in the plan (none outside a slice).
struct StoredRuns {
    std::vector<RunResult> runs;
    std::vector<std::optional<PlanPlace>> places;
};
StoredRuns read_run_store(const std::filesystem::path& dir, const std::string& store = "runs.jsonl");

}  // namespace rotbench
