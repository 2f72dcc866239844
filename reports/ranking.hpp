// The ranking of every scheme in a set of results: the CPU time each needs to reach one
// accuracy, on a free top and under an orientation-dependent torque (work-precision read
// at a fixed error, the quantity a user choosing an integrator trades).
#pragma once

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"

#include <string>
#include <vector>

namespace rotbench {

struct CostToTolerance {
    double seconds = 0;          // CPU time for the whole run at the step that just reaches the tolerance
    std::string how;             // "interpolated", "at most" (the coarsest step already did), "extrapolated", "never"
};

// From the runs of one scheme on one scene: interpolated in log dt - log error between the
// two steps that bracket `tolerance`; the coarsest step's time when even it is below;
// extrapolated from the finest step with the observed order when no step reaches it;
// infinite ("never") when none does and there is no order to extrapolate with.
CostToTolerance cost_to_tolerance(const std::vector<const RunResult*>& runs, const OrderFit& fit, double tolerance);

// Markdown: the ranking table and the rule it follows.
std::string ranking_section(const ResultSet& set, const std::vector<OrderRow>& orders);

inline constexpr double ranking_tolerance = 1e-6;  // rad/s, omega_err_max: inside both ladders for second-order schemes

}  // namespace rotbench
