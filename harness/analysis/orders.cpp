#include "harness/analysis/orders.hpp"

#include "harness/analysis/round_off.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

const char* status_name(OrderStatus status) {
    switch (status) {
        case OrderStatus::fit: return "fit";
        case OrderStatus::insufficient: return "insufficient";
        case OrderStatus::exact: return "exact";
        case OrderStatus::no_convergence: return "no_convergence";
    }
    return "insufficient";
}

OrderStatus order_status(const std::vector<const RunResult*>& runs, const std::string& metric, const OrderFit& fit) {
    std::vector<const RunResult*> usable;
    for (const RunResult* r : runs)
        if (r->has(metric) && std::isfinite(r->value(metric))) usable.push_back(r);
    if (usable.empty()) return OrderStatus::insufficient;
    if (std::all_of(usable.begin(), usable.end(), [&](const RunResult* r) { return r->value(metric) <= round_off_bound(*r, metric); }))
        return OrderStatus::exact;
    if (fit.sufficient) return OrderStatus::fit;
    const auto [fine, coarse] = std::minmax_element(usable.begin(), usable.end(),
                                                    [](const RunResult* a, const RunResult* b) { return a->spec.dt < b->spec.dt; });
    const double e_fine = (*fine)->value(metric), e_coarse = (*coarse)->value(metric);
    if ((*coarse)->spec.dt >= 4.0 * (*fine)->spec.dt && e_fine > round_off_bound(**fine, metric) && !(e_fine < 0.5 * e_coarse))
        return OrderStatus::no_convergence;
    return OrderStatus::insufficient;
}

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
        for (const auto& metric : fitted_metrics()) {
            std::vector<OrderPoint> points;
            for (const RunResult* r : runs[key])
                if (r->has(metric)) points.push_back({r->spec.dt, r->value(metric)});
            if (points.empty()) continue;
            OrderFit fit = fit_order(points);
            const OrderStatus status = order_status(runs[key], metric, fit);
            rows.push_back({key.first, key.second, metric, std::move(fit), status});
        }
    return rows;
}

}  // namespace rotbench
