// The Mann-Whitney U test: do two samples come from the same distribution? rotbench asks it of
// two sets of timing repeats before it calls a cost change a regression, as Google
// Benchmark's compare.py does.
#pragma once

#include <vector>

namespace rotbench {

struct UTest {
    double u = 0;        // U of the first sample
    double p = 1;        // two-sided p-value
    bool valid = false;  // both samples have at least 5 values (otherwise p is 1)
};

// Normal approximation with the correction for ties and for continuity (what SciPy's
// mannwhitneyu(method="asymptotic") computes).
UTest mann_whitney(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace rotbench
