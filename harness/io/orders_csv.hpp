// orders.csv and local_orders.csv (docs/outputs.md).
#pragma once

#include "harness/analysis/orders.hpp"

#include <string>
#include <vector>

namespace rotbench {

// Header scene,scheme,metric,order,order_lo,order_hi,dt_min,dt_max,points; an
// insufficient fit has order "insufficient" and lo/hi "nan".
std::string orders_csv(const std::vector<OrderRow>& rows);
// Header scene,scheme,metric,dt_coarse,dt_fine,order.
std::string local_orders_csv(const std::vector<OrderRow>& rows);

}  // namespace rotbench
