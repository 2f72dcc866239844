// What `rotbench advise` prints and writes: a table, best first, and advice.json.
#pragma once

#include "harness/analysis/advice.hpp"

#include <string>

namespace rotbench {

std::string advice_table(const Advice& advice);

// {"particle": {...}, "tolerance", "t_end", "contact_period", "dt_peng",
//  "recommendations": [{"scheme", "dt", "dt_stability", "predicted_error", "how", "ns_per_step",
//  "cpu_seconds", "verified_error", "verified_stable"}, ...], "not_recommended": [{"scheme", "why"}]}.
// cpu_seconds is per simulated second; the verified fields are null without --verify, and
// an infinite stability limit (none found) is null too.
std::string advice_json(const Advice& advice);

}  // namespace rotbench
