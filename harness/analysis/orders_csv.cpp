#include "harness/analysis/orders_csv.hpp"

#include "harness/store/output_files.hpp"

#include <fmt/format.h>

namespace rotbench {

std::string orders_csv(const std::vector<OrderRow>& rows) {
    std::string csv = "scene,scheme,metric,status,order,order_lo,order_hi,dt_min,dt_max,points\n";
    for (const auto& r : rows) {
        const auto& f = r.fit;
        const bool fitted = r.status == OrderStatus::fit;
        csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", r.scene, r.scheme, r.metric, status_name(r.status),
                           fitted ? format_number(f.order) : "", fitted ? format_number(f.order_lo) : "",
                           fitted ? format_number(f.order_hi) : "", format_number(f.dt_min), format_number(f.dt_max), f.points);
    }
    return csv;
}

std::string local_orders_csv(const std::vector<OrderRow>& rows) {
    std::string csv = "scene,scheme,metric,dt_coarse,dt_fine,order\n";
    for (const auto& r : rows)
        for (const auto& l : r.fit.local_orders)
            csv += fmt::format("{},{},{},{},{},{}\n", r.scene, r.scheme, r.metric, format_number(l.dt_coarse),
                               format_number(l.dt_fine), format_number(l.order));
    return csv;
}

}  // namespace rotbench
