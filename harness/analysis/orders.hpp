// Observed orders of every (scene, scheme, error metric) in a set of results:
// (the rows of orders.csv and local_orders.csv, harness/io/orders_csv.hpp).
#pragma once

#include "harness/analysis/order_fit.hpp"
#include "harness/engine/run.hpp"

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

}  // namespace rotbench
