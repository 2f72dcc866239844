#include "reports/orders.hpp"

#include "reports/output_files.hpp"

#include <fmt/format.h>
#include <map>

namespace rotbench {

std::vector<OrderRow> observed_orders(const std::vector<RunResult>& results) {
    // Keyed in order of first appearance, so the files follow the sweep's order.
    std::vector<std::pair<std::string, std::string>> pairs;
    std::map<std::pair<std::string, std::string>, std::vector<const RunResult*>> runs;
    for (const auto& r : results) {
        const auto key = std::make_pair(r.spec.scene, r.spec.scheme);
        if (!runs.count(key)) pairs.push_back(key);
        runs[key].push_back(&r);
    }
    std::vector<OrderRow> rows;
    for (const auto& key : pairs)
        for (const auto& metric : order_metrics) {
            std::vector<OrderPoint> points;
            for (const RunResult* r : runs[key])
                if (r->has(metric)) points.push_back({r->spec.dt, r->value(metric)});
            if (points.empty()) continue;
            rows.push_back({key.first, key.second, metric, fit_order(points)});
        }
    return rows;
}

std::string orders_csv(const std::vector<OrderRow>& rows) {
    std::string csv = "scene,scheme,metric,order,order_lo,order_hi,dt_min,dt_max,points\n";
    for (const auto& r : rows) {
        const auto& f = r.fit;
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", r.scene, r.scheme, r.metric,
                           f.sufficient ? format_number(f.order) : "insufficient",
                           f.sufficient ? format_number(f.order_lo) : "nan", f.sufficient ? format_number(f.order_hi) : "nan",
                           format_number(f.dt_min), format_number(f.dt_max), f.points);
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
