#include "harness/granular/linked_cells.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rotbench {

void LinkedCells::build(const std::vector<Vec3>& points, double reach) {
    if (!(reach > 0.0) || !std::isfinite(reach)) throw std::invalid_argument("LinkedCells: reach must be positive and finite");
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (const Vec3& p : points) {
        if (!p.allFinite()) throw std::invalid_argument("LinkedCells: a point is not finite");
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    if (points.empty()) lo = hi = Vec3::Zero();
    double edge = reach;
    const double limit = 8.0 * static_cast<double>(std::max<std::size_t>(points.size(), 1));
    auto cells_along = [&](int k) { return std::floor((hi[k] - lo[k]) / edge) + 1.0; };
    while (cells_along(0) * cells_along(1) * cells_along(2) > limit) edge *= 2.0;
    for (int k = 0; k < 3; ++k) dims_[k] = static_cast<long>(cells_along(k));
    const std::size_t cells = static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]);
    std::vector<std::size_t> cell_of(points.size());
    start_.assign(cells + 1, 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        long c[3];
        for (int k = 0; k < 3; ++k) c[k] = std::min(dims_[k] - 1, static_cast<long>((points[i][k] - lo[k]) / edge));
        cell_of[i] = index(c[0], c[1], c[2]);
        ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    order_.resize(points.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) order_[fill[cell_of[i]]++] = i;
}

}  // namespace rotbench
