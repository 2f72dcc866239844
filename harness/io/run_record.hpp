// One finished run as a self-delimiting record: the form in which the journal keeps runs and
// an isolated worker hands its run back.
//   "run INDEX R N S P W\n", R bytes of its results.csv, N of its runs.csv, S of its series
//   (0: none), P of its snapshots (0: none), W of its walls (0: none), "end INDEX\n".
// A record cut short (a kill while it was written) is not a record.
#pragma once

#include "harness/engine/run.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rotbench {

std::string run_record(std::size_t index, const RunResult& result);

struct RunRecords {
    std::vector<std::pair<std::size_t, RunResult>> runs;  // in the order found
    std::size_t whole_length = 0;                         // the bytes the whole records span
};

// The whole records at the start of `text`; reading stops at the first cut or foreign one.
// A record whose CSVs are malformed is an InputError naming `name`.
RunRecords parse_run_records(const std::string& text, const std::string& name);

}  // namespace rotbench
