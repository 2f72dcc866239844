// Baselines: what changed between two sets of runs of the same plan, and whether it is a
// regression. `rotbench compare BASE NEW` and `rotbench gate --baseline DIR` judge with it.
#pragma once

#include "harness/gate/gate.hpp"

#include <string>
#include <vector>

namespace rotbench {

struct CompareOptions {
    double error_tolerance = 0.10;  // an error up by more than 10 % is a regression
    double order_tolerance = 0.1;   // an observed order down by more than 0.1
    double cost_tolerance = 0.05;   // a cost up by more than 5 %, and significant:
    double significance = 0.05;     // Mann-Whitney U test of the timing repeats, two-sided p below this
};

struct MetricChange {
    RunSpec spec;
    std::string metric;
    double base = 0, now = 0;
    double change() const;  // (now - base) / |base|
};

struct Comparison {
    std::vector<MetricChange> changes;  // every metric of every run found in both
    std::vector<Verdict> verdicts;      // per scene and scheme: baseline_accuracy, _order, _stability, _cost
    std::vector<std::string> notes;     // runs found in one only; costs too thinly timed to test
};

// Runs are matched by scene, scheme, kind, dt, duration and parameters. `where` names the
// baseline in the verdicts (their location).
Comparison compare_runs(const std::vector<RunResult>& base, const std::vector<RunResult>& now, const CompareOptions& options,
                        const std::string& where);

// scene,scheme,kind,dt,metric,base,new,change (RFC 4180).
std::string compare_csv(const Comparison& comparison);

}  // namespace rotbench
