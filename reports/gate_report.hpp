// What `rotbench gate` prints and writes: a readable summary, JUnit XML (one test case per
// check and scheme) and gate.csv.
#pragma once

#include "harness/gate/gate.hpp"

#include <string>
#include <vector>

namespace rotbench {

std::string gate_summary(const std::vector<GateCheck>& checks, const GateResult& result);
std::string gate_junit(const std::vector<GateCheck>& checks, const GateResult& result);
// scene,scheme,check,criterion,metric,bound,measured,passed,detail
std::string gate_csv(const std::vector<GateCheck>& checks, const GateResult& result);

}  // namespace rotbench
