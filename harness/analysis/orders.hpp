// Observed orders of every (scene, scheme, error metric) in a set of results:
// (the rows of orders.csv and local_orders.csv, harness/analysis/orders_csv.hpp).
#pragma once

#include "harness/analysis/order_fit.hpp"
#include "harness/exec/run.hpp"

#include <string>
#include <vector>

namespace rotbench {

// What the runs of one (scene, scheme, metric) show:
//   exact           every finite error is within its round-off bound (round_off.hpp);
//   fit             an order was fitted (order_fit.hpp);
//   no_convergence  the error at the finest usable step is not below half the error at the
//                   coarsest, over a ladder at least 4x wide: it does not fall with dt;
//   insufficient    none of these: too few points in the asymptotic range to fit.
enum class OrderStatus { fit, insufficient, exact, no_convergence };
const char* status_name(OrderStatus status);

struct OrderRow {
    std::string scene, scheme, metric;
    OrderFit fit;
    OrderStatus status = OrderStatus::insufficient;
};

// From the runs of one scene and scheme (any order of dt) and their fit.
OrderStatus order_status(const std::vector<const RunResult*>& runs, const std::string& metric, const OrderFit& fit);

std::vector<OrderRow> observed_orders(const std::vector<RunResult>& results);

}  // namespace rotbench
