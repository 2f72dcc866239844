// Observed orders of every (scene, scheme, error metric) in a set of results:
// orders.csv (DESIGN.md contract) and local_orders.csv.
#pragma once

#include "harness/order_fit.hpp"
#include "harness/run.hpp"

#include <string>
#include <vector>

namespace rotbench {

// The error metrics whose convergence is fitted.
inline const std::vector<std::string> order_metrics = {"omega_err_max", "orientation_err_max", "omega_rms_x",
                                                       "energy_drift_max", "momentum_drift_max"};

struct OrderRow {
    std::string scene, scheme, metric;
    OrderFit fit;
};

std::vector<OrderRow> observed_orders(const std::vector<RunResult>& results);

// Header scene,scheme,metric,order,order_lo,order_hi,dt_min,dt_max,points; an
// insufficient fit has order "insufficient" and lo/hi "nan".
std::string orders_csv(const std::vector<OrderRow>& rows);
// Header scene,scheme,metric,dt_coarse,dt_fine,order.
std::string local_orders_csv(const std::vector<OrderRow>& rows);

}  // namespace rotbench
