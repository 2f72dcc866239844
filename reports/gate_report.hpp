// What `rotbench gate` prints and writes: a readable summary, JUnit XML, gate.csv,
// summary.json (docs/gate.md gives its fields), a Markdown job summary, and GitHub Actions
// annotations. Each is a function of the gate's result alone.
#pragma once

#include "harness/gate/gate.hpp"
#include "reports/provenance.hpp"

#include <string>

namespace rotbench {

// One line per verdict (PASS, FAIL, XFAIL: an expected failure, XPASS: an unexpected pass),
// the warnings, and the counts.
std::string gate_summary(const GateResult& result);

// How each file begins: an existing file that does not is not rotbench's, and is never replaced.
inline constexpr const char* junit_signature = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"rotbench gate\"";
inline constexpr const char* summary_json_signature = "{\n  \"format\": \"rotbench-gate-summary";
inline constexpr const char* markdown_signature = "## rotbench ";
// One test case per verdict; an expected failure is <skipped> with its reason.
std::string gate_junit(const GateResult& result, const std::string& gate_file);
// scene,scheme,check,family,criterion,outcome,measured,lo,hi,bound,message
std::string gate_csv(const GateResult& result);
std::string gate_summary_json(const GateResult& result, const std::string& gate_file, const Provenance& provenance);
// For $GITHUB_STEP_SUMMARY: the counts, a table per scheme, and every failure; headed by the
// verb that judged ("gate", "compare") and what it judged against (the gate file, the baseline).
std::string gate_markdown(const GateResult& result, const std::string& verb, const std::string& against);
// "::error file=...,line=...::message" for every failure and unexpected pass, and
// "::warning ...::" for the warnings.
std::string gate_annotations(const GateResult& result);

}  // namespace rotbench
