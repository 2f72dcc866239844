#include "harness/granular/wall_faces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rotbench {

std::vector<WallFace> wall_faces(const std::vector<Wall>& walls, const Eigen::AlignedBox3d& domain) {
    std::vector<WallFace> faces;
    for (const Wall& w : walls) {
        int k = 0;
        if (w.normal.cwiseAbs().maxCoeff(&k) != 1.0 || w.normal.cwiseAbs().sum() != 1.0)
            throw std::invalid_argument("wall_faces: a wall's normal must be a coordinate axis");
        if (!std::isfinite(w.offset)) continue;
        const int a = (k + 1) % 3, b = (k + 2) % 3;  // (a, b, k) right-handed
        const double plane = w.offset / w.normal[k];
        const Eigen::AlignedBox3d extent = w.region.intersection(domain);
        if (extent.isEmpty()) continue;
        // The rectangle [a0, a1] x [b0, b1] in the plane, as a face.
        const auto add = [&](double a0, double a1, double b0, double b1) {
            if (!(a0 < a1 && b0 < b1)) return;
            WallFace f{{}, w.normal, w.friction};
            const std::array<std::array<double, 2>, 4> ab = {{{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}}};
            for (int c = 0; c < 4; ++c) {
                Vec3& x = f.corners[static_cast<std::size_t>(w.normal[k] > 0 ? c : 3 - c)];
                x[k] = plane, x[a] = ab[static_cast<std::size_t>(c)][0], x[b] = ab[static_cast<std::size_t>(c)][1];
            }
            faces.push_back(f);
        };
        const double a0 = extent.min()[a], a1 = extent.max()[a], b0 = extent.min()[b], b1 = extent.max()[b];
        if (!w.hole) {
            add(a0, a1, b0, b1);
            continue;
        }
        const double h0 = std::clamp(w.hole->min()[a], a0, a1), h1 = std::clamp(w.hole->max()[a], a0, a1);
        const double g0 = std::clamp(w.hole->min()[b], b0, b1), g1 = std::clamp(w.hole->max()[b], b0, b1);
        add(a0, h0, b0, b1);  // beside the hole along a, the full length along b
        add(h1, a1, b0, b1);
        add(h0, h1, b0, g0);  // before and after it along b
        add(h0, h1, g1, b1);
    }
    return faces;
}

}  // namespace rotbench
