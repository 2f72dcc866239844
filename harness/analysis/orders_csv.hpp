// orders.csv and local_orders.csv (docs/outputs.md).
#pragma once

#include "harness/analysis/orders.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Header scene,scheme,metric,status,order,order_lo,order_hi,dt_min,dt_max,points; order,
// order_lo and order_hi are numbers when status is "fit" and empty otherwise.
std::string orders_csv(const std::vector<OrderRow>& rows);
// Header scene,scheme,metric,dt_coarse,dt_fine,order.
std::string local_orders_csv(const std::vector<OrderRow>& rows);

}  // namespace rotbench
