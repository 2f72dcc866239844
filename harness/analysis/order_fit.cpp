#include "harness/analysis/order_fit.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>

namespace rotbench {

OrderFit fit_order(std::vector<OrderPoint> points, double floor) {
    std::erase_if(points, [&](const OrderPoint& p) { return !std::isfinite(p.error) || !(p.error > floor) || !(p.dt > 0); });
    std::sort(points.begin(), points.end(), [](const OrderPoint& a, const OrderPoint& b) { return a.dt > b.dt; });
    // Rule 2: coarser than the largest error, the error still grows as dt shrinks (a saturated
    // phase error); then the plateau.
    points.erase(points.begin(), std::max_element(points.begin(), points.end(),
                                                  [](const OrderPoint& a, const OrderPoint& b) { return a.error < b.error; }));
    for (std::size_t i = 1; i < points.size(); ++i)
        if (!(points[i].error < plateau_ratio * points[i - 1].error)) {
            points.resize(i);
            break;
        }

    OrderFit fit;
    auto local = [&](std::size_t i) {  // order between points i-1 and i
        return std::log(points[i - 1].error / points[i].error) / std::log(points[i - 1].dt / points[i].dt);
    };
    for (std::size_t i = 1; i < points.size(); ++i) fit.local_orders.push_back({points[i - 1].dt, points[i].dt, local(i)});
    if (points.size() < static_cast<std::size_t>(min_fit_points)) {
        fit.points = static_cast<int>(points.size());
        return fit;
    }
    std::size_t first = points.size() - 2;  // rule 3: the longest consistent run at the fine end
    for (std::size_t s = 0; s + 2 < points.size(); ++s) {
        std::vector<double> orders;
        for (std::size_t i = s + 1; i < points.size(); ++i) orders.push_back(local(i));
        std::vector<double> sorted = orders;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double median = sorted[sorted.size() / 2];
        if (std::all_of(orders.begin(), orders.end(), [&](double p) { return std::abs(p - median) <= asymptotic_spread; })) {
            first = s;
            break;
        }
    }
    const std::size_t n = points.size() - first;
    fit.points = static_cast<int>(n);
    fit.dt_max = points[first].dt;
    fit.dt_min = points.back().dt;
    if (n < static_cast<std::size_t>(min_fit_points)) return fit;

    double sx = 0, sy = 0;
    for (std::size_t i = first; i < points.size(); ++i) {
        sx += std::log(points[i].dt);
        sy += std::log(points[i].error);
    }
    const double mx = sx / n, my = sy / n;
    double sxx = 0, sxy = 0;
    for (std::size_t i = first; i < points.size(); ++i) {
        const double x = std::log(points[i].dt) - mx, y = std::log(points[i].error) - my;
        sxx += x * x;
        sxy += x * y;
    }
    const double slope = sxy / sxx, intercept = my - slope * mx;
    double ssr = 0;
    for (std::size_t i = first; i < points.size(); ++i) {
        const double r = std::log(points[i].error) - (intercept + slope * std::log(points[i].dt));
        ssr += r * r;
    }
    const double se = n > 2 ? std::sqrt(ssr / static_cast<double>(n - 2) / sxx) : 0.0;
    const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(n - 2));
    fit.sufficient = true;
    fit.order = slope;
    fit.order_lo = slope - t * se;
    fit.order_hi = slope + t * se;
    return fit;
}

}  // namespace rotbench
