// How large an error round-off alone can make: the bound below which a scheme is exact
// (the gate's exactness claim, orders.csv's `exact`, the report's "exact").
#pragma once

#include "harness/exec/run.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace rotbench {

inline constexpr double unit_round_off = std::numeric_limits<double>::epsilon();

// Of `metric` in run r: ten units of round-off per step, accumulated over the N steps, times
// the size of the quantity (|w_ref| for the angular velocity, 1 rad for the orientation, 1
// for a relative drift); for the angular momentum (4 N + 16) eps, each step rounding L a few
// times and measuring it from q and w a few more. NaN for a metric without a bound.
inline double round_off_bound(const RunResult& r, std::string_view name) {
    const double n = r.value(metric::steps);
    const MetricInfo* m = find_metric(name);
    switch (m ? m->round_off : RoundOff::none) {
    case RoundOff::per_step_of_omega: return n * 10.0 * unit_round_off * r.value(metric::omega_ref_max);
    case RoundOff::per_step: return n * 10.0 * unit_round_off;
    case RoundOff::momentum: return (4.0 * n + 16.0) * unit_round_off;
    case RoundOff::none: break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rotbench
