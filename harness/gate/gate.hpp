// `rotbench gate FILE.toml`: checks per (scene, scheme) that a CI job can fail on.
//
//   [[check]]
//   name      = "free top: at least first order"     # optional; shown in the summary and JUnit
//   scene     = "asymmetric_free"
//   schemes   = ["*"]             # ids, or "*": every registered scheme (plug-ins included)
//   min_order = 0.8               # exactly one criterion, see below
//   metric    = "omega_err_max"   # min_order and max_error only; default omega_err_max
//   dt        = [0.1, 0.05, ...]  # min_order: the ladder (default: the scene's); others: one dt
//   t_end     = 5.0               # optional
//   params    = { zeta = 0.3 }    # optional scene parameters
//   why       = "..."             # printed with a failure: what a failure means
//
// Criteria: min_order (least-squares order on the detected asymptotic range; a ladder whose
// errors all lie below `round_off`, default 1e-10, counts as exact and passes),
// max_error (metric at dt), max_energy_drift, max_momentum_drift (energy_drift_max and
// momentum_drift_max at dt), min_stability (measured stability limit divided by Peng et
// al.'s prediction for the scene, same criterion as `rotbench stability`), max_cost_ratio
// (CPU time per step against `direct` on the same scene and dt, medians, measured here).
#pragma once

#include "harness/scenes/params.hpp"
#include "harness/engine/run.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rotbench {

struct GateCheck {
    std::string name;
    std::string scene;
    std::vector<std::string> schemes;
    std::string criterion;  // min_order, max_error, max_energy_drift, max_momentum_drift, min_stability, max_cost_ratio
    double bound = 0;
    std::string metric;       // the metric the criterion reads
    std::vector<double> dts;  // empty: the scene's ladder (min_order)
    double t_end = 0;
    double round_off = 1e-10;
    ParamOverrides params;
    std::string why;
    std::string location;  // file:line of the [[check]]
};

// Reads and checks a gate file; every error names file, line and column (InputError).
std::vector<GateCheck> load_gate(const std::string& path);
// The same for text already read; `name` stands for the file in messages.
std::vector<GateCheck> parse_gate(std::string_view text, const std::string& name);

struct GateOutcome {
    std::size_t check = 0;  // index into the checks
    std::string scheme;
    bool passed = false;
    double measured = 0;  // NaN when nothing could be measured
    std::string detail;   // what was measured, and why it passed or failed
};

struct GateResult {
    std::vector<GateOutcome> outcomes;  // in check order, then scheme order
    std::vector<RunResult> runs;        // every run made, for results.csv
};

// Runs what the checks need (each distinct run once, `jobs` in parallel; timing runs one at
// a time) and judges them. A failing or throwing scheme is a failed check, never a crash.
GateResult run_gate(const std::vector<GateCheck>& checks, int jobs);

}  // namespace rotbench
