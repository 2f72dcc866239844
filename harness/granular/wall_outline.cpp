#include "harness/granular/wall_outline.hpp"

#include <algorithm>
#include <cmath>

namespace rotbench {
namespace {

// The wall's axis among x (0) and z (2) and its position on it; axis -1 for a wall that is not
// drawn: facing y or obliquely, at an infinite offset, or outside its own region.
struct Placed {
    int axis = -1;
    double position = NAN;
};
Placed place(const Wall& w) {
    const int axis = std::abs(w.normal.x()) == 1.0 ? 0 : std::abs(w.normal.z()) == 1.0 ? 2 : -1;
    if (axis < 0) return {};
    const double position = w.offset / w.normal[axis];
    if (!std::isfinite(position) || position < w.region.min()[axis] || position > w.region.max()[axis] ||
        w.region.min().y() > w.region.max().y())
        return {};
    return {axis, position};
}

}  // namespace

std::vector<std::array<double, 4>> wall_segments(const std::vector<Wall>& walls, const Eigen::AlignedBox2d& frame) {
    std::vector<std::array<double, 4>> segments;
    for (const Wall& w : walls) {
        const Placed p = place(w);
        if (p.axis < 0) continue;
        const int along = p.axis == 0 ? 2 : 0, in_frame = along == 0 ? 0 : 1;  // the segment's direction, in 3-D and in the frame
        const double lo = std::max(w.region.min()[along], frame.min()[in_frame]), hi = std::min(w.region.max()[along], frame.max()[in_frame]);
        std::vector<std::pair<double, double>> pieces = {{lo, hi}};
        if (w.hole && w.hole->min()[along] < hi && w.hole->max()[along] > lo) pieces = {{lo, w.hole->min()[along]}, {w.hole->max()[along], hi}};
        for (const auto& [a, b] : pieces) {
            if (!(a < b)) continue;
            if (p.axis == 0) segments.push_back({p.position, a, p.position, b});
            else segments.push_back({a, p.position, b, p.position});
        }
    }
    return segments;
}

Eigen::AlignedBox2d picture_frame(const std::vector<Sphere>& spheres, const std::vector<Wall>& walls) {
    Eigen::AlignedBox2d box;  // empty
    for (const Sphere& s : spheres) {
        const Eigen::Vector2d centre(s.centre.x(), s.centre.z());
        box.extend(centre - Eigen::Vector2d::Constant(s.radius)).extend(centre + Eigen::Vector2d::Constant(s.radius));
    }
    if (box.isEmpty()) return box;
    for (const Wall& w : walls) {
        const Placed p = place(w);
        if (p.axis == 0) box.extend(Eigen::Vector2d(p.position, box.min().y()));
        if (p.axis == 2) box.extend(Eigen::Vector2d(box.min().x(), p.position));
    }
    return box;
}

}  // namespace rotbench
