#include "harness/analysis/orders.hpp"

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

}  // namespace rotbench
