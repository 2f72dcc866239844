// Ensembles: a chaotic scene (the granular ones) run K times per scheme and time step, from K
// packings that differ only in their seed (`rotbench run --ensemble K`), so that a difference
// between schemes can be set against the scatter between equally valid runs.
#pragma once

#include "harness/exec/run.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rotbench {

// The scheme the others are compared with, as the seed's Tables 4 and 5 compare theirs with its
// quaternion scheme (the seed's corrected Zhao-van Wachem step).
inline const std::string ensemble_reference_scheme = "zvw_corrected";

// The ensemble's members for K = `size`: the overrides of member k (k = 0 ... K-1) set the
// scene's `seed` to its value plus k.
ParamOverrides ensemble_member(const ParamOverrides& overrides, double base_seed, int k);

// The runs with each ensemble's members (runs of one scene, scheme, time step and kind that
// differ only in `seed`, two or more) replaced by one result, in the place of the first:
//   <metric>           the mean over the members that did not fail;
//   <metric>_ci95      half-width of its 95 % interval, t(0.975, n - 1) s / sqrt(n);
//   <metric>_diff      the mean difference from ensemble_reference_scheme's runs on the same
//                      seeds, in % of that scheme's mean (as the seed's tables give theirs);
//   <metric>_diff_ci95 half-width of the paired 95 % interval of that difference, in %;
//   ensemble_size, ensemble_failed  members, and those that failed.
// Counts and timings are averaged without intervals. A granular scene's curve becomes a band
// (each y column's member mean, then y_min and y_max: the envelope of the members) and the
// snapshots are the first member's. Other runs pass through unchanged.
std::vector<RunResult> collapse_ensembles(const std::vector<RunResult>& runs);

// The ensemble a run belongs to: its spec without the seed (the members differ in it only).
RunSpec ensemble_of(RunSpec spec);

// Whether each run is a member of an ensemble of two or more, and its seed.
std::vector<bool> ensemble_members(const std::vector<RunResult>& runs);
double member_seed(const RunSpec& spec);  // NaN without one

}  // namespace rotbench
