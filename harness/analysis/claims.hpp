// Whether a scheme holds what it claims (SchemeClaims, schemes/scheme.hpp): one judge per
// claim, with its bound and where the bound comes from. The gate, the report's verdict table
// and the tests all judge through these functions, so they cannot disagree on a threshold.
#pragma once

#include "harness/analysis/result_set.hpp"
#include "harness/exec/run.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rotbench {

using RunRefs = std::vector<const RunResult*>;

// A figure in a judgement's message: three significant digits.
std::string figure(double v);

// What a judge found. `message` states the value (with its interval), the bound, and the
// bound's origin; a caller prefixes it with the claim and the scene.
struct Judgement {
    bool passed = false;
    double measured = std::numeric_limits<double>::quiet_NaN();
    double lo = std::numeric_limits<double>::quiet_NaN(), hi = std::numeric_limits<double>::quiet_NaN();  // its interval
    double bound = std::numeric_limits<double>::quiet_NaN();
    std::string message;
};

// The one rule for the scenes that can judge a scheme's claims of one kind (the gate's
// [claims] lists, the report's verdicts and its expected orders all ask it): a reference, and
// either no torque (the angular momentum conserved) or an orientation-dependent torque whose
// true motion conserves energy (bounded energy is judged there too).
bool judges_claims(const SceneInfo& scene, bool with_torque);
// Of every scene, those whose true motion conserves energy, for bounded energy.
bool judges_energy(const SceneInfo& scene);
// Of those, the ones the report judges a scheme's claims on, as the default gate does (its
// [claims] lists the same scenes; tests/test_claims.cpp keeps the two equal): the free top and
// the tumbling brick without torque, the dipole top with one. The other scenes' ladders are not
// all asymptotic (dzhanibekov's flip, fast_spin), so an order there is shown, not judged.
const std::vector<std::string>& default_claim_scenes(bool with_torque);

// The horizon run that judges bounded energy on a scene of a sweep: at the coarsest of its
// steps, `dts`, over the scene's duration t_end and energy_horizon times it.
RunSpec horizon_run(const RunSpec& coarsest);

// A claimed order p holds when the observed order lies within this of p (and its interval reaches p).
inline constexpr double order_tolerance = 0.2;
// What any consistent scheme must show when it claims nothing.
inline constexpr double sanity_min_order = 0.8;
inline constexpr double sanity_max_momentum_drift = 0.05;
// Bounded energy: a drift growing as t^a multiplies the largest energy error energy_horizon^a
// times over a run energy_horizon times as long (run.hpp), a bounded error about once; the
// bound splits the two at a = 1/2.
inline const double energy_growth_bound = std::sqrt(energy_horizon);

// The order of omega_err_max over a ladder of steps against the claimed order p.
Judgement judge_order(const RunRefs& ladder, int claimed);
// At least sanity_min_order over a ladder.
Judgement judge_sanity_order(const RunRefs& ladder);
// A gate's min_order check: the order of `metric` over a ladder at least `min_order`, or
// every error at most `round_off` (exact).
Judgement judge_min_order(const RunRefs& ladder, const std::string& metric, double min_order, double round_off);
// Every error of every run within its round-off bound (round_off.hpp).
Judgement judge_exact(const RunRefs& runs);
// The angular momentum kept to round-off in every run.
Judgement judge_momentum(const RunRefs& runs);
// A client's runs differ from its counterpart's (`counterpart`) by round-off only at every step
// and every dt: the same map (counterpart_omega_diff_max and counterpart_angle_diff_max within
// their round-off bounds, round_off.hpp).
Judgement judge_same_map(const RunRefs& runs, const std::string& counterpart);
// The angular momentum within sanity_max_momentum_drift.
Judgement judge_sanity_momentum(const RunResult& run);
// From a horizon run (RunKind::horizon): the largest energy error over energy_horizon x T
// against that over T.
Judgement judge_bounded_energy(const RunResult& horizon_run);
// Back to the start to round-off, after N steps forward and N back.
Judgement judge_reversal(const RunResult& run);
// A stability margin: the limit a stability search measured, at least `min_ratio` times Peng
// et al.'s prediction (the bound is the gate file's).
Judgement judge_stability_margin(const RunResult& search, double min_ratio);
// A cost (RunKind::cost): the scheme's CPU time per step at most `max_ratio` times direct's on the
// same scene and step (the bound is the gate file's), unless significantly above it: the median
// ratio's 95 % interval wholly above the bound fails.
Judgement judge_cost_ratio(const RunResult& cost, double max_ratio);

// Against a baseline (`rotbench compare`, `gate --baseline`; harness/analysis/baseline_claims.cpp):
// the new runs of one scene and scheme claim to be no worse than the same runs of BASE.
struct BaselineTolerances {
    double error = 0.10;         // an error up by more than 10 % is a regression
    double order = 0.1;          // an observed order down by more than 0.1
    double cost = 0.05;          // a cost up by more than 5 %, and significant:
    double significance = 0.05;  // Mann-Whitney U test of the timing repeats, two-sided p below this
};
using RunPairs = std::vector<std::pair<const RunResult*, const RunResult*>>;  // (base, new), matched runs
// The worst relative increase of an error metric above round-off; the claims' metric takes the
// headline when it regressed.
Judgement judge_baseline_accuracy(const RunPairs& runs, const BaselineTolerances& t);
// No run became unstable or failed (nor an ensemble member more), no stability limit fell.
Judgement judge_baseline_stability(const RunPairs& runs, const BaselineTolerances& t);
// Each observed order of the base ladder (every trajectory run BASE has) against the new one's:
// down beyond both intervals, or no longer measurable, is a regression.
Judgement judge_baseline_order(const RunRefs& base_ladder, const RunRefs& new_ladder, const BaselineTolerances& t);
// The timing repeats per step, pooled over the runs: up by more than t.cost and significant.
// Not tested (passed, `tested` false) with fewer than 5 repeats on a side.
struct CostJudgement : Judgement {
    bool tested = true;
};
CostJudgement judge_baseline_cost(const RunPairs& runs, const BaselineTolerances& t);

}  // namespace rotbench
