// Baselines: what changed between two sets of runs of the same plan, and whether it is a
// regression. `rotbench compare BASE NEW` and `rotbench gate --baseline DIR` judge with it.
#pragma once

#include "harness/analysis/claims.hpp"
#include "harness/gate/gate.hpp"

#include <string>
#include <vector>

namespace rotbench {

struct MetricChange {
    RunSpec spec;
    std::string metric;
    double base = 0, now = 0;
    double change() const;  // (now - base) / |base|
};

struct Comparison {
    std::vector<MetricChange> changes;  // every metric of every run found in both
    // Per scene and scheme: baseline_accuracy, _order, _stability, _cost (claims.hpp's judges), and
    // baseline_matched where runs of the baseline are missing (or none matched at all).
    std::vector<Verdict> verdicts;
    std::vector<std::string> notes;     // runs found in one only; costs too thinly timed to test
};

// Runs are matched by scene, scheme, kind, dt, duration and parameters. `where` names the
// baseline in the verdicts (their location).
Comparison compare_runs(const std::vector<RunResult>& base, const std::vector<RunResult>& now, const BaselineTolerances& tolerances,
                        const std::string& where);

// scene,scheme,kind,dt,metric,base,new,change (RFC 4180).
std::string compare_csv(const Comparison& comparison);

}  // namespace rotbench
