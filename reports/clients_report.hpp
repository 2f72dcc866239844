// The report's section on clients (docs/clients.md): per client with a counterpart and per scene,
// its largest difference from the built-in scheme it should equal over every step of its runs
// (harness/analysis/scheme_verdicts.hpp judges whether it is the same map).
#pragma once

#include "harness/analysis/scheme_verdicts.hpp"

#include <string>

namespace rotbench {

inline const std::string clients_heading = "Real clients: codes run as shipped, against their counterparts";

// Empty when no client with a counterpart has runs in the set.
std::string clients_section(const std::vector<CounterpartVerdict>& verdicts);

}  // namespace rotbench
