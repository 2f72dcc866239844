// How large an error round-off alone can make: the bound below which a scheme is exact
// (the gate's exactness claim, orders.csv's `exact`, the report's "exact").
#pragma once

#include "harness/engine/run.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace rotbench {

inline constexpr double unit_round_off = std::numeric_limits<double>::epsilon();

// Of `metric` in run r: ten units of round-off per step, accumulated over the N steps, times
// the size of the quantity (|w_ref| for the angular velocity, 1 rad for the orientation, 1
// for a relative drift); for the angular momentum (4 N + 16) eps, each step rounding L a few
// times and measuring it from q and w a few more. NaN for a metric without a bound.
inline double round_off_bound(const RunResult& r, const std::string& metric) {
    const double n = r.value("steps");
    if (metric == "omega_err_max" || metric == "omega_rms_x" || metric == "omega_rms_y" || metric == "omega_rms_z")
        return n * 10.0 * unit_round_off * r.value("omega_ref_max");
    if (metric == "orientation_err_max" || metric == "energy_drift_max") return n * 10.0 * unit_round_off;
    if (metric == "momentum_drift_max") return (4.0 * n + 16.0) * unit_round_off;
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rotbench
