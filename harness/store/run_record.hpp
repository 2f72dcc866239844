// The run store's record: one finished run, whole and lossless, as one line of JSON (JSON
// Lines). It is the form in which the journal keeps runs and an isolated worker hands its run
// back; every CSV of a run is an export of these records, never read back inside the run.
//   {"index": I, "plan": {...}, "run": {"spec": {...}, "metrics": [[name, value], ...], "failure": "...",
//    "series_columns": [...], "series": [[...], ...], "snapshots": [...], "walls": [...],
//    "timing_samples": [...]}}
// A number that is not finite is written as the string "nan", "inf" or "-inf" (JSON has none);
// every other one in the shortest form that reads back to the same double. "plan" is there only
// in a slice of a sharded command (PlanPlace). docs/outputs.md.
#pragma once

#include "harness/core/run.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotbench {

// Where a run of `rotbench run --shard K/N` stands in the whole plan, so that `merge` puts the
// slices back in plan order. Counts as read: merge checks them before it trusts them.
struct PlanPlace {
    std::string plan_id;  // the whole plan's fingerprint (harness/store/shard.hpp)
    std::uint64_t shard = 0, shards = 0, plan_size = 0, plan_index = 0;
};

// The record of run `index`, ending with its line break.
std::string run_record(std::size_t index, const RunResult& result, const std::optional<PlanPlace>& place = {});

struct RunRecords {
    std::vector<std::pair<std::size_t, RunResult>> runs;  // in the order found
    std::vector<std::optional<PlanPlace>> places;         // each run's, when its record has one
    std::size_t whole_length = 0;                         // the bytes the whole records span
};

// The whole records at the start of `in`, read line by line (a store or journal of any size);
// reading stops at the first line that is cut (no line break: a kill while it was written) or
// is not a record. A line that is JSON of the record's shape but holds a wrong value (an
// unknown kind, a metric that is not a number) is an InputError naming `name`.
RunRecords parse_run_records(std::istream& in, const std::string& name);
RunRecords parse_run_records(const std::string& text, const std::string& name);

// A run's spec alone, as one line without a line break (the worker's --spec), and back.
std::string spec_record(const RunSpec& spec);
RunSpec parse_spec_record(const std::string& text, const std::string& name);

}  // namespace rotbench
