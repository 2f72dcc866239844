// "The answer": for each tolerance on the relative angular-velocity error, the largest dt at
// which each scheme meets it on each scene, what a run at that dt costs, and whether that dt
// lies below the measured stability limit (answer.csv; reports/answer.hpp formats it).
#pragma once

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"

#include <string>
#include <vector>

namespace rotbench {

inline const std::vector<double> default_tolerances = {1e-3, 1e-6};  // relative: omega_err_max / omega_ref_max

struct LargestDt {
    std::string scene, scheme;
    double tolerance = 0;
    // "interpolated" (log-log between the two measured steps around the tolerance),
    // "at most" (the coarsest step measured already meets it: dt is at least that),
    // "extrapolated" (no measured step does: the finest one extended with the observed order),
    // "exact" (round-off only at every step: dt is the coarsest measured, limited by stability only),
    // "never" (no measured step meets it and there is no order to extrapolate with).
    std::string how;
    double dt = 0;           // s; NaN for "never"
    double cpu_seconds = 0;  // a whole run at dt: ns_per_step x (t_end / dt), NaN for "never" and for runs not timed
    double dt_limit = 0;     // the stability limit compared with, NaN when none is known
    std::string limit_from;  // where dt_limit comes from
};

// The dt at which the relative error reaches `error`, log-log between a coarse and a fine run whose
// errors bracket it (the error taken as a power of dt between them).
double interpolated_dt(const RunResult& coarse, const RunResult& fine, double error);

// From the runs of one scheme on one scene and the fit of its omega_err_max.
LargestDt largest_dt(const std::vector<const RunResult*>& runs, const OrderRow& order, double tolerance);

// Every (tolerance, scene with a reference, scheme), with the stability limits from `stability`:
// a contact scene's own row (same zeta), else fast_spin's measured dt x w_max for the scheme
// (its limits scale as 1/w exactly) over the scene's largest |w_ref|.
std::vector<LargestDt> largest_dts(const ResultSet& set, const std::vector<OrderRow>& orders,
                                   const std::vector<double>& tolerances, const std::vector<StabilityRow>& stability);

// answer.csv: tolerance,scene,scheme,how,dt,cpu_seconds,dt_limit,limit_from.
std::string answer_csv(const std::vector<LargestDt>& answers);

}  // namespace rotbench
