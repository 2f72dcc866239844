// `rotbench gate`: a gate file (harness/gate/gate_file.hpp) turned into a plan of runs, which
// the one sweep engine makes, and the verdicts judged from the results by pure functions
// (harness/gate/judge.hpp).
#pragma once

#include "harness/exec/run.hpp"
#include "harness/gate/gate_file.hpp"
#include "harness/store/scheme_record.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace rotbench {

// One check of one scheme on one scene, and the runs it reads.
struct GateCase {
    std::string id;         // a claim id (order_without_torque, ...) or the [[check]]'s name
    std::string family;     // "claim", "sanity" (a scheme that claims nothing), "check" or "baseline"
    std::string criterion;  // the claim id, or the check's criterion
    std::string scene, scheme;
    std::vector<std::size_t> runs;  // indices into GatePlan::runs, in the order the judge reads them
    std::size_t check = std::numeric_limits<std::size_t>::max();  // index of the [[check]], for "check"
    int claimed_order = 0;                                        // order claims
    std::string location;                                         // file:line it comes from
    bool expected_to_fail = false;
    std::string expected_reason;
};

struct GatePlan {
    std::vector<RunSpec> runs;  // each distinct run once
    std::vector<GateCase> cases;
    std::vector<std::string> warnings;  // e.g. a scheme that claims nothing
};

// InputError when the file asks for something the registries cannot give. `quick`: each ladder
// that a claim or check leaves to the scene is its default ladder's finest quick_rungs, so that a
// client's program is started a few times, not dozens.
inline constexpr std::size_t quick_rungs = 3;
GatePlan plan_gate(const GateFile& file, bool quick = false);

// What was decided for one case.
struct Verdict {
    GateCase of;
    bool passed = false;  // the condition itself held
    double measured = std::numeric_limits<double>::quiet_NaN();
    double lo = std::numeric_limits<double>::quiet_NaN(), hi = std::numeric_limits<double>::quiet_NaN();  // its interval
    double bound = std::numeric_limits<double>::quiet_NaN();
    std::string message;  // names the claim or check, the scene, the value with its interval, and the bound
    double seconds = 0;   // CPU time of the runs it read

    // A case expected to fail is fine when it fails; passing it is an unexpected pass.
    bool ok() const { return of.expected_to_fail ? !passed : passed; }
    // "pass", "fail", "expected failure" or "unexpected pass".
    std::string outcome() const;
};

struct GateResult {
    std::vector<Verdict> verdicts;  // in the plan's order
    std::vector<RunResult> runs;
    std::vector<std::string> warnings;
    std::string gate_file, gate_file_hash;  // the file that judged (GateFile::path, hash)
    SchemeInfos schemes;                    // what each judged scheme is: a plug-in's path, hash and build
    bool passed() const;
    std::size_t count(const std::string& outcome) const;
};

// Judges every case of the plan from the results of its runs (runs[i] made plans.runs[i]).
GateResult judge_gate(const GateFile& file, const GatePlan& plan, std::vector<RunResult> runs);

}  // namespace rotbench
